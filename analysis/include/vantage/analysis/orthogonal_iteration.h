#pragma once

/// Pose from one perspective image by orthogonal iteration (Lu, Hager & Mjolsness 2000) with the
/// absolute-orientation step done by FOAM, as proposed by Wu & Wu (seed 004; DESIGN.md notes 8
/// and 9), or by Haralick's SVD (seed 003, Sec. 3) for the seed's comparison.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z.
///
/// Image points are (u, v) in image units centred at the principal point. With focal length f
/// (OrthogonalIterationOptions::focal_length, in image units; f = 1 means the points are already
/// normalised camera coordinates x/z, y/z) point i defines the line of sight through
///   m_i = (u_i / f, v_i / f, 1),
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

#include <Eigen/Core>
#include <string>

#include "vantage/analysis/absolute_orientation.h"

namespace vantage {

/// Outcome of orthogonal_iteration_pose().
enum class OrthogonalIterationStatus {
  /// E <= absolute_tolerance, or |E_(k-1) - E_k| <= relative_tolerance * E_(k-1) after a step
  kConverged,
  /// max_iterations rotation steps were taken without meeting either threshold; R, p are the
  /// last iterate (usable, but not converged to the requested accuracy)
  kMaxIterations,
  /// the data do not determine the pose: all lines of sight (nearly) parallel, so F is singular
  /// (smallest eigenvalue <= degenerate_tolerance * sum w_i), or the absolute-orientation step
  /// had a relative eigen gap <= degenerate_tolerance (e.g. collinear or coincident model points)
  kDegenerate,
};

/// "converged", "max_iterations" or "degenerate".
const char* to_string(OrthogonalIterationStatus status);

/// Options of orthogonal_iteration_pose().
struct OrthogonalIterationOptions {
  /// Absolute-orientation step: kFoam (Wu & Wu), kSvd (Lu et al.'s original) or kQMethod.
  OrientationMethod rotation_step = OrientationMethod::kFoam;
  /// Focal length in image units per unit of normalised coordinate; > 0 and finite. The default 1
  /// means image points are normalised camera coordinates.
  double focal_length = 1.0;
  /// Stop when E <= absolute_tolerance. Units of E: squared object units times weight. >= 0.
  double absolute_tolerance = 1e-20;
  /// Stop when one step changes E by at most relative_tolerance * E. Dimensionless, >= 0.
  double relative_tolerance = 1e-12;
  /// Maximum number of rotation steps; >= 0 (0 returns the weak-perspective start).
  int max_iterations = 500;
  /// Relative threshold of the kDegenerate status (see there). Dimensionless, in [0, 1).
  double degenerate_tolerance = 1e-12;
  /// Fallback tuning of the FOAM / q-method step (see OrientationOptions::eigen).
  TopEigenOptions eigen;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Pose from orthogonal iteration.
struct OrthogonalIterationResult {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_camera_object = Eigen::Vector3d::Zero();  ///< p(R) of the returned R
  /// E(R, p) at the returned pose: squared object units times weight.
  double error = 0.0;
  double initial_error = 0.0;    ///< E at the weak-perspective start
  int iterations = 0;            ///< rotation steps taken after the start
  int points_behind_camera = 0;  ///< points with (R x_i + p)_z <= 0 at the returned pose
  OrthogonalIterationStatus status = OrthogonalIterationStatus::kConverged;
  std::string message;  ///< empty when status is kConverged
};

/// Orthogonal iteration from the weak-perspective start (see the file comment).
/// model_object: 3 x n object points, n >= 3, finite. image: 2 x n image points (u, v), finite.
/// weights: n positive finite entries, or empty for all 1. n = 3 is accepted but the P3P problem
/// has up to four solutions; the iteration returns the one it reaches.
/// Allocates nothing beyond the result's message (the translation factor of Eq. 10 is a fixed
/// 3 x 9 matrix computed once).
/// Throws InvalidArgument on mismatched sizes, n < 3, non-finite data, bad weights or options.
OrthogonalIterationResult orthogonal_iteration_pose(const Eigen::Matrix3Xd& model_object,
                                                    const Eigen::Matrix2Xd& image,
                                                    const Eigen::VectorXd& weights = {},
                                                    const OrthogonalIterationOptions& options = {});

/// Orthogonal iteration from a given start rotation (e.g. the previous frame's pose when
/// tracking). initial_R_camera_object must be a rotation (|R^T R - I|_F <= 1e-6, det > 0).
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
/// another method). Only options.focal_length is used. Same preconditions as
/// orthogonal_iteration_pose(), n >= 1.
double object_space_error(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                          const Eigen::Matrix3d& R_camera_object,
                          const Eigen::Vector3d& p_camera_object,
                          const Eigen::VectorXd& weights = {},
                          const OrthogonalIterationOptions& options = {});

}  // namespace vantage
