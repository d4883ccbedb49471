#pragma once

/// Haralick et al. [H], Sec. 2: closed-form weighted least-squares 2-D rotation and
/// translation between corresponding 2-D point sets (2D-2D pose estimation).
///
/// Frames: to_i ~= R_to_from * from_i + t_to_from, with R the counter-clockwise rotation by theta
///   R = [[cos theta, -sin theta], [sin theta, cos theta]].
/// In the paper's notation from = x_n (observed), to = y_n (model). The objective is
///   eps^2 = sum_n w_n ||to_n - (R from_n + t)||^2                              (Sec. 2.1)
/// whose optimal translation is t = y_bar - R x_bar (weighted centroids), and whose stationary
/// angles satisfy A sin theta + B cos theta = 0 with
///   A = sum w [(y1 - y1_bar)(x1 - x1_bar) + (y2 - y2_bar)(x2 - x2_bar)],
///   B = sum w [(y1 - y1_bar)(x2 - x2_bar) - (y2 - y2_bar)(x1 - x1_bar)]       (Sec. 2.2)
/// That equation has two solutions half a turn apart, (cos, sin) = +-(A, -B) / sqrt(A^2 + B^2);
/// as the paper prescribes, both are substituted into eps^2 and the smaller one is kept (the
/// other is the worst rotation). The paper has no scale: the estimate is a rigid motion.
///
/// Point sets are Eigen::Matrix2Xd with one column per point. Weights are an Eigen::VectorXd with
/// one entry >= 0 per column (the paper's w_n >= 0; they need not sum to 1); an empty vector
/// means all weights are 1.

#include <Eigen/Core>
#include <string>

namespace vantage {

/// Outcome of pose_2d().
enum class Pose2dStatus {
  kOk,  ///< sqrt(A^2 + B^2) > Pose2dOptions::degenerate_tolerance * sqrt(S_from S_to)
  /// sqrt(A^2 + B^2) <= degenerate_tolerance * sqrt(S_from S_to), where S_from and S_to are the
  /// weighted spreads sum w ||x - x_bar||^2 and sum w ||y - y_bar||^2 (an upper bound of
  /// sqrt(A^2 + B^2) by Cauchy-Schwarz): fewer than two distinct points, or correlation so weak
  /// that every angle fits about equally; the result is still the better candidate (theta = 0
  /// when A = B = 0) but the angle is not determined by the data
  kDegenerate,
};

/// "ok" or "degenerate".
const char* to_string(Pose2dStatus status);

/// Options of pose_2d().
struct Pose2dOptions {
  /// Relative correlation sqrt(A^2 + B^2) / sqrt(S_from S_to) at or below which the status is
  /// kDegenerate. Dimensionless, in [0, 1).
  double degenerate_tolerance = 1e-12;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Rigid 2-D pose from point correspondences (Haralick et al. Sec. 2).
struct Pose2dResult {
  Eigen::Matrix2d R_to_from = Eigen::Matrix2d::Identity();
  Eigen::Vector2d t_to_from = Eigen::Vector2d::Zero();
  double theta = 0.0;     ///< counter-clockwise angle of R_to_from in radians, in (-pi, pi]
  double residual = 0.0;  ///< eps^2 at the chosen candidate, with the weights as given
  /// eps^2 at the other stationary angle theta + pi, which the two-candidate test rejected (the
  /// maximum of eps^2 over theta); residual <= rejected_residual always.
  double rejected_residual = 0.0;
  double correlation_a = 0.0;  ///< A of Sec. 2.2 (weights as given)
  double correlation_b = 0.0;  ///< B of Sec. 2.2 (weights as given)
  Pose2dStatus status = Pose2dStatus::kOk;
  std::string message;  ///< empty when status is kOk
};

/// Haralick et al. Sec. 2: minimises eps^2 = sum w_n ||to_n - (R from_n + t)||^2 over the 2-D
/// rotation R and translation t in closed form. from and to: 2 x n, n >= 1, finite; weights: n
/// finite entries >= 0 with a positive sum, or empty. Allocates nothing unless degenerate.
/// Throws InvalidArgument (naming the argument) on mismatched sizes, n = 0, non-finite points,
/// negative, non-finite or all-zero weights, or invalid options.
Pose2dResult pose_2d(const Eigen::Matrix2Xd& from, const Eigen::Matrix2Xd& to,
                     const Eigen::VectorXd& weights = {}, const Pose2dOptions& options = {});

}  // namespace vantage
