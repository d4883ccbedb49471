#include "vantage/simulate/visibility_json.h"

#include <cmath>
#include <limits>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

Json vector_json(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

using TrialField = double VisibilityTrial::*;
const std::vector<std::pair<const char*, TrialField>>& trial_fields() {
  static const std::vector<std::pair<const char*, TrialField>> fields = {
      {"t", &VisibilityTrial::t},
      {"pbar", &VisibilityTrial::pbar},
      {"max_error_rad", &VisibilityTrial::max_error_rad},
      {"max_mismatch_rad", &VisibilityTrial::max_mismatch_rad},
      {"max_mismatch_ratio", &VisibilityTrial::max_mismatch_ratio},
      {"view_excess_ratio", &VisibilityTrial::view_excess_ratio},
  };
  return fields;
}

/// Reads the fields of a shard file, naming the file and the field on a bad shape.
class Reader {
 public:
  Reader(const std::string& source, std::string prefix)
      : source_(source), prefix_(std::move(prefix)) {}

  [[noreturn]] void bad(const std::string& field, const std::string& what) const {
    throw InvalidArgument(source_ + ": " + prefix_ + field + ": " + what);
  }
  const Json& member(const Json& object, const std::string& name) const {
    if (!object.is_object() || !object.contains(name)) bad(name, "missing");
    return object.at(name);
  }
  double number(const Json& value, const std::string& field) const {
    if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (!value.is_number()) bad(field, "not a number");
    return value.get<double>();
  }
  Eigen::Vector3d vector(const Json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 3) bad(field, "must be a list of 3 numbers");
    return {number(value[0], field), number(value[1], field), number(value[2], field)};
  }
  std::vector<int> indices(const Json& value, const std::string& field) const {
    if (!value.is_array()) bad(field, "must be a list of marker indices");
    std::vector<int> out;
    for (const Json& i : value) {
      if (!i.is_number_integer() || i.get<long>() < 0) bad(field, "must hold marker indices");
      out.push_back(i.get<int>());
    }
    return out;
  }
  /// A list of `size` entries (size 0: any).
  const Json& list(const Json& object, const std::string& name, std::size_t size) const {
    const Json& value = member(object, name);
    if (!value.is_array() || (size > 0 && value.size() != size)) {
      bad(name, "must be a list of one entry per trial");
    }
    return value;
  }

 private:
  const std::string& source_;
  std::string prefix_;
};

}  // namespace

Json to_json(const VisibilityCheck& check) {
  const VisibilitySetup& s = check.setup;
  Json workspace = nullptr;
  if (s.workspace) {
    workspace = {{"axis", vector_json(s.workspace->axis)},
                 {"half_angle_deg", s.workspace->half_angle_deg}};
  }
  Json out = {{"model", s.model()},
              {"min_visible", s.min_visible},
              {"workspace", workspace},
              {"occlusion_resolution_deg",
               s.occlusion_resolution_deg ? Json(*s.occlusion_resolution_deg) : Json(nullptr)},
              {"trackable_fraction", s.trackable_fraction},
              {"coverage_samples", s.coverage_samples},
              {"worst_viewpoint", vector_json(s.worst_viewpoint)},
              {"worst_visible_markers", s.worst_visible},
              {"t_upper", json_number(s.t_upper)},
              {"t_lower", json_number(s.t_lower)},
              {"pbar_min", json_number(s.pbar_min)},
              {"bound_deg", json_number(check.bound_deg)},
              {"trials", check.trials},
              {"draws", check.draws},
              {"visible_markers", to_json(check.visible_markers)},
              {"max_view_t", json_number(check.max_view_t)},
              {"bound_checked", check.bound_checked}};
  if (!check.bound_checked) return out;
  const Json fields = {
      {"max_error_deg", json_number(check.max_error_deg)},
      {"max_ratio", json_number(check.max_ratio)},
      {"max_view_ratio", json_number(check.max_view_ratio)},
      {"max_view_excess_over_tolerance", json_number(check.max_view_excess_over_tolerance)},
      {"max_abs_eq26_mismatch_deg", json_number(check.max_abs_eq26_mismatch_deg)},
      {"max_eq26_mismatch_over_tolerance", json_number(check.max_eq26_mismatch_over_tolerance)},
      {"passed", check.passed},
      {"message", check.message}};
  out.update(fields);
  return out;
}

