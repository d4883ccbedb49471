#pragma once

/// Relative pose from two perspective views: Haralick et al.'s simplified linear algorithm
/// ([H] Sec. 4, after Zhuang & Haralick).
///
/// Frames: x_camera2 = R_camera2_camera1 * x_camera1 + T (Haralick's Eq. b, P2 = R0 P1 + T0);
/// both cameras look along +z (Haralick's cameras look along -z; every sign below is for +z).
///
/// Image points are (u, v) in image units centred at the principal point; with focal length f
/// (TwoViewOptions::focal_length; f = 1 means normalised coordinates X = x/z, Y = y/z) point i
/// of view k is the ray m_ki = (u / f, v / f, 1).
///
/// Steps (Sec. 4.2-4.3):
///  1. Two-view motion equation (Eq. c): m_2i^T E m_1i = 0 with E = hat(T) R. Each
///     correspondence gives one row (m_2i kron m_1i) of a linear homogeneous system in the nine
///     entries of E; E is its least-squares solution with ||E||_F = 1 (right singular vector of
///     the smallest singular value).
///  2. Rank 2: E = hat(T) R has singular values (|T|, |T|, 0), so E is replaced by the nearest
///     such matrix, U diag(1, 1, 0) V^T, i.e. ||E||_F = sqrt(2) ||T|| with |T| = 1.
///  3. T: E^T T = 0 (least squares: the left singular vector of the zero singular value), unit
///     length, sign still open.
///  4. R from E = hat(T) R: R = [E_2 x E_3, E_3 x E_1, E_1 x E_2] - hat(T) E, E = [E_1 E_2 E_3].
///  5. Sign choice: E is known only up to sign and T up to sign, giving four (R, T) candidates,
///     two rotations each with +-T. Haralick's test (the depth in view 1 from
///     z1 (m_2 x R m_1) + m_2 x T = 0 must be positive, summed over the points) is applied together
///     with its counterpart for view 2 ((R m_1 x m_2) z2 = R m_1 x T): the chosen candidate
///     places the most points in front of both cameras; ties go to the larger of Haralick's sums.
///
/// Degeneracies (the "surface assumption" of Sec. 4.2): with T = 0 (pure rotation) or when the
/// points lie on a critical surface (e.g. a plane), the motion equation has more than one
/// independent solution; the status is then kDegenerate.

#include <Eigen/Core>
#include <string>

namespace vantage {

/// Outcome of two_view_pose().
enum class TwoViewStatus {
  kOk,  ///< unique E (sigma_8 > degenerate_tolerance * sigma_1) and a majority of points in front
  /// sigma_8 <= degenerate_tolerance * sigma_1 of the 9-column motion-equation matrix: E is not
  /// unique (pure rotation, T = 0, or points on a critical surface such as a plane); R and T are
  /// those of one solution
  kDegenerate,
  /// no candidate places more than half of the points in front of both cameras (gross noise or
  /// mismatched correspondences); R and T are the best candidate's
  kNoPointsInFront,
};

/// "ok", "degenerate" or "no_points_in_front".
const char* to_string(TwoViewStatus status);

/// Options of two_view_pose().
struct TwoViewOptions {
  /// Focal length in image units per unit of normalised coordinate; > 0 and finite.
  double focal_length = 1.0;
  /// Relative threshold on sigma_8 / sigma_1 of the motion-equation matrix below which the
  /// status is kDegenerate. Dimensionless, in [0, 1).
  double degenerate_tolerance = 1e-10;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Relative pose of two views.
struct TwoViewResult {
  Eigen::Matrix3d R_camera2_camera1 = Eigen::Matrix3d::Identity();
  /// Direction of the translation of x_camera2 = R x_camera1 + T: unit length (the scale is not
  /// observable from two views).
  Eigen::Vector3d t_camera2_camera1 = Eigen::Vector3d::UnitZ();
  /// E = hat(T) R after rank-2 enforcement, ||E||_F = sqrt(2); sign matches (R, T).
  Eigen::Matrix3d essential = Eigen::Matrix3d::Zero();
  /// sqrt(mean_i (m_2i^T E m_1i)^2) with the returned E: the algebraic epipolar residual, in
  /// normalised coordinates (radians for small angles).
  double residual = 0.0;
  /// sigma_9 / sigma_8 of the motion-equation matrix: 0 for exact data, near 1 when E is poorly
  /// determined.
  double null_space_ratio = 0.0;
  int points_in_front = 0;  ///< points with positive depth in both views for the chosen (R, T)
  TwoViewStatus status = TwoViewStatus::kOk;
  std::string message;  ///< empty when status is kOk
};

/// Haralick's linear two-view algorithm (see the file comment). image1, image2: 2 x n
/// corresponding image points, n >= 8, finite. Throws InvalidArgument on mismatched sizes,
/// n < 8, non-finite data or bad options.
TwoViewResult two_view_pose(const Eigen::Matrix2Xd& image1, const Eigen::Matrix2Xd& image2,
                            const TwoViewOptions& options = {});

}  // namespace vantage
