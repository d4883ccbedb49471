// libFuzzer entry point for the CSV and AprilTag (YAML) layout readers: any input must either
// parse into a valid layout or raise vantage::InvalidArgument with a one-line message, never
// crash, leak or hit undefined behaviour. Every input goes to both readers (the seed corpus,
// examples/layouts, holds files of each format).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "vantage/analysis/common.h"
#include "vantage/io/apriltag_bundle.h"
#include "vantage/io/csv_layout.h"
#include "vantage/io/layout_file.h"

namespace {

void check_message(const vantage::InvalidArgument& e) {
  for (const char* c = e.what(); *c; ++c)
    if (*c == '\n') __builtin_trap();
}

void check_layout(const vantage::Layout& layout) {
  const vantage::DataVectors vectors = vantage::data_vectors(layout);
  if (vectors.vectors.cols() < 1 || !vectors.weights.allFinite()) __builtin_trap();
  vantage::io::parse_layout(vantage::io::layout_to_json(layout), "round-trip");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    check_layout(vantage::io::parse_csv_layout(text, "fuzz.csv"));
  } catch (const vantage::InvalidArgument& e) {
    check_message(e);
  }
  for (const auto points : {vantage::io::TagPoints::kCorners, vantage::io::TagPoints::kCentres}) {
    try {
      vantage::io::AprilTagOptions options;
      options.tag_points = points;
      check_layout(vantage::io::parse_apriltag_layout(text, "fuzz.yaml", options));
    } catch (const vantage::InvalidArgument& e) {
      check_message(e);
    }
  }
  return 0;
}
