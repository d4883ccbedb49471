#pragma once

/// Pose from one perspective image by orthogonal iteration (Lu, Hager & Mjolsness 2000) with the
/// absolute-orientation step done by FOAM, as proposed by Wu & Wu ([W]; docs/math.md §5
/// and §17), or by Haralick's SVD ([H] Sec. 3) for [W]'s comparison.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z.
///
/// Image points are (u, v) in pixels with the camera of camera.h (focal length f and principal
/// point c in pixels; f = 1, c = 0 when the points are already normalised coordinates x/z, y/z).
/// Point i defines the line of sight through
///   m_i = ((u_i - c_x) / f, (v_i - c_y) / f, 1),
/// and the observed line-of-sight projection V_i = m_i m_i^T / (m_i^T m_i) (Wu & Wu Sec. 2).
///
/// Object-space collinearity error (Wu & Wu Eq. 7, Lu et al. Eq. 17), in squared object units:
///   E(R, p) = sum_i w_i || (I - V_i) (R x_i + p) ||^2.
/// For fixed R the optimal translation is closed-form (Wu & Wu Eq. 10):
///   p(R) = F^-1 sum_i w_i (V_i - I) R x_i,   F = sum_i w_i (I - V_i),
/// and each iteration projects the current camera-frame points onto their lines of sight,
/// q_i = V_i (R x_i + p(R)), and solves the absolute-orientation problem
///   R <- argmax_R sum_i w_i q_i^T R (x_i - x_bar)     (Wu & Wu Eq. 12-14)
/// with FOAM (Eq. 17-20) or the SVD (Eq. 15-16). The start is the weak-perspective estimate
/// (the same absolute-orientation step between the centred model and the centred rays m_i).
///
/// E measures distances perpendicular to the lines of sight, not along them: a point behind the
/// camera lies on its line too. The result reports how many points end up behind the camera.
///
/// Two branches: for a (near-)planar model (BranchOptions::necker_planarity) the weak-perspective
/// start only determines the rotation about the optical axis (the centred model and the centred
/// rays both lie in planes), so the iteration starts instead from Prop. 8 (affine_pose()) and
/// from its Necker mirror; the run with the smaller E (fewer points behind the camera first) is
/// returned, the other as `alternative`, and `ambiguous` follows BranchOptions, so the result is
/// never a local minimum that the other branch is known to beat.

#include <Eigen/Core>
#include <string>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/camera.h"
#include "vantage/analysis/pose_estimate.h"

namespace vantage {

/// Options of orthogonal_iteration_pose().
struct OrthogonalIterationOptions {
  /// Absolute-orientation step: kFoam (Wu & Wu), kSvd (Lu et al.'s original) or kQMethod.
  OrientationMethod rotation_step = OrientationMethod::kFoam;
  /// The camera, pixels; camera.focal_length must be > 0 (1 for normalised coordinates).
  Camera camera;
  /// Stop when E <= absolute_tolerance * sum w_i |x_i - x_bar|^2 (E relative to the model's
  /// spread). Dimensionless, >= 0.
  double absolute_tolerance = 1e-24;
  /// Stop when one step changes E by at most relative_tolerance * E. Dimensionless, >= 0.
  double relative_tolerance = 1e-12;
  /// Stop when one step rotates by at most pose_tolerance radians and moves p by at most
  /// pose_tolerance * |p|: the pose has stopped changing (exact data, where E keeps shrinking
  /// geometrically). Dimensionless, >= 0.
  double pose_tolerance = 1e-12;
  /// Maximum number of rotation steps; >= 0 (0 returns the weak-perspective start).
  int max_iterations = 500;
  /// Relative threshold of the kDegenerate status (see there). Dimensionless, in [0, 1).
  double degenerate_tolerance = 1e-12;
  /// Fallback tuning of the FOAM / q-method step (see OrientationOptions::eigen).
  TopEigenOptions eigen;
  /// When the Necker branch is also iterated and when the result is ambiguous.
  BranchOptions branches;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Pose from orthogonal iteration. PoseEstimate's fields:
///  - status kOk: E <= absolute_tolerance * spread, or a step changed E by at most
///    relative_tolerance * E, or a step changed the pose by at most pose_tolerance (see there);
///    kMaxIterations: max_iterations rotation steps without any of these (R, p are the last
///    iterate); kDegenerate: all lines of sight (nearly) parallel, so F is singular (smallest
///    eigenvalue <= degenerate_tolerance * sum w_i), or the absolute-orientation step had a
///    relative eigen gap <= degenerate_tolerance (e.g. collinear or coincident model points);
///  - reprojection_rms_px: pinhole RMS image residual (+infinity with a point behind the camera);
///  - objective: E(R, p) at the returned pose, squared object units times weight.
struct OrthogonalIterationResult : PoseEstimate {
  double initial_objective = 0.0;  ///< E at the weak-perspective start of the returned branch
  int points_behind_camera = 0;    ///< points with (R x_i + p)_z <= 0 at the returned pose
  int branches = 1;                ///< starts iterated: 1, or 2 with the Necker mirror
};

/// Orthogonal iteration from the weak-perspective start (see the file comment).
/// model_object: 3 x n object points, n >= 3, finite. image: 2 x n image points (u, v), finite.
/// weights: n positive finite entries, or empty for all 1. n = 3 is accepted but the P3P problem
/// has up to four solutions; the iteration returns the one it reaches.
/// For non-planar models allocates nothing beyond the result's message (the translation factor
/// of Eq. 10 is a fixed 3 x 9 matrix computed once); the planar path computes Prop. 8's start.
/// Throws InvalidArgument on mismatched sizes, n < 3, non-finite data, bad weights or options.
OrthogonalIterationResult orthogonal_iteration_pose(const Eigen::Matrix3Xd& model_object,
                                                    const Eigen::Matrix2Xd& image,
                                                    const Eigen::VectorXd& weights = {},
                                                    const OrthogonalIterationOptions& options = {});

/// Orthogonal iteration from a given start rotation (e.g. the previous frame's pose when
/// tracking; one branch only). initial_R_camera_object must be a rotation (|R^T R - I|_F <= 1e-6,
/// det > 0).
OrthogonalIterationResult orthogonal_iteration_pose(const Eigen::Matrix3Xd& model_object,
                                                    const Eigen::Matrix2Xd& image,
                                                    const Eigen::Matrix3d& initial_R_camera_object,
                                                    const Eigen::VectorXd& weights = {},
                                                    const OrthogonalIterationOptions& options = {});

/// The weak-perspective start: the rotation maximising sum_i w_i (m_i - m_bar)^T R (x_i - x_bar)
/// (absolute orientation between the centred model and the centred rays m_i of the file
/// comment, by options.rotation_step). Same preconditions as orthogonal_iteration_pose().
Eigen::Matrix3d weak_perspective_rotation(const Eigen::Matrix3Xd& model_object,
                                          const Eigen::Matrix2Xd& image,
                                          const Eigen::VectorXd& weights = {},
                                          const OrthogonalIterationOptions& options = {});

/// E(R, p) of the file comment for any pose (the residual a caller reports for a pose found by
/// another method). Only options.camera is used. Same preconditions as
/// orthogonal_iteration_pose(), n >= 1.
double object_space_error(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                          const Eigen::Matrix3d& R_camera_object,
                          const Eigen::Vector3d& p_camera_object,
                          const Eigen::VectorXd& weights = {},
                          const OrthogonalIterationOptions& options = {});

}  // namespace vantage
