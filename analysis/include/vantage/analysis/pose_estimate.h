#pragma once

/// The one result type of a pose: what estimate_pose() (estimate_pose.h) returns for every
/// method, and the base of the solvers' own results (affine_pose.h, refined_pose.h,
/// orthogonal_iteration.h). The pose, one status with one criterion per value, one ambiguity
/// model (`ambiguous` and the `alternative` branch: a status never says "ambiguous"), one fit
/// measure, and the method's diagnostics.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z.
/// For the relative pose of two views (two-view) the "object" frame is the first camera's:
/// R_camera_object is R_camera2_camera1 and p_camera_object the unit direction of T.

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/camera.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/pose_method.h"

namespace vantage {

/// Outcome of a pose solve. Every estimator uses these three values with these criteria.
enum class PoseStatus {
  /// The estimator met its stopping rule (stated in its header) and, when several branches were
  /// evaluated, the returned pose has the least reprojection error among them.
  kOk,
  /// The iteration limit was reached before the stopping rule held; the pose is the last iterate.
  kMaxIterations,
  /// The data do not determine the pose (collinear or coincident points, singular normal
  /// equations, two views of a critical surface); the pose is not meaningful.
  kDegenerate,
  /// two-view only: no candidate places more than half of the points in front of both cameras
  /// (gross noise or mismatched correspondences); the pose is the best candidate's.
  kNoPointsInFront,
};

/// "ok", "max_iterations", "degenerate" or "no_points_in_front".
const char* to_string(PoseStatus status);

/// The other branch of a two-fold ambiguity, when it was evaluated.
struct PoseAlternative {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_camera_object = Eigen::Vector3d::Zero();
  double reprojection_rms_px = 0.0;  ///< as PoseEstimate::reprojection_rms_px
};

/// What a method reports beside the pose: the quantities `vantage pose` prints for it. A field
/// a method does not compute keeps its default (NaN, 0 or empty), and the groups say which
/// methods fill them.
struct PoseDiagnostics {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  /// Free vectors (affine, standard, full3d; affine-refined and perspective: of the Prop. 8
  /// start, when one was computed): the set asked for and the vectors used.
  std::optional<FreeVectorSet> free_vectors;
  long free_vector_count = 0;

  /// Prop. 4 / Lemma 7 (affine; standard solves its one pattern).
  std::uint64_t sign_patterns = 0;
  double orientation_residual = kNaN;  ///< J_2d of Eq. (15) of the winning pattern
  double runner_up_residual = kNaN;    ///< J_2d of the best distinct other pattern (inf: none)
  double ambiguity_margin = kNaN;      ///< runner_up_residual - orientation_residual
  double runner_up_angle_rad = kNaN;   ///< rotation between the winner and the runner-up
  int clamped = 0;                     ///< vectors whose v_z was clamped to 0 (docs/math.md §8)
  int in_plane = 0;                    ///< vectors in the image plane (one sign)

  /// Theorem 1's conditioning lambda_1 - lambda_2 of D (affine, standard, full3d, haralick-3d).
  double eigen_gap = kNaN;

  /// Refinement and iteration (affine-refined, perspective, oi-foam, oi-svd).
  int branches = 0;                                ///< starts refined (2: the Necker pair too)
  double planarity = kNaN;                         ///< sigma_3 / sigma_1 of the centred model
  double start_reprojection_rms_px = kNaN;         ///< RMS of the best start (refined methods)
  double initial_objective = kNaN;                 ///< E at the weak-perspective start (oi-*)
  int points_behind_camera = 0;                    ///< (oi-*) at the returned pose
  std::optional<OrientationMethod> rotation_step;  ///< (oi-*) the absolute-orientation step

  /// Two views (two-view): E = hat(T) R, sigma_9 / sigma_8 of the motion equations, and the
  /// points in front of both cameras.
  std::optional<Eigen::Matrix3d> essential;
  double null_space_ratio = kNaN;
  int points_in_front = 0;

  /// Haralick's 2-D pose (haralick-2d): eps^2 at the rejected stationary angle theta + pi.
  double rejected_objective = kNaN;
};

/// A pose estimate (see the file comment).
struct PoseEstimate {
  /// The method that produced it (set by estimate_pose(); the solver functions set their own).
  PoseMethod method = PoseMethod::kAffine;
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  /// An entry is NaN when the method does not determine it: p_z without a focal length under
  /// the affine model, all of p for direction data.
  Eigen::Vector3d p_camera_object = Eigen::Vector3d::Zero();
  /// Object units per pixel (affine model: alpha (q - c) = P (R z + p); perspective: p_z / f;
  /// 3-D measurements: alpha q = R z + p); NaN when the method has no scale.
  double alpha = std::numeric_limits<double>::quiet_NaN();
  PoseStatus status = PoseStatus::kOk;
  /// True when a second branch fits about as well (criterion in the estimator's header): the
  /// data cannot tell the two apart and `alternative` holds the other one.
  bool ambiguous = false;
  /// Weighted RMS image residual of the estimator's own camera model, sqrt(sum w |r_i|^2 /
  /// sum w), in pixels (in the image's units when they are not pixels); NaN for the methods
  /// without an image residual (full3d, haralick-2d, haralick-3d, two-view).
  double reprojection_rms_px = 0.0;
  /// The method's own objective at the estimate (its header says which): J of Eq. (35) for
  /// affine and standard, J of Eq. (12) for full3d, E for oi-*, eps^2 for haralick-2d, the RMS
  /// epipolar residual for two-view; NaN when it has none.
  double objective = std::numeric_limits<double>::quiet_NaN();
  /// The best other branch, when one was evaluated and converged to a distinct pose.
  std::optional<PoseAlternative> alternative;
  int iterations = 0;  ///< iterations of the refinement (0 for closed forms)
  Camera camera;       ///< the camera the estimate used (estimate_pose())
  PoseDiagnostics diagnostics;
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
