// layout_to_csv(): the CSV marker format of csv_layout.h, written so that it reads back exactly.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "number_text.h"
#include "vantage/analysis/common.h"
#include "vantage/io/csv_layout.h"
#include "vantage/io/printable.h"

namespace vantage::io {

namespace {

// Why the reader would not give `name` back, or nullptr: it splits on commas, strips blanks and
// double quotes around a field, reads line by line and skips lines starting with '#'.
const char* unwritable_reason(const std::string& name) {
  if (name.find(',') != std::string::npos) return "contains a comma";
  if (name.find('"') != std::string::npos) return "contains a double quote";
  if (name.find_first_of("\r\n") != std::string::npos) return "contains a line break";
  if (name.front() == ' ' || name.front() == '\t' || name.back() == ' ' || name.back() == '\t') {
    return "starts or ends with a blank";
  }
  if (name.front() == '#') return "starts with '#' (a comment line in CSV)";
  return nullptr;
}

// One comment line: line breaks inside the text become blanks.
std::string comment(const std::string& label, std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return "# " + label + ": " + text + "\n";
}

}  // namespace

std::string layout_to_csv(const Layout& layout) {
  layout.validate();
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument(
        "vectors: a CSV layout holds marker positions (name,x,y,z,weight), not direction "
        "vectors; write .json");
  }
  if (layout.candidates.cols() > 0) {
    throw InvalidArgument("candidates: a CSV layout cannot hold the " +
                          std::to_string(layout.candidates.cols()) +
                          " candidates; write .json to keep them");
  }
  const Eigen::Index n = layout.entries.cols();
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::string name = layout.entry_name(i);
    if (const char* reason = unwritable_reason(name)) {
      throw InvalidArgument("names[" + std::to_string(i) + "]: \"" + excerpt(name) + "\" " +
                            reason + ", which CSV cannot hold; write .json");
    }
  }
  const MarkerVisibility* visibility = layout.visibility ? &*layout.visibility : nullptr;
  if (visibility != nullptr) {
    const bool default_cones =
        (visibility->cone_half_angle_deg.array() == MarkerVisibility::kDefaultConeDeg).all();
    if (!default_cones || visibility->min_visible != 3 || !visibility->body_path.empty() ||
        layout.workspace) {
      throw InvalidArgument(
          "visibility: a CSV layout holds normals only (90-degree cones, 3 markers seen, no body "
          "or workspace); write .json to keep the rest");
    }
  }
  std::string out;
  if (!layout.name.empty()) out += comment("name", layout.name);
  if (!layout.description.empty()) out += comment("description", layout.description);
  out += visibility != nullptr ? "name,x,y,z,weight,nx,ny,nz\n" : "name,x,y,z,weight\n";
  for (Eigen::Index i = 0; i < n; ++i) {
    out += layout.entry_name(i);
    for (int r = 0; r < 3; ++r) out += "," + internal::round_trip_number(layout.entries(r, i));
    out += "," + internal::round_trip_number(layout.weights(i));
    for (int r = 0; visibility != nullptr && r < 3; ++r) {
      out += "," + internal::round_trip_number(visibility->normals(r, i));
    }
    out += "\n";
  }
  return out;
}

}  // namespace vantage::io
