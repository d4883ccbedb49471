// libFuzzer entry point for the CSV, AprilTag (YAML), Atracsys geometry (.ini) and NDI tool
// definition (.rom) layout readers: any input must either parse into a valid layout or raise
// vantage::InvalidArgument with a one-line message, never crash, leak or hit undefined
// behaviour. Every input goes to every reader (the seed corpus, examples/layouts and
// examples/tools, holds files of the text formats). An accepted layout is finite, a CSV data row
// is never dropped as a header, and an accepted geometry file written back reads back to the
// same positions bit for bit.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/io/apriltag_bundle.h"
#include "vantage/io/atracsys_geometry.h"
#include "vantage/io/csv_layout.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/ndi_rom.h"

namespace {

void check_message(const vantage::InvalidArgument& e) {
  for (const char* c = e.what(); *c; ++c)
    if (*c == '\n') __builtin_trap();
}

void check_layout(const vantage::Layout& layout) {
  if (!layout.entries.allFinite() || !layout.weights.allFinite()) __builtin_trap();
  const vantage::DataVectors vectors = vantage::data_vectors(layout);
  if (vectors.vectors.cols() < 1 || !vectors.weights.allFinite()) __builtin_trap();
  vantage::io::parse_layout(vantage::io::layout_to_json(layout), "round-trip");
}

// The rows the CSV reader reads: non-blank lines not starting with '#' (after blanks).
std::vector<std::string> csv_rows(std::string_view text) {
  std::vector<std::string> rows;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line(text.substr(start, end - start));
    const auto first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos && line[first] != '#') rows.push_back(line);
    start = end + 1;
  }
  return rows;
}

// Issue 22: a data row must never be dropped as a header. An accepted CSV holds one marker per
// row, or one fewer when the first row is a header, and then its second field (x) is no number
// at all (strtod reads nothing of it: not "nan", "inf" or "1e999" either).
void check_csv_rows(std::string_view text, const vantage::Layout& layout) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  const std::vector<std::string> rows = csv_rows(text);
  const auto markers = static_cast<std::size_t>(layout.entries.cols());
  if (markers == rows.size()) return;
  if (markers + 1 != rows.size()) __builtin_trap();
  const std::string& header = rows.front();
  const auto comma = header.find(',');
  if (comma == std::string::npos) __builtin_trap();
  std::string x = header.substr(comma + 1, header.find(',', comma + 1) - comma - 1);
  // As the reader trims a field: blanks, then one pair of surrounding double quotes.
  const auto first = x.find_first_not_of(" \t\r");
  x = first == std::string::npos ? "" : x.substr(first, x.find_last_not_of(" \t\r") - first + 1);
  if (x.size() >= 2 && x.front() == '"' && x.back() == '"') x = x.substr(1, x.size() - 2);
  char* end = nullptr;
  std::strtod(x.c_str(), &end);
  if (end != x.c_str()) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const vantage::Layout layout = vantage::io::parse_csv_layout(text, "fuzz.csv");
    check_layout(layout);
    check_csv_rows(text, layout);
  } catch (const vantage::InvalidArgument& e) {
    check_message(e);
  }
  try {
    const vantage::io::AtracsysGeometry geometry =
        vantage::io::parse_atracsys_geometry(text, "fuzz.ini");
    check_layout(geometry.layout);
    const vantage::io::AtracsysGeometry back = vantage::io::parse_atracsys_geometry(
        vantage::io::layout_to_atracsys_geometry(geometry.layout, geometry.id, geometry.pivot),
        "round-trip.ini");
    if (!back.layout.entries.cwiseEqual(geometry.layout.entries).all() || back.id != geometry.id ||
        back.pivot.has_value() != geometry.pivot.has_value()) {
      __builtin_trap();
    }
  } catch (const vantage::InvalidArgument& e) {
    check_message(e);
  }
  try {
    check_layout(vantage::io::parse_ndi_rom_layout(text, "fuzz.rom"));
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
