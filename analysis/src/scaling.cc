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

}  // namespace vantage
