// libFuzzer entry point for the layout and correspondence parsers: any input must either parse
// into a valid layout or raise vantage::InvalidArgument with a one-line message, never crash,
// leak or hit undefined behaviour.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "vantage/analysis/common.h"
#include "vantage/io/correspondence_file.h"
#include "vantage/io/layout_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const vantage::Layout layout = vantage::io::parse_layout(text, "fuzz");
    const vantage::DataVectors vectors = vantage::data_vectors(layout);
    if (vectors.vectors.cols() < 1 || !vectors.weights.allFinite()) __builtin_trap();
    vantage::io::parse_layout(vantage::io::layout_to_json(layout), "round-trip");
  } catch (const vantage::InvalidArgument& e) {
    for (const char* c = e.what(); *c; ++c)
      if (*c == '\n') __builtin_trap();
  }
  try {
    vantage::io::parse_correspondences(text, "fuzz");
  } catch (const vantage::InvalidArgument&) {
  }
  return 0;
}
