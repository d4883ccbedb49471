#pragma once

/// The front door of every pose estimator: one call, one input type, one result type.
/// `vantage pose`, `vantage simulate` and `vantage.pose` all call estimate_pose(); the solver
/// functions it dispatches to (affine_pose.h, refined_pose.h, orthogonal_iteration.h,
/// absolute_orientation.h, two_view.h, haralick_2d.h) remain for callers who want their full
/// results.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z.
/// Two views: x_camera2 = R_camera2_camera1 * x_camera1 + T, |T| = 1 (PoseEstimate's R and p).

#include <Eigen/Core>
#include <string>

#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/camera.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/pose_estimate.h"
#include "vantage/analysis/pose_method.h"

namespace vantage {

/// What the estimators measure from: the fields of a correspondence file (README, "File
/// formats"), with the same names, so that an error names the user's field. Absent data have no
/// columns; data a method does not use are ignored. Each method needs the data of
/// pose_data(method):
///  - kImage: `model` (3 x n object-frame points, n >= 3, no two equal) and `image` (2 x n,
///    pixels of `camera`);
///  - kMeasured: `model` and `measured` (3 x n, camera frame, alpha measured = R model + p);
///  - kTwoViews: `image1` and `image2` (2 x n each, n >= 8, pixels of `camera`), no weights;
///  - kPlanar: `model` (3 x n, z = 0) and `image` (2 x n, the moved points in the same units).
/// `directions`: `model` holds data vectors z_i and `image` their affine images d_i (Eq. 15;
/// affine: Lemma 7, standard: Theorem 1 with v_z = 0; n >= 2, no translation).
/// Every coordinate's magnitude is at most Layout::kMaxLength (1e150), so that differences and
/// squares stay finite.
struct Correspondences {
  Eigen::Matrix3Xd model;
  Eigen::Matrix2Xd image;
  Eigen::Matrix3Xd measured;
  Eigen::Matrix2Xd image1;
  Eigen::Matrix2Xd image2;
  Eigen::VectorXd weights;  ///< one positive entry per correspondence, or empty (all 1)
  /// Pixels. The pinhole methods (perspective, oi-*) and two-view without a focal length read
  /// the image as normalised coordinates (f = 1); the affine methods then leave p_z unknown.
  Camera camera;
  bool directions = false;
};

/// Options of estimate_pose().
struct PoseOptions {
  /// The free vectors of the methods that use them (uses_free_vectors()). kAuto is the one
  /// policy everywhere (free_vectors.h); an explicit set larger than orientation.max_vectors is
  /// refused for the methods that enumerate Prop. 4's 2^m sign patterns (affine and the starts
  /// of affine-refined and perspective).
  FreeVectorSet free_vectors = FreeVectorSet::kAuto;
  PairWeighting pair_weighting = PairWeighting::kGeometricMean;
  AffineOrientationOptions orientation;  ///< Prop. 4 tuning
  BranchOptions branches;                ///< the Necker pair (refined methods, oi-*)

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Checks `data` for `method` as estimate_pose() does and throws InvalidArgument naming the
/// Correspondences field ("model", "image", "measured", "image1", "image2", "weights",
/// "camera.focal", "camera.principal_point") and index: data the method needs but lacks,
/// weights for two-view (unweighted), direction data for a method without Lemma 7, counts that
/// differ, too few correspondences, non-finite or over-large coordinates, coincident model
/// points, and an explicit free-vector set beyond Prop. 4's limit.
void validate_correspondences(PoseMethod method, const Correspondences& data,
                              const PoseOptions& options = {});

/// Runs `method` on `data` (see the solver headers for each method's model and stopping rule)
/// and returns its estimate with `method`, `camera` and the method's diagnostics filled in.
/// Bad input throws InvalidArgument (validate_correspondences()); a numerical outcome (degenerate
/// data, no convergence) is the estimate's status, with the reason in `message`.
PoseEstimate estimate_pose(PoseMethod method, const Correspondences& data,
                           const PoseOptions& options = {});

}  // namespace vantage
