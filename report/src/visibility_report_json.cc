// The "visibility" object of `vantage analyze --json` (issue 18's field names, README
// "vantage analyze"): the layout on its body.

#include <cmath>

#include "visibility_report_json.h"

#include "vantage/report/json_number.h"

namespace vantage::report::internal {
namespace {

using Json = nlohmann::ordered_json;

using report::json_number;

Json direction(const Eigen::Vector3d& a) {
  return {json_number(a.x()), json_number(a.y()), json_number(a.z())};
}

Json dropout(const visibility::VisibilityReport& r) {
  Json out = Json::array();
  for (const visibility::VisibilityDropoutEntry& e : r.dropout) {
    out.push_back({{"lost", e.lost},
                   {"status", r.entry_status(e)},
                   {"t", json_number(e.t)},
                   {"pbar_min", json_number(e.pbar_min)},
                   {"max_worst_case_error_deg", json_number(e.max_worst_case_error_deg)},
                   {"trackable_fraction", json_number(e.trackable_fraction)}});
  }
  return out;
}

}  // namespace

nlohmann::ordered_json visibility_json(const visibility::VisibilityReport& r) {
  Json out;
  out["model"] = r.with_body ? "cone+mesh" : "cone";
  out["min_visible"] = r.min_visible;
  if (r.workspace) {
    out["workspace"] = {{"axis", direction(r.workspace->axis)},
                        {"half_angle_deg", r.workspace->half_angle_deg}};
  } else {
    out["workspace"] = nullptr;
  }
  out["trackable_fraction"] = json_number(r.coverage.trackable_fraction);
  out["status"] = r.certificate_status();
  const bool trackable =
      r.worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable;
  out["t"] = trackable ? json_number(r.worst.t) : Json(nullptr);
  out["pbar_min"] = trackable ? json_number(r.worst.pbar_min) : Json(nullptr);
  out["max_worst_case_error_deg"] = json_number(r.max_worst_case_error_deg);
  out["worst_viewpoint"] = trackable ? direction(r.worst.viewpoint) : Json(nullptr);
  Json ties = Json::array();
  if (trackable) {
    for (const Eigen::Vector3d& a : r.worst.viewpoints) ties.push_back(direction(a));
  }
  out["worst_viewpoints"] = ties;
  out["visible_markers"] = trackable ? Json(r.worst.visible_markers) : Json::array();
  out["certificate"] = {{"t_upper", json_number(r.worst.t_upper)},
                        {"t_lower", json_number(r.worst.t_lower)},
                        {"certified", r.certified()},
                        {"certified_at_resolution",
                         r.worst.certified() && r.with_body && !r.exact_viewpoint_disagrees()},
                        {"patches", r.worst.patches}};
  out["occlusion_resolution_deg"] =
      r.occlusion_resolution_deg ? Json(*r.occlusion_resolution_deg) : Json(nullptr);
  if (r.exact_viewpoint) {
    out["exact_viewpoint"] = {{"visible_markers", r.exact_viewpoint->visible},
                              {"trackable", r.exact_viewpoint->trackable},
                              {"t", json_number(r.exact_viewpoint->t)},
                              {"agrees", !r.exact_viewpoint_disagrees()}};
  }
  out["lost"] = {{"fraction", json_number(r.coverage.lost_fraction)},
                 {"largest_region_center", r.coverage.largest_region_center
                                               ? direction(*r.coverage.largest_region_center)
                                               : Json(nullptr)},
                 {"largest_region_radius_deg", json_number(r.coverage.largest_region_radius_deg)}};
  if (r.with_body) {
    out["distance_to_body"] = r.distance_to_body;
    out["off_body"] = r.off_body;
    out["hidden_by_body"] = r.hidden_by_body;
  }
  if (!r.dropout.empty()) {
    out["dropout"] = dropout(r);
    out["dropout_by_harm"] = r.dropout_by_harm;
  }
  return out;
}

}  // namespace vantage::report::internal
