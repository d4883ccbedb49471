// The normals as the layout readers keep them (analysis/marker_visibility.h): unit length at
// any scale a file can hold, kept bit for bit when already unit, zero for what has no direction.

#include "vantage/analysis/marker_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vantage {
namespace {

// One rounding of a division by a correctly rounded norm: a few ulps of 1.
constexpr double kUnitRounding = 4.0 * std::numeric_limits<double>::epsilon();

TEST(UnitNormal, IsUnitAtEveryScaleAFileCanHold) {
  for (double scale : {1e300, 1e150, 3.0, 1e-150, 1e-300}) {
    SCOPED_TRACE(scale);
    const Eigen::Vector3d n = unit_normal(Eigen::Vector3d(scale, -2.0 * scale, 2.0 * scale));
    EXPECT_NEAR(n.x(), 1.0 / 3.0, kUnitRounding);
    EXPECT_NEAR(n.y(), -2.0 / 3.0, kUnitRounding);
    EXPECT_NEAR(n.z(), 2.0 / 3.0, kUnitRounding);
  }
}

TEST(UnitNormal, KeepsAUnitVectorBitForBit) {
  const Eigen::Vector3d v = Eigen::Vector3d(0.3, -0.4, 0.5).normalized();
  EXPECT_EQ(unit_normal(v), v);
}

TEST(UnitNormal, HasNoDirectionForZeroOrNonFinite) {
  EXPECT_EQ(unit_normal(Eigen::Vector3d::Zero()), Eigen::Vector3d::Zero());
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(unit_normal(Eigen::Vector3d(inf, 0.0, 0.0)), Eigen::Vector3d::Zero());
  EXPECT_EQ(unit_normal(Eigen::Vector3d(std::nan(""), 1.0, 0.0)), Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace vantage
