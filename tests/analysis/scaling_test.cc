#include "vantage/analysis/scaling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/eigen_testing.h"

namespace vantage {
namespace {

TEST(Scaling, PowerOfTwoScalingIsExactAndLandsInHalfToOne) {
  std::mt19937 rng(testing::kSeed);
  for (const double unit : {1e-300, 1e-200, 1.0, 3.0, 1e200, 1e307}) {
    const Eigen::Matrix3Xd x = testing::random_points(rng, 6, 1.0) * unit;
    const int e = binary_exponent(x);
    const Eigen::Matrix3Xd y = scaled_by_power_of_two(x, e);
    const double largest = y.cwiseAbs().maxCoeff();
    EXPECT_GE(largest, 0.5) << unit;
    EXPECT_LT(largest, 1.0) << unit;
    // Exact: scaling back gives the input bit for bit (no rounding anywhere).
    EXPECT_EQ(scaled_by_power_of_two(y, -e), x) << unit;
  }
  // A coordinate at 1e308 needs 2^-1024, a subnormal factor: done in two steps, still exact.
  Eigen::Matrix3Xd big = Eigen::Matrix3Xd::Zero(3, 2);
  big(0, 0) = 1e308;
  big(1, 1) = 1.0;
  const int e = binary_exponent(big);
  EXPECT_EQ(e, 1024);
  EXPECT_EQ(scaled_by_power_of_two(scaled_by_power_of_two(big, e), -e), big);
  EXPECT_EQ(binary_exponent(Eigen::Matrix3Xd::Zero(3, 2)), 0);
}

}  // namespace
}  // namespace vantage
