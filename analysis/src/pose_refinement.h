#pragma once

// Private: Levenberg-Marquardt refinement of a pose on SO(3) x R^k for the two camera models of
// camera.h, and the Necker mirror of a pose. Used by refined_pose.cc and
// orthogonal_iteration.cc.

#include <Eigen/Core>

namespace vantage::internal {

/// Stopping rules of refine_*(); see RefinedPoseOptions in refined_pose.h for their meaning.
struct LmSettings {
  int max_iterations = 50;
  double step_tolerance = 1e-12;
  double relative_tolerance = 1e-14;
};

/// A refined pose. sse = sum w |r_i|^2 in pixels^2.
struct LmPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  double inverse_alpha = 1.0;  ///< scaled-orthographic model only: pixels per object unit
  double sse = 0.0;
  int iterations = 0;
  bool converged = false;   ///< a stopping rule held before max_iterations
  bool degenerate = false;  ///< the normal equations were singular at the end
};

/// Scaled orthographic: r_i = s P R z_i + t - (q_i - c), over (R, s, t); returns p_xy = t / s,
/// p_z untouched (start.p.z()). centred = q - c.
LmPose refine_scaled_orthographic(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                                  const Eigen::VectorXd& weights, const LmPose& start,
                                  const LmSettings& settings);

/// Pinhole: r_i = f (X_i.x, X_i.y) / X_i.z - (q_i - c), X_i = R z_i + p, over (R, p). Steps that
/// put a point at or behind the camera are rejected.
LmPose refine_pinhole(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                      const Eigen::VectorXd& weights, double focal_length, const LmPose& start,
                      const LmSettings& settings);

/// sum w |r_i|^2 of the pinhole model (+infinity when a point is at or behind the camera).
double pinhole_sse(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                   const Eigen::VectorXd& weights, double focal_length, const Eigen::Matrix3d& R,
                   const Eigen::Vector3d& p);

/// Best-fit plane of the weighted points: its unit normal, the weighted centroid and the
/// planarity sigma_3 / sigma_1 of the centred points (0: coplanar).
struct PlaneFit {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double planarity = 0.0;
};
PlaneFit fit_plane(const Eigen::Matrix3Xd& model, const Eigen::VectorXd& weights);

/// The Necker mirror of (R, p) about `plane`: R' = diag(1, 1, -1) R (I - 2 n n^T), with p' such
/// that the centroid keeps its camera-frame position. For points in the plane the affine image
/// P (R' z + p') equals P (R z + p): the two-fold affine ambiguity.
void necker_mirror(const PlaneFit& plane, const Eigen::Matrix3d& R, const Eigen::Vector3d& p,
                   Eigen::Matrix3d* R_mirror, Eigen::Vector3d* p_mirror);

}  // namespace vantage::internal
