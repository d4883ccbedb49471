#include "vantage/analysis/scaling.h"

#include <cmath>

namespace vantage {

int binary_exponent(const Eigen::Matrix3Xd& x) {
  if (x.size() == 0) return 0;
  const double largest = x.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
  int e = 0;
  std::frexp(largest, &e);
  return e;
}

Eigen::Matrix3Xd scaled_by_power_of_two(const Eigen::Matrix3Xd& x, int e) {
  return (x * std::ldexp(1.0, -e / 2)) * std::ldexp(1.0, -(e - e / 2));
}

Eigen::Vector3d unit_direction(const Eigen::Vector3d& z) {
  const double largest = z.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !z.allFinite()) return Eigen::Vector3d::Zero();
  int e = 0;
  std::frexp(largest, &e);
  // One ldexp per component: the result's largest component is in [0.5, 1), so a component can
  // lose bits (become subnormal) only when it is below 2^-1022 of the largest: negligible.
  const Eigen::Vector3d y(std::ldexp(z.x(), -e), std::ldexp(z.y(), -e), std::ldexp(z.z(), -e));
  return y / y.norm();
}

Eigen::Matrix3Xd unit_directions(const Eigen::Matrix3Xd& vectors) {
  Eigen::Matrix3Xd n(3, vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) n.col(i) = unit_direction(vectors.col(i));
  return n;
}

}  // namespace vantage
