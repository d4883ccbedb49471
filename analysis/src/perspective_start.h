#pragma once

// Private: closed-form starts of the pinhole pose for perspective_pose() (refined_pose.cc) and
// orthogonal_iteration_pose(): cheap, O(n), and exact on noise-free images, so that the
// refinement only has to polish. The Prop. 8 start (affine_pose()) solves 2^m sign patterns;
// these replace it where they apply.

#include <Eigen/Core>

#include "pose_refinement.h"

namespace vantage::internal {

/// A pinhole start: x_camera = R z + p.
struct PinholeStart {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

/// Iterations of scaled_orthographic_start() and when it stops.
struct PositSettings {
  int max_iterations = 20;
  /// Stops when max_i |eps_i - eps_i'| <= this between two iterations (dimensionless).
  double tolerance = 1e-9;
};

/// Pose of a non-coplanar model by POSIT (DeMenthon and Davis 1995) about the weighted centroid
/// c: with eps_i = r3 . (z_i - c) / p'_z (p' = p + R c, the centroid's camera position), the
/// pinhole projection x_i = f (X_i.x, X_i.y) / X_i.z reads
///   (x_i / f) (1 + eps_i) = (r1 . (z_i - c)) / p'_z + p'_x / p'_z   (and likewise for y),
/// linear in (r1 / p'_z, p'_x / p'_z) for fixed eps. Starting from eps = 0 (the scaled
/// orthographic camera, unique for non-coplanar points: no Necker pair), each iteration solves
/// that 4 x 4 weighted least-squares problem for both image axes, takes the nearest pair of
/// orthonormal rows (r1, r2) with scale 1 / p'_z = the mean singular value, r3 = r1 x r2, and
/// updates eps. Converges to the truth on noise-free images when the object is not too close
/// (geometric rate ~ object size / depth). Returns the iterate of least pinhole error; false
/// when the points are (nearly) coplanar (the 4 x 4 system is singular) or no iterate puts
/// every point in front of the camera. centred = q - principal point, pixels.
bool scaled_orthographic_start(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                               const Eigen::VectorXd& weights, double focal_length,
                               const PositSettings& settings, PinholeStart* start);

/// Planarity (PlaneFit::planarity) at or below which a model is treated as planar: IPPE's
/// homography describes its points; above it POSIT's 4 x 4 system is well enough conditioned.
inline constexpr double kPlanarStartPlanarity = 0.01;

/// The two pinhole poses of a (near-)planar model by IPPE (Collins and Bartoli 2014): the
/// homography H between plane coordinates and normalised image points (linear least squares on
/// Hartley-normalised coordinates), the two rotations that match H's Jacobian at the image of
/// the plane's centroid (the perspective counterparts of the Necker pair), and for each the
/// least-squares translation. On noise-free images of coplanar points one of them is the truth.
/// centred = q - principal point, pixels. Returns how many starts were written (0 when n < 4
/// or the homography is degenerate).
int planar_starts(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                  const Eigen::VectorXd& weights, double focal_length, const PlaneFit& plane,
                  PinholeStart starts[2]);

}  // namespace vantage::internal