VisibilitySetup visibility_setup_from_json(const Json& visibility, const std::string& source) {
  const Reader read(source, "visibility.");
  VisibilitySetup s;
  const Json& model = read.member(visibility, "model");
  if (model != "cone" && model != "cone+mesh") read.bad("model", "must be cone or cone+mesh");
  s.with_body = model == "cone+mesh";
  const Json& min_visible = read.member(visibility, "min_visible");
  if (!min_visible.is_number_integer()) read.bad("min_visible", "must be an integer");
  s.min_visible = min_visible.get<int>();
  const Json& workspace = read.member(visibility, "workspace");
  if (!workspace.is_null()) {
    LayoutWorkspace w;
    w.axis = read.vector(read.member(workspace, "axis"), "workspace.axis");
    w.half_angle_deg = read.number(read.member(workspace, "half_angle_deg"), "workspace");
    s.workspace = w;
  }
  const Json& resolution = read.member(visibility, "occlusion_resolution_deg");
  if (!resolution.is_null()) {
    s.occlusion_resolution_deg = read.number(resolution, "occlusion_resolution_deg");
  }
  s.trackable_fraction =
      read.number(read.member(visibility, "trackable_fraction"), "trackable_fraction");
  const Json& samples = read.member(visibility, "coverage_samples");
  if (!samples.is_number_integer()) read.bad("coverage_samples", "must be an integer");
  s.coverage_samples = samples.get<int>();
  s.worst_viewpoint = read.vector(read.member(visibility, "worst_viewpoint"), "worst_viewpoint");
  s.worst_visible =
      read.indices(read.member(visibility, "worst_visible_markers"), "worst_visible_markers");
  s.t_upper = read.number(read.member(visibility, "t_upper"), "t_upper");
  s.t_lower = read.number(read.member(visibility, "t_lower"), "t_lower");
  s.pbar_min = read.number(read.member(visibility, "pbar_min"), "pbar_min");
  s.bound_rad = std::asin(std::min(1.0, s.t_upper));
  return s;
}

Json visibility_trials_json(const std::vector<VisibilityTrial>& trials) {
  Json direction = Json::array();
  Json visible = Json::array();
  Json draws = Json::array();
  for (const VisibilityTrial& t : trials) {
    direction.push_back(vector_json(t.direction));
    visible.push_back(t.visible);
    draws.push_back(t.draws);
  }
  Json out = {{"direction", direction}, {"visible", visible}, {"draws", draws}};
  for (const auto& [name, field] : trial_fields()) {
    Json list = Json::array();
    for (const VisibilityTrial& t : trials) list.push_back(json_number(t.*field));
    out[name] = list;
  }
  return out;
}

std::vector<VisibilityTrial> visibility_trials_from_json(const Json& json,
                                                         const std::string& source) {
  const Reader read(source, "per_trial.visibility.");
  const Json& direction = read.list(json, "direction", 0);
  const std::size_t n = direction.size();
  const Json& visible = read.list(json, "visible", n);
  const Json& draws = read.list(json, "draws", n);
  std::vector<VisibilityTrial> trials(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string at = "[" + std::to_string(k) + "]";
    trials[k].direction = read.vector(direction[k], "direction" + at);
    trials[k].visible = read.indices(visible[k], "visible" + at);
    if (!draws[k].is_number_integer()) read.bad("draws" + at, "must be an integer");
    trials[k].draws = draws[k].get<long>();
  }
  for (const auto& [name, field] : trial_fields()) {
    const Json& values = read.list(json, name, n);
    for (std::size_t k = 0; k < n; ++k) {
      trials[k].*field = read.number(values[k], name + std::string("[") + std::to_string(k) + "]");
    }
  }
  return trials;
}

}  // namespace vantage::simulate
