#pragma once

/// The best pose from one image, started from the paper's closed form (Prop. 8, affine_pose()):
///
///  - affine_refined_pose(): minimises the affine (scaled-orthographic) image residual of
///    camera.h over (R, alpha, p_x, p_y),
///      sum_i w_i |(1 / alpha) P (R z_i + p) - (q_i - c)|^2   (pixels^2),
///    by Levenberg-Marquardt on SO(3) x R^3. For the true alpha and the right signs this residual
///    is zero, so noise-free affine images return the truth (to rounding), which the LUB scale
///    of Lemma 7 does not.
///  - perspective_pose(): minimises the pinhole reprojection error
///      sum_i w_i |f (X_i.x, X_i.y) / X_i.z - (q_i - c)|^2,   X_i = R z_i + p   (pixels^2),
///    by Levenberg-Marquardt on SO(3) x R^3: the maximum-likelihood pose under independent
///    Gaussian pixel noise of variance sigma^2 / w_i. The start (PerspectiveStart) is by default
///    a closed form that is exact on noise-free pinhole images and O(n): POSIT (the scaled
///    orthographic camera corrected for perspective) for non-planar models, IPPE's two poses
///    from the plane's homography for (almost) exactly planar ones; Prop. 8 (affine_pose(), 2^m
///    sign patterns) with p_z = alpha f when those do not apply (n = 3, degenerate systems) or
///    on request.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z.
///
/// Two branches. A (near-)planar model (planarity sigma_3 / sigma_1 of the centred points <=
/// necker_planarity) has two poses that the affine image cannot tell apart, the Necker pair
/// R' = diag(1, 1, -1) R (I - 2 n n^T) (n the plane normal). Both are refined (from Prop. 8 and
/// its mirror for affine_refined_pose(); for perspective_pose() from POSIT and its mirror, or
/// from IPPE's pair, or with PerspectiveStart::kProp8 from Prop. 8, its mirror and the better
/// IPPE pose); the one with the smaller residual is returned and the best distinct other one is
/// `alternative`.
/// `ambiguous` follows BranchOptions (pose_estimate.h): always for exactly planar models under
/// the affine model (the pair is exact there), and under the pinhole model only when
/// perspective does not separate the two beyond the ratio.
///
/// Stopping rule (status kOk): an accepted step with rotation <= step_tolerance radians and
/// relative translation (and scale) change <= step_tolerance, or a decrease of the residual of at
/// most relative_tolerance times the residual, or no descent at any damping; kMaxIterations
/// otherwise; kDegenerate when the start is (affine_pose() degenerate) or the normal equations
/// at the result are singular (relative eigenvalue <= 1e-12: e.g. collinear points).

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string>

#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/camera.h"
#include "vantage/analysis/pose_estimate.h"

namespace vantage {

/// Where perspective_pose() starts the refinement.
enum class PerspectiveStart {
  /// POSIT (planarity > 0.01; with its Necker mirror when planarity <= necker_planarity) or
  /// IPPE's two poses from the plane's homography (planarity <= 0.01 <= necker_planarity):
  /// O(n), exact on noise-free pinhole images; Prop. 8 when they do not apply.
  kClosedForm,
  /// Prop. 8 (2^m sign patterns); for planar models also its Necker mirror and the homography.
  kProp8,
};

/// "closed_form" or "prop8".
const char* to_string(PerspectiveStart start);

/// Options of affine_refined_pose() and perspective_pose().
struct RefinedPoseOptions {
  /// The camera (pixels). perspective_pose() needs focal_length > 0; affine_refined_pose() uses
  /// it only for p_z = alpha f.
  Camera camera;
  /// The closed-form start (free vectors, weighting, Prop. 4 tuning); its camera is ignored.
  AffinePoseOptions start;
  int max_iterations = 50;            ///< per branch, >= 1
  double step_tolerance = 1e-12;      ///< radians / relative, > 0
  double relative_tolerance = 1e-14;  ///< dimensionless, >= 0
  BranchOptions branches;  ///< when the Necker branch is refined and when it is ambiguous
  /// perspective_pose() only (affine_refined_pose() always starts from Prop. 8).
  PerspectiveStart perspective_start = PerspectiveStart::kClosedForm;

  bool is_valid(std::string* why = nullptr) const;
};

/// Result of affine_refined_pose() and perspective_pose(). PoseEstimate's alpha is the refined
/// scale (affine) or p_z / f (perspective), object units per pixel.
struct RefinedPoseResult : PoseEstimate {
  int branches = 0;        ///< starts refined: 1, 2 with the Necker mirror (3: kProp8, planar)
  double planarity = 0.0;  ///< sigma_3 / sigma_1 of the centred model
  /// RMS residual of the best start in the method's own model: Prop. 8 under the affine model
  /// (affine_refined_pose()), the closed-form or Prop. 8 start under the pinhole model
  /// (perspective_pose()).
  double start_reprojection_rms_px = 0.0;
};

/// Refined affine pose (see the file comment). model_object: 3 x n, n >= 3, finite, no two
/// points equal; image: 2 x n finite pixels; weights: n positive or empty. Throws
/// InvalidArgument naming the argument on bad input.
RefinedPoseResult affine_refined_pose(const Eigen::Matrix3Xd& model_object,
                                      const Eigen::Matrix2Xd& image,
                                      const Eigen::VectorXd& weights = {},
                                      const RefinedPoseOptions& options = {});

/// Perspective (pinhole) pose (see the file comment). As affine_refined_pose(), and
/// options.camera.focal_length must be > 0.
RefinedPoseResult perspective_pose(const Eigen::Matrix3Xd& model_object,
                                   const Eigen::Matrix2Xd& image,
                                   const Eigen::VectorXd& weights = {},
                                   const RefinedPoseOptions& options = {});

}  // namespace vantage
