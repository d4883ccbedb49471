#include "vantage/io/layout_file.h"

#include <string>
#include <vector>

#include "json_fields.h"
#include "placement_fields.h"
#include "sensor_fields.h"
#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"
#include "visibility_fields.h"

namespace vantage::io {

using internal::fail;

namespace {

std::vector<std::string> read_names(const nlohmann::json& value, const std::string& source) {
  if (!value.is_array()) fail(source, "names: expected a list of strings");
  std::vector<std::string> names;
  names.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    names.push_back(internal::read_string(value[i], source, "names[" + std::to_string(i) + "]"));
  }
  return names;
}

}  // namespace

Layout parse_layout(std::string_view text, const std::string& source) {
  const nlohmann::json root = internal::parse_object(text, source);
  internal::reject_unknown_fields(
      root, source,
      {"name", "description", "vectors", "points", "names", "weights", "candidates", "normals",
       "visibility", "workspace", "placement", "sensor"});
  const bool has_vectors = root.contains("vectors");
  const bool has_points = root.contains("points");
  if (has_vectors == has_points) {
    fail(source, has_vectors ? "vectors/points: give exactly one of \"vectors\" or \"points\", "
                               "not both"
                             : "vectors/points: missing; give \"vectors\" (directions) or "
                               "\"points\" (marker positions)");
  }
  Layout layout;
  layout.mode = has_points ? LayoutMode::kPoints : LayoutMode::kVectors;
  const char* field = layout.entries_field();
  layout.name = root.contains("name") ? internal::read_string(root["name"], source, "name") : "";
  layout.description = root.contains("description")
                           ? internal::read_string(root["description"], source, "description")
                           : "";
  layout.entries = internal::read_vectors<3>(root[field], source, field);
  if (root.contains("names")) layout.names = read_names(root["names"], source);
  layout.weights = root.contains("weights")
                       ? internal::read_numbers(root["weights"], source, "weights")
                       : Eigen::VectorXd::Ones(layout.entries.cols());
  layout.candidates = root.contains("candidates")
                          ? internal::read_vectors<3>(root["candidates"], source, "candidates")
                          : Eigen::Matrix3Xd(3, 0);
  layout.visibility = internal::read_visibility(root, source, layout.entries.cols());
  layout.workspace = internal::read_workspace(root, source);
  layout.placement = internal::read_placement(root, source, layout.entries.cols());
  layout.sensor = internal::read_sensor(root, source);
  if (layout.sensor && layout.mode != LayoutMode::kPoints) {
    fail(source, "sensor: a camera or tracker tracks marker points; this layout has \"vectors\"");
  }
  try {
    layout.validate();
  } catch (const InvalidArgument& e) {
    throw e.against(printable(source));
  }
  return layout;
}

Layout read_layout(const std::string& path, std::size_t max_bytes) {
  return parse_layout(read_text_file(path, max_bytes), path);
}

std::string layout_to_json(const Layout& layout) {
  nlohmann::ordered_json out;
  out["name"] = layout.name;
  if (!layout.description.empty()) out["description"] = layout.description;
  out[layout.entries_field()] = internal::vector_rows(layout.entries);
  if (!layout.names.empty()) out["names"] = layout.names;
  out["weights"] =
      std::vector<double>(layout.weights.data(), layout.weights.data() + layout.weights.size());
  if (layout.candidates.cols() > 0) out["candidates"] = internal::vector_rows(layout.candidates);
  internal::write_visibility(layout, &out);
  internal::write_placement(layout, &out);
  internal::write_sensor(layout, &out);
  // Names read from CSV or YAML files may not be UTF-8 (JSON requires it): such bytes are
  // written as U+FFFD instead of throwing.
  return out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void write_layout(const std::string& path, const Layout& layout, bool overwrite) {
  layout.validate();
  write_text_file(path, layout_to_json(layout), overwrite);
}

}  // namespace vantage::io
