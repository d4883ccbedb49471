#include "pose_json.h"

#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::pose_json {
namespace {

constexpr double kRadiansToDegrees = 180.0 / 3.14159265358979323846;

/// The head of every object: method, n.
Json head(const std::string& method, Eigen::Index n) {
  Json out;
  out["method"] = method;
  out["n"] = n;
  return out;
}

/// The fields every method prints: R, p, status, ambiguous, reprojection_rms_px, alternative.
void pose_fields(const PoseEstimate& pose, Json* out) {
  (*out)["R"] = rows(pose.R_camera_object);
  (*out)["p"] = finite_list(pose.p_camera_object);
  (*out)["status"] = to_string(pose.status);
  (*out)["ambiguous"] = pose.ambiguous;
  (*out)["reprojection_rms_px"] = number(pose.reprojection_rms_px);
  if (!pose.message.empty()) (*out)["message"] = pose.message;
  if (pose.alternative) {
    Json alternative;
    alternative["R"] = rows(pose.alternative->R_camera_object);
    alternative["p"] = finite_list(pose.alternative->p_camera_object);
    alternative["reprojection_rms_px"] = number(pose.alternative->reprojection_rms_px);
    (*out)["alternative"] = alternative;
  }
}

/// pose_fields for the estimators without an image residual (3-D measurements, two views).
void fields_without_image(const Eigen::Matrix3d& R, const Eigen::Vector3d& p,
                          const std::string& status, const std::string& message, Json* out) {
  (*out)["R"] = rows(R);
  (*out)["p"] = list(p);
  (*out)["status"] = status;
  (*out)["ambiguous"] = false;
  (*out)["reprojection_rms_px"] = nullptr;
  if (!message.empty()) (*out)["message"] = message;
}

}  // namespace

Json rows(const Eigen::Matrix3d& m) {
  Json out = Json::array();
  for (int i = 0; i < 3; ++i) out.push_back({m(i, 0), m(i, 1), m(i, 2)});
  return out;
}

Json list(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json finite_list(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(number(v(i)));
  return out;
}

Json camera(const Camera& camera) {
  Json out;
  out["focal"] = camera.has_focal_length() ? Json(camera.focal_length) : Json(nullptr);
  out["principal_point"] = {camera.principal_point.x(), camera.principal_point.y()};
  return out;
}

Json affine(const std::string& method, Eigen::Index n, const AffinePoseOptions& options,
            const AffinePoseResult& pose) {
  const AffineOrientationResult& o = pose.orientation;
  Json out = head(method, n);
  pose_fields(pose, &out);
  out["alpha"] = number(pose.alpha);
  out["depth_known"] = pose.depth_known;
  out["camera"] = camera(options.camera);
  out["objective"] = number(pose.objective);
  out["orientation_residual"] = number(o.residual);
  out["free_vectors"] = to_string(options.free_vectors);
  out["free_vector_count"] = pose.pairs.cols();
  out["sign_patterns"] = o.sign_patterns;
  out["ambiguity_margin"] = number(o.ambiguity_margin);
  out["runner_up_residual"] = number(o.runner_up_residual);
  out["runner_up_angle_deg"] = std::isfinite(o.runner_up_residual)
                                   ? number(o.runner_up_angle * kRadiansToDegrees)
                                   : Json(nullptr);
  out["clamped"] = o.clamped;
  out["in_plane"] = o.in_plane;
  out["eigen_gap"] = number(o.eigen_gap);
  return out;
}

Json refined(const std::string& method, Eigen::Index n, const RefinedPoseOptions& options,
             const RefinedPoseResult& pose) {
  Json out = head(method, n);
  pose_fields(pose, &out);
  out["alpha"] = number(pose.alpha);
  out["camera"] = camera(options.camera);
  out["iterations"] = pose.iterations;
  out["branches"] = pose.branches;
  out["planarity"] = number(pose.planarity);
  out["start_reprojection_rms_px"] = number(pose.start_reprojection_rms_px);
  return out;
}

Json full3d(const std::string& method, Eigen::Index n, const AffinePoseOptions& options,
            const PoseResult& pose) {
  Json out = head(method, n);
  fields_without_image(pose.R_camera_object, pose.p_camera_object, to_string(pose.status),
                       pose.message, &out);
  out["alpha"] = number(pose.alpha);
  out["objective"] = number(pose.residual);
  out["free_vectors"] = to_string(options.free_vectors);
  out["free_vector_count"] =
      free_vector_count(n, single_pattern_free_vectors(options.free_vectors));
  out["eigen_gap"] = number(pose.eigen_gap);
  return out;
}

Json orthogonal_iteration(const std::string& method, Eigen::Index n,
                          const OrthogonalIterationOptions& options,
                          const OrthogonalIterationResult& pose) {
  Json out = head(method, n);
  pose_fields(pose, &out);
  out["alpha"] = nullptr;
  out["camera"] = camera(options.camera);
  out["objective"] = number(pose.objective);
  out["initial_objective"] = number(pose.initial_objective);
  out["iterations"] = pose.iterations;
  out["branches"] = pose.branches;
  out["rotation_step"] = to_string(options.rotation_step);
  out["points_behind_camera"] = pose.points_behind_camera;
  return out;
}

Json two_view(const std::string& method, Eigen::Index n, const TwoViewOptions& options,
              const TwoViewResult& pose) {
  Json out = head(method, n);
  // The fit is epipolar, not a reprojection: reprojection_rms_px is null.
  fields_without_image(pose.R_camera2_camera1, pose.t_camera2_camera1, to_string(pose.status),
                       pose.message, &out);
  out["T"] = list(pose.t_camera2_camera1);
  out["alpha"] = nullptr;
  out["focal"] = options.focal_length;
  out["epipolar_rms"] = number(pose.residual);
  out["essential"] = rows(pose.essential);
  out["null_space_ratio"] = number(pose.null_space_ratio);
  out["points_in_front"] = pose.points_in_front;
  return out;
}

}  // namespace vantage::pose_json
