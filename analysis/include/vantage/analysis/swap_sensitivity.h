#pragma once

/// Prop. 2 (swap sensitivity): how far the Theorem 1 rotation moves when two measured vectors are
/// matched to each other's data vectors.

#include <Eigen/Core>
#include <vector>

namespace vantage {

/// The rotation error caused by swapping the measurements of data vectors i and j.
struct SwapError {
  int i = 0;               ///< column of the first data vector (i < j)
  int j = 0;               ///< column of the second data vector
  double error_deg = 0.0;  ///< geodesic angle between the swapped and the true rotation
  /// The swapped D has a repeated top eigenvalue (relative gap <= kSwapAmbiguousGap), so the
  /// swapped optimum is not unique; its optima then include a half turn and error_deg is the
  /// worst case, 180 degrees.
  bool ambiguous = false;
};

/// Relative eigen gap (lambda_1 - lambda_2) / ||D||_F of the swapped D at or below which a swap is
/// reported as ambiguous.
constexpr double kSwapAmbiguousGap = 1e-9;

/// For every pair (i, j), i < j, of data vectors z (3 x m, m >= 2, finite), the rotation error
/// in degrees of Theorem 1 when v_i and v_j are swapped: D = sum w_k K(v_k, z_k) (Eq. 2) of the
/// noise-free measurements v_k = z_k plus Delta D of Eq. (10) (swap_delta_d), top eigenvector,
/// Eq. (5). With noise-free 3-D data v_k = R z_k, the swapped optimum is R Q with Q the swapped
/// optimum for R = I, so the error does not depend on the true rotation (nor on the scale):
/// R = I is used. Noise-free, R = I stays a stationary point of the swapped problem (the last
/// column of the swapped D vanishes), so a swap either leaves the rotation exactly unchanged or
/// moves it to another optimum: errors are 0 or large, and ambiguous swaps are flagged. Returns the
/// worst `count` pairs (count >= 1; all pairs when fewer), sorted by decreasing error, ties by (i,
/// j). weights: m positive entries or empty (all 1). Throws InvalidArgument on bad sizes,
/// non-finite data, bad weights or count < 1.
std::vector<SwapError> swap_sensitivity(const Eigen::Matrix3Xd& z,
                                        const Eigen::VectorXd& weights = {}, int count = 5);

}  // namespace vantage
