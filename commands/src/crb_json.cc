// The JSON of the pose CRB report (crb_json.h).

#include "vantage/commands/crb_json.h"

#include <cmath>

#include "vantage/report/json_number.h"

namespace vantage::crb_json {

namespace {

using report::json_number;

Json vector3(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

}  // namespace

Json at_direction(const camera::PoseCrbAt& at, bool with_covariance) {
  Json out = Json::object();
  out["direction"] = vector3(at.direction);
  out["trackable"] = at.trackable;
  out["unbounded"] = at.unbounded;
  out["rot_rms_deg"] = json_number(at.rot_rms_deg);
  out["trans_rms"] = json_number(at.trans_rms);
  if (with_covariance) {
    Json rows = Json::array();
    for (int r = 0; r < 6; ++r) {
      Json row = Json::array();
      for (int c = 0; c < 6; ++c) row.push_back(at.covariance(r, c));
      rows.push_back(row);
    }
    out["covariance"] = at.trackable ? rows : Json(nullptr);
    out["covariance_order"] = "x, y, z, rx, ry, rz (camera frame; layout units, radians)";
  }
  out["visible_markers"] = at.visible_markers;
  return out;
}

Json report(const camera::PoseCrbReport& r) {
  Json out = Json::object();
  out["camera"] = {
      {"model", "pinhole"},
      {"distance", r.camera.distance},
      {"focal", r.camera.focal_length},
      {"principal_point", {r.camera.principal_point.x(), r.camera.principal_point.y()}},
      {"noise_px", r.camera.noise_px}};
  if (r.camera.aim)
    out["camera"]["aim"] = {r.camera.aim->x(), r.camera.aim->y(), r.camera.aim->z()};
  out["markers"] = r.markers;
  out["visibility"] = r.with_body ? "cone+mesh" : "cone";
  if (r.at_direction) out["at_direction"] = at_direction(*r.at_direction, true);
  const bool ok = r.map.status == camera::PoseCrbMap::Status::kOk;
  out["status"] = camera::to_string(r.map.status);
  if (!ok) out["message"] = camera::untrackable_reason(r.map, r.camera.distance);
  out["worst"] = ok ? at_direction(r.map.worst, false) : Json(nullptr);
  out["best"] = ok ? at_direction(r.map.best, false) : Json(nullptr);
  out["trackable_fraction"] = r.map.trackable_fraction;
  out["unbounded_fraction"] = r.map.unbounded_fraction;
  out["percentiles"] = {{"p50", ok ? Json(r.map.percentiles.p50) : Json(nullptr)},
                        {"p95", ok ? Json(r.map.percentiles.p95) : Json(nullptr)},
                        {"p99", ok ? Json(r.map.percentiles.p99) : Json(nullptr)}};
  out["sliver"] = r.map.sliver;
  out["worst_region_width_deg"] = r.map.worst_region_width_deg;
  out["affine_bound_deg"] = r.affine_bound_deg;
  out["samples"] = static_cast<int>(r.map.samples.size());
  if (!r.sweep_distance.empty()) {
    Json rows = Json::array();
    for (const camera::PoseCrbSweepRow& row : r.sweep_distance) {
      const bool row_ok = row.status == camera::PoseCrbMap::Status::kOk;
      rows.push_back({{"distance", row.distance},
                      {"trackable_fraction", row.trackable_fraction},
                      {"unbounded_fraction", row.unbounded_fraction},
                      {"worst", row_ok ? at_direction(row.worst, false) : Json(nullptr)},
                      {"median", row_ok ? at_direction(row.median, false) : Json(nullptr)}});
    }
    out["sweep_distance"] = rows;
  }
  return out;
}

Json tag_sweep(const std::vector<camera::TagFace>& faces,
               const std::vector<camera::TagSweepRow>& rows) {
  Json out = Json::object();
  Json face_list = Json::array();
  for (const camera::TagFace& face : faces) {
    face_list.push_back({{"centre", vector3(face.centre)},
                         {"normal", vector3(face.normal)},
                         {"extent", face.extent},
                         {"tags", face.tags}});
  }
  out["faces"] = face_list;
  Json row_list = Json::array();
  for (const camera::TagSweepRow& row : rows) {
    const bool ok = row.status == camera::PoseCrbMap::Status::kOk;
    row_list.push_back({{"tags_per_side", row.per_side},
                        {"tags", row.tags},
                        {"fill", row.fill},
                        {"tag_size", row.tag_size},
                        {"tag_pixels", row.tag_pixels},
                        {"status", camera::to_string(row.status)},
                        {"trackable_fraction", row.trackable_fraction},
                        {"unbounded_fraction", row.unbounded_fraction},
                        {"worst", ok ? at_direction(row.worst, false) : Json(nullptr)},
                        {"median", ok ? at_direction(row.median, false) : Json(nullptr)},
                        {"percentiles",
                         {{"p50", ok ? Json(row.percentiles.p50) : Json(nullptr)},
                          {"p95", ok ? Json(row.percentiles.p95) : Json(nullptr)},
                          {"p99", ok ? Json(row.percentiles.p99) : Json(nullptr)}}}});
  }
  out["rows"] = row_list;
  return out;
}

}  // namespace vantage::crb_json
