#include "vantage/commands/tre_json.h"

namespace vantage::tre_json {
namespace {

Json tre_vector3(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json tre_matrix3(const Eigen::Matrix3d& m) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i) rows.push_back(Json::array({m(i, 0), m(i, 1), m(i, 2)}));
  return rows;
}

Json at_direction(const tracker::TreAtDirection& at) {
  Json out;
  out["direction"] = tre_vector3(at.direction);
  out["tracked"] = at.tracked;
  out["rms"] = at.tracked ? Json(at.rms) : Json(nullptr);
  out["covariance"] = at.tracked ? tre_matrix3(at.covariance) : Json(nullptr);
  out["visible_markers"] = at.visible_markers;
  return out;
}

}  // namespace

Json extreme(const tracker::TreExtreme& e) {
  Json out;
  const bool tracked = e.status != tracker::TreExtreme::Status::kUntracked;
  out["direction"] = tracked ? tre_vector3(e.direction) : Json(nullptr);
  out["rms"] = tracked ? Json(e.rms) : Json(nullptr);
  out["visible_markers"] = e.visible_markers;
  out["certified"] = e.certified();
  out["status"] = tracker::to_string(e.status);
  out["rms_bound"] = tracked ? Json(e.rms_bound) : Json(nullptr);
  out["patches"] = e.patches;
  out["closed_form"] = e.closed_form;
  return out;
}

Json report(const tracker::TreReport& r) {
  Json targets = Json::array();
  for (const tracker::TreTargetReport& t : r.targets) {
    Json entry;
    entry["target"] = tre_vector3(t.target);
    if (t.rms_isotropic) entry["rms_isotropic"] = *t.rms_isotropic;
    if (t.at_direction) entry["at_direction"] = at_direction(*t.at_direction);
    entry["worst"] = extreme(t.extremes.worst);
    entry["best"] = extreme(t.extremes.best);
    if (t.monte_carlo) {
      entry["monte_carlo"] = {{"trials", t.monte_carlo->trials},
                              {"rms", t.monte_carlo->rms},
                              {"formula_rms", t.monte_carlo->formula_rms},
                              {"rel_diff", t.monte_carlo->rel_diff},
                              {"direction", tre_vector3(t.monte_carlo_direction)}};
    }
    targets.push_back(std::move(entry));
  }
  Json fle;
  if (r.fle.from_rms) {
    fle = {{"kind", "isotropic"}, {"rms", r.fle.rms()}};
  } else {
    fle = {{"kind", "anisotropic"},
           {"sigma_perp", r.fle.sigma_perp},
           {"sigma_axial", r.fle.sigma_axial},
           {"rms", r.fle.rms()}};
  }
  Json model = {{"registration", "unweighted least squares, no scale (Theorem 1, q-method)"},
                {"order", "first"},
                {"line_of_sight", "tool toward tracker, tool frame"},
                {"markers", r.markers},
                {"min_visible", r.min_visible},
                {"visibility", r.with_body ? "cone+mesh" : (r.with_normals ? "cone" : "none")},
                {"reference", "docs/math.md §23"}};
  if (r.five_dof) {
    model["five_dof"] = {{"axis_point", tre_vector3(r.axis_point)},
                         {"axis", tre_vector3(r.axis)},
                         {"note",
                          "collinear markers: the rotation about the axis is not "
                          "measured; targets on the axis only"}};
  }
  Json out;
  out["targets"] = std::move(targets);
  out["fle"] = std::move(fle);
  out["model"] = std::move(model);
  return out;
}

std::string untracked_reason(const tracker::TreReport& report) {
  for (const tracker::TreTargetReport& target : report.targets) {
    if (target.extremes.worst.status == tracker::TreExtreme::Status::kUntracked) {
      return "no direction of the workspace sees at least " + std::to_string(report.min_visible) +
             " markers that are not collinear: the TRE is not defined";
    }
  }
  return "";
}

}  // namespace vantage::tre_json
