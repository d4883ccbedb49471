#pragma once

// Private to vantage::tracker: the RMS residual of the best rigid fit of one point set onto
// another (docs/math.md §24), by a rotation or by an improper orthogonal transform.

#include <Eigen/Core>

namespace vantage::internal {

/// sqrt((1/n) min_{Q, t} sum_i |Q x_i + t - y_i|^2) over Q in SO(3) (improper = false) or over
/// the orthogonal Q with det Q = -1 (improper = true), for x, y of n >= 1 columns each. §3's
/// rotation of the centred sets (the improper Q as R M with M = diag(-1, 1, 1)); the residual is
/// summed directly, so a perfect fit returns rounding, not the difference of two sums.
double orthogonal_fit_rms(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y, bool improper);

/// sqrt((1/n) sum_i |x_i - mean(x)|^2): the RMS radius of the set about its centroid.
double rms_radius(const Eigen::Matrix3Xd& x);

}  // namespace vantage::internal
