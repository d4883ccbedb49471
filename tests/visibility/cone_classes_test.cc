// Which cones' hidden sides never meet (docs/math.md §20, "Units"), for normals that are unit
// only to the problem's tolerance.

#include "vantage/visibility/internal/cone_classes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::visibility::internal {
namespace {

// The normals' tolerance in VisibilityProblem::validate: |n| within 1e-9 of 1.
constexpr double kShortNormal = 1.0 - 0.9e-9;

// Marker 0's normal is x, 0.9e-9 short, with a 60-degree cone; marker 1's is at b from x in the
// xy plane with a cone of 120 degrees + e. Their hidden sides {a : n.a < c} meet iff
// acos(c0 / |n0|) + acos(c1) < 2 pi - b: with |n0| taken as 1 the gap is about 2e-10 rad the
// other way. A direction in both is built in the plane and checked as the visibility test checks
// it (n.a < c with n as given): the classes must not be called apart.
TEST(ConeClasses, AShortNormalsConeIsItsTrueCone) {
  const double e = 4e-10;
  const double b = kPi - e / 2.0;
  Eigen::Matrix3Xd normals(3, 2);
  normals.col(0) = kShortNormal * Eigen::Vector3d::UnitX();
  normals.col(1) = Eigen::Vector3d(std::cos(b), std::sin(b), 0.0);
  Eigen::VectorXd cos_cone(2);
  cos_cone << std::cos(kPi / 3.0), std::cos(2.0 * kPi / 3.0 + e);

  const double t0 = std::acos(cos_cone(0) / kShortNormal);
  const double t1 = std::acos(cos_cone(1));
  ASSERT_LT(t0 + t1, 2.0 * kPi - b);                     // the hidden sides overlap
  const double psi = (t0 + (2.0 * kPi - b - t1)) / 2.0;  // below x, away from both normals
  const Eigen::Vector3d a(std::cos(psi), -std::sin(psi), 0.0);
  ASSERT_LT(normals.col(0).dot(a), cos_cone(0));
  ASSERT_LT(normals.col(1).dot(a), cos_cone(1));

  const ConeClasses classes(normals, cos_cone);
  EXPECT_FALSE(classes.hidden_apart(classes.of(0), classes.of(1)));
  EXPECT_FALSE(classes.hidden_apart(classes.of(1), classes.of(0)));
}

// Exactly opposite 90-degree cones share one edge and no direction hides both (the capsule's
// case of the TRE search).
TEST(ConeClasses, OppositeRightConesAreApart) {
  Eigen::Matrix3Xd normals(3, 2);
  normals.col(0) = Eigen::Vector3d::UnitY();
  normals.col(1) = -Eigen::Vector3d::UnitY();
  const ConeClasses classes(normals, Eigen::VectorXd::Zero(2));
  EXPECT_TRUE(classes.hidden_apart(classes.of(0), classes.of(1)));
}

}  // namespace
}  // namespace vantage::visibility::internal
