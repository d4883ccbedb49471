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

/// The direction z / |z| of one vector, normalised by its own scale: z is first multiplied by
/// the power of two that brings its largest |component| into [0.5, 1) (exact), so that the sum
/// of squares neither over- nor underflows for any non-zero finite z (1e-300 or 1e300 long). A
/// common factor for several vectors cannot do that: beside a 1e80 vector, a 1e-80 one scaled
/// by the same power of two has a subnormal sum of squares and loses its direction's digits.
/// Returns the zero vector for z = 0 or a z with a non-finite component.
Eigen::Vector3d unit_direction(const Eigen::Vector3d& z);

/// unit_direction() of every column.
Eigen::Matrix3Xd unit_directions(const Eigen::Matrix3Xd& vectors);

}  // namespace vantage
