#pragma once

/// The result every single-image pose estimator returns (affine, affine-refined, perspective,
/// orthogonal iteration): the pose, one status pattern, the ambiguity flag, one fit measure, and
/// the second branch when one was evaluated.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z.

#include <Eigen/Core>
#include <optional>
#include <string>

namespace vantage {

/// Outcome of a pose solve. Every estimator uses these three values with these criteria.
enum class PoseStatus {
  /// The estimator met its stopping rule (stated in its header) and, when several branches were
  /// evaluated, the returned pose has the least reprojection error among them.
  kOk,
  /// The iteration limit was reached before the stopping rule held; the pose is the last iterate.
  kMaxIterations,
  /// The data do not determine the pose (collinear or coincident points, singular normal
  /// equations); the pose is not meaningful.
  kDegenerate,
};

/// "ok", "max_iterations" or "degenerate".
const char* to_string(PoseStatus status);

/// The other branch of a two-fold ambiguity, when it was evaluated.
struct PoseAlternative {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_camera_object = Eigen::Vector3d::Zero();
  double reprojection_rms_px = 0.0;  ///< as PoseEstimate::reprojection_rms_px
};

/// Pose from one image.
struct PoseEstimate {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  /// p_z is NaN when the estimator cannot determine the depth (affine model without a focal
  /// length).
  Eigen::Vector3d p_camera_object = Eigen::Vector3d::Zero();
  PoseStatus status = PoseStatus::kOk;
  /// True when a second branch fits about as well (criterion in the estimator's header): the
  /// data cannot tell the two apart and `alternative` holds the other one.
  bool ambiguous = false;
  /// Weighted RMS image residual of the estimator's own camera model, sqrt(sum w |r_i|^2 /
  /// sum w), in pixels (in the image's units when they are not pixels).
  double reprojection_rms_px = 0.0;
  /// The best other branch, when one was evaluated and converged to a distinct pose.
  std::optional<PoseAlternative> alternative;
  int iterations = 0;   ///< iterations of the refinement (0 for closed forms)
  std::string message;  ///< empty when status is kOk and not ambiguous
};

/// The two-branch rule shared by the estimators that evaluate the Necker pair (refined_pose.h,
/// orthogonal_iteration.h).
struct BranchOptions {
  /// Planarity sigma_3 / sigma_1 of the centred model (singular values of the weighted, centred
  /// points) at or below which the Necker branch is also evaluated; in [0, 1] (0: exactly planar
  /// models only, 1: always).
  double necker_planarity = 0.1;
  /// The result is ambiguous when the alternative's RMS residual is at most ambiguity_ratio
  /// times max(best RMS, ambiguity_floor_px): the runner-up fits about as well. >= 1.
  double ambiguity_ratio = 1.5;
  /// RMS residual (pixels) below which a fit counts as exact for the ambiguity test; >= 0.
  double ambiguity_floor_px = 1e-9;
  /// Two branches whose rotations are closer than this (radians) are the same pose; >= 0.
  double same_pose_angle = 1e-6;

  /// The ambiguity test above for an estimate (false without an alternative).
  bool ambiguous(const PoseEstimate& estimate) const;

  bool is_valid(std::string* why = nullptr) const;
};

}  // namespace vantage
