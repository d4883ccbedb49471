#pragma once

/// Exact rescaling of data by powers of two, so that sums of squares neither over- nor underflow
/// whatever the data's units (a point at 1e308, data in units of 1e-200), while every relative
/// quantity (directions, ratios, angles) stays bit-for-bit the same.

#include <Eigen/Core>

namespace vantage {

/// e with max |x_ij| * 2^-e in [0.5, 1); 0 when x is all zero or not finite.
int binary_exponent(const Eigen::Matrix3Xd& x);

/// x * 2^-e, in two exact steps (2^-e alone may be subnormal).
Eigen::Matrix3Xd scaled_by_power_of_two(const Eigen::Matrix3Xd& x, int e);

}  // namespace vantage
