// layout_to_atracsys_geometry() and the geometry id of a file name (atracsys_geometry.h).

#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "json_fields.h"
#include "number_text.h"
#include "vantage/analysis/common.h"
#include "vantage/io/atracsys_geometry.h"

namespace vantage::io {

namespace {

std::string point_keys(const Eigen::Vector3d& p) {
  return "x=" + internal::round_trip_number(p.x()) + "\ny=" + internal::round_trip_number(p.y()) +
         "\nz=" + internal::round_trip_number(p.z()) + "\n";
}

}  // namespace

std::vector<std::string> atracsys_dropped_fields(const Layout& layout) {
  std::vector<std::string> dropped;
  for (std::size_t k = 0; k < layout.names.size(); ++k) {
    if (layout.names[k] != "fiducial" + std::to_string(k)) {
      dropped.push_back("names");
      break;
    }
  }
  if ((layout.weights.array() != 1.0).any()) dropped.push_back("weights");
  if (layout.visibility) {
    dropped.push_back("normals");
    dropped.push_back("visibility");
  }
  if (layout.workspace) dropped.push_back("workspace");
  if (layout.sensor) dropped.push_back("sensor");
  if (!layout.description.empty()) dropped.push_back("description");
  return dropped;
}

std::string layout_to_atracsys_geometry(const Layout& layout, std::uint32_t id,
                                        const std::optional<Eigen::Vector3d>& pivot) {
  layout.validate();
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument(
        "vectors: an Atracsys geometry file holds fiducial positions, not direction vectors; "
        "write .json");
  }
  if (layout.candidates.cols() > 0) {
    throw InvalidArgument("candidates: an Atracsys geometry file cannot hold the " +
                          std::to_string(layout.candidates.cols()) +
                          " candidates; write .json to keep them");
  }
  const Eigen::Index n = layout.entries.cols();
  if (n < kAtracsysMinFiducials || n > kAtracsysMaxFiducials) {
    throw InvalidArgument(
        "points: an Atracsys geometry file holds 3 to 6 fiducials, the layout "
        "has " +
        std::to_string(n));
  }
  if (pivot && !pivot->allFinite()) throw InvalidArgument("pivot: not finite");
  std::string out;
  if (!layout.name.empty()) {
    std::string name = layout.name;
    for (char& c : name) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    out += "; " + name + "\n";
  }
  out += "[geometry]\ncount=" + std::to_string(n) + "\nid=" + std::to_string(id) + "\n";
  for (Eigen::Index k = 0; k < n; ++k) {
    out += "[fiducial" + std::to_string(k) + "]\n" + point_keys(layout.entries.col(k));
  }
  if (pivot) out += "[pivot]\n" + point_keys(*pivot);
  return out;
}

std::uint32_t atracsys_geometry_id_of(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  std::size_t first = stem.size();
  while (first > 0 && std::isdigit(static_cast<unsigned char>(stem[first - 1]))) --first;
  const std::string digits = stem.substr(first);
  const bool fits = !digits.empty() && digits.size() <= 10 &&
                    std::strtoull(digits.c_str(), nullptr, 10) <= 0xFFFFFFFFull;
  if (!fits) {
    internal::fail(path,
                   "cannot tell the geometry id from the file name: end its stem with the id, "
                   "as in geometry150.ini (the fusionTrack manual's geometry<id>.ini; ids up to "
                   "100 are the built-in markers')");
  }
  return static_cast<std::uint32_t>(std::strtoull(digits.c_str(), nullptr, 10));
}

}  // namespace vantage::io
