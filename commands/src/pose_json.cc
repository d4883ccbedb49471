#include "vantage/commands/pose_json.h"

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/report/json_number.h"

namespace vantage::pose_json {

using report::json_number;

Json rows(const Eigen::Matrix3d& m) {
  Json out = Json::array();
  for (int i = 0; i < 3; ++i) out.push_back({m(i, 0), m(i, 1), m(i, 2)});
  return out;
}

Json list(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Json finite_list(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(json_number(v(i)));
  return out;
}

Json camera(const Camera& camera) {
  Json out;
  out["focal"] = camera.has_focal_length() ? Json(camera.focal_length) : Json(nullptr);
  out["principal_point"] = {camera.principal_point.x(), camera.principal_point.y()};
  return out;
}

Json estimate(const PoseEstimate& pose, Eigen::Index n) {
  const PoseDiagnostics& d = pose.diagnostics;
  Json out;
  out["method"] = to_string(pose.method);
  out["n"] = n;
  out["R"] = rows(pose.R_camera_object);
  out["p"] = finite_list(pose.p_camera_object);
  out["alpha"] = json_number(pose.alpha);
  out["status"] = to_string(pose.status);
  out["ambiguous"] = pose.ambiguous;
  out["reprojection_rms_px"] = json_number(pose.reprojection_rms_px);
  out["objective"] = json_number(pose.objective);
  out["iterations"] = pose.iterations;
  out["camera"] = camera(pose.camera);
  if (!pose.message.empty()) out["message"] = pose.message;
  if (pose.alternative) {
    Json alternative;
    alternative["R"] = rows(pose.alternative->R_camera_object);
    alternative["p"] = finite_list(pose.alternative->p_camera_object);
    alternative["reprojection_rms_px"] = json_number(pose.alternative->reprojection_rms_px);
    out["alternative"] = alternative;
  }
  switch (pose.method) {
    case PoseMethod::kAffine:
    case PoseMethod::kStandard:
      out["depth_known"] = std::isfinite(pose.p_camera_object.z());
      out["orientation_residual"] = json_number(d.orientation_residual);
      out["sign_patterns"] = d.sign_patterns;
      out["ambiguity_margin"] = json_number(d.ambiguity_margin);
      out["runner_up_residual"] = json_number(d.runner_up_residual);
      out["runner_up_angle_deg"] = json_number(d.runner_up_angle_rad * kDegreesPerRadian);
      out["clamped"] = d.clamped;
      out["in_plane"] = d.in_plane;
      out["eigen_gap"] = json_number(d.eigen_gap);
      break;
    case PoseMethod::kFull3d:
    case PoseMethod::kHaralick3d:
      out["eigen_gap"] = json_number(d.eigen_gap);
      break;
    case PoseMethod::kAffineRefined:
    case PoseMethod::kPerspective:
      out["branches"] = d.branches;
      out["planarity"] = json_number(d.planarity);
      out["start_reprojection_rms_px"] = json_number(d.start_reprojection_rms_px);
      break;
    case PoseMethod::kOiFoam:
    case PoseMethod::kOiSvd:
      out["branches"] = d.branches;
      out["initial_objective"] = json_number(d.initial_objective);
      out["points_behind_camera"] = d.points_behind_camera;
      if (d.rotation_step) out["rotation_step"] = to_string(*d.rotation_step);
      break;
    case PoseMethod::kTwoView:
      out["T"] = list(pose.p_camera_object);
      out["focal"] = pose.camera.focal_length;
      out["epipolar_rms"] = json_number(pose.objective);
      if (d.essential) out["essential"] = rows(*d.essential);
      out["null_space_ratio"] = json_number(d.null_space_ratio);
      out["points_in_front"] = d.points_in_front;
      break;
    case PoseMethod::kHaralick2d:
      out["rejected_objective"] = json_number(d.rejected_objective);
      break;
  }
  if (d.free_vectors) {
    out["free_vectors"] = to_string(*d.free_vectors);
    out["free_vector_count"] = d.free_vector_count;
  }
  return out;
}

}  // namespace vantage::pose_json
