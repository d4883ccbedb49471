#include "vantage/analysis/quaternion.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <functional>
#include <limits>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::IsNearQuaternion;
using testing::IsRotation;
using testing::kSeed;

// Eigen-solver agreement: the fast path and Eigen's solver differ by rounding only.
constexpr double kEigenTolerance = 1e-10;
// A rotation through its quaternion and back: rounding of products of unit-size entries.
constexpr double kExact = 1e-14;

// K is built symmetric, and from a zero vector it is zero: no rounding at all.
constexpr double kIdentical = 0.0;
// K is linear in v: a combination with coefficients 2 and -3 of unit-size entries, rounded.
constexpr double kBilinearRounding = 1e-13;
// The fallback's eigen-equation residual: the eigensolver's accuracy on a unit-size matrix.
constexpr double kFallbackEigenvector = 1e-9;
// The top eigenvalues 2 and 2 + 1e-9 of Q diag Q^T, Q orthogonal: rounding of unit-size entries.
constexpr double kGapRounding = 1e-12;

TEST(QuaternionK, IsSymmetricAndBilinear) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d v1 = testing::random_points(rng, 1).col(0);
    const Eigen::Vector3d v2 = testing::random_points(rng, 1).col(0);
    const Eigen::Vector3d z = testing::random_points(rng, 1).col(0);
    const Eigen::Matrix4d K = quaternion_k(v1, z);
    EXPECT_EIGEN_NEAR(K, K.transpose(), kIdentical);
    EXPECT_EIGEN_NEAR(quaternion_k(2.0 * v1 - 3.0 * v2, z),
                      2.0 * quaternion_k(v1, z) - 3.0 * quaternion_k(v2, z), kBilinearRounding);
    EXPECT_EIGEN_NEAR(quaternion_k(v1, Eigen::Vector3d::Zero()), Eigen::Matrix4d::Zero(),
                      kIdentical);
  }
}

TEST(QuaternionK, QuadraticFormIsCorrelationShiftedByDotProduct) {
  // eps^T K(v, z) eps = v^T R(eps) z - v^T z for unit eps (docs/math.md §2).
  std::mt19937 rng(kSeed + 1);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d v = testing::random_points(rng, 1).col(0);
    const Eigen::Vector3d z = testing::random_points(rng, 1).col(0);
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Vector4d eps = quaternion_from_rotation(R);
    EXPECT_NEAR(eps.dot(quaternion_k(v, z) * eps), v.dot(R * z) - v.dot(z), kBilinearRounding);
  }
}

TEST(RotationFromQuaternion, MatchesEigenAndIsRotation) {
  std::mt19937 rng(kSeed + 2);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Vector4d eps = quaternion_from_rotation(R);
    EXPECT_GE(eps(3), 0.0);
    EXPECT_NEAR(eps.norm(), 1.0, kExact);
    EXPECT_THAT(rotation_from_quaternion(eps), IsRotation());
    EXPECT_EIGEN_NEAR(rotation_from_quaternion(eps), R, kExact);
    EXPECT_EIGEN_NEAR(rotation_from_quaternion(-eps), R, kExact);
  }
}

TEST(RotationFromQuaternion, AxisAngleConvention) {
  // 90 degrees about z maps x to y (active rotation).
  const double s = std::sqrt(0.5);
  const Eigen::Matrix3d R = rotation_from_quaternion(Eigen::Vector4d(0, 0, s, s));
  EXPECT_EIGEN_NEAR(R * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), kExact);
}

TEST(RotationFromQuaternion, HalfTurnRoundTrips) {
  const Eigen::Vector3d axes[] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                  Eigen::Vector3d(1, 1, 1).normalized()};
  for (const Eigen::Vector3d& axis : axes) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(kPi, axis).toRotationMatrix();
    EXPECT_EIGEN_NEAR(rotation_from_quaternion(quaternion_from_rotation(R)), R, kExact);
  }
}

Eigen::Matrix4d random_symmetric(std::mt19937& rng) {
  Eigen::Matrix4d A;
  std::normal_distribution<double> normal;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) A(i, j) = normal(rng);
  return A + A.transpose();
}

TEST(TopEigenpair, FastPathAgreesWithFullSolver) {
  std::mt19937 rng(kSeed + 3);
  int fast = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix4d D = random_symmetric(rng);
    const TopEigenpair got = top_eigenpair(D);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> reference(D);
    EXPECT_NEAR(got.lambda, reference.eigenvalues()(3), kEigenTolerance);
    EXPECT_NEAR(got.gap, reference.eigenvalues()(3) - reference.eigenvalues()(2), kEigenTolerance);
    EXPECT_THAT(got.vector, IsNearQuaternion(reference.eigenvectors().col(3), 1e-9));
    EXPECT_EIGEN_NEAR(D * got.vector, got.lambda * got.vector, kFallbackEigenvector);
    fast += got.used_fallback ? 0 : 1;
  }
  EXPECT_GT(fast, 190);  // random matrices almost never have a near-double top eigenvalue
}

TEST(TopEigenpair, FallsBackWhenTopEigenvaluesNearlyCoincide) {
  std::mt19937 rng(kSeed + 4);
  const Eigen::Matrix4d Q =
      Eigen::HouseholderQR<Eigen::Matrix4d>(random_symmetric(rng)).householderQ();
  const Eigen::Vector4d eigenvalues(-1.0, 0.5, 2.0, 2.0 + 1e-9);
  const Eigen::Matrix4d D = Q * eigenvalues.asDiagonal() * Q.transpose();
  const TopEigenpair got = top_eigenpair(D);
  EXPECT_TRUE(got.used_fallback);
  EXPECT_NEAR(got.gap, 1e-9, kGapRounding);
  EXPECT_NEAR(got.lambda, 2.0 + 1e-9, kGapRounding);
}

TEST(TopEigenpair, HandlesMultiplesOfIdentityAndZero) {
  for (const double c : {0.0, 3.0}) {
    const TopEigenpair got = top_eigenpair(c * Eigen::Matrix4d::Identity());
    EXPECT_NEAR(got.lambda, c, kExact);
    EXPECT_EQ(got.gap, 0.0);
    EXPECT_NEAR(got.vector.norm(), 1.0, kExact);
  }
}

TEST(TopEigenpair, ForcedFullSolverMatchesFastPath) {
  std::mt19937 rng(kSeed + 5);
  const Eigen::Matrix4d D = random_symmetric(rng);
  TopEigenOptions full;
  full.force_full_solver = true;
  EXPECT_THAT(top_eigenpair(D, full).vector, IsNearQuaternion(top_eigenpair(D).vector, 1e-9));
}

TEST(LargestTwoQuarticRoots, AnyHintGivesTheTopTwoRoots) {
  // Roots 3, 1, -1.5, -2.5 (sum 0): the hint may be exact, loose, wrong (between roots, where
  // the quartic is positive too) or infinite; only a provable upper bound may be used as start.
  const double r[4] = {3.0, 1.0, -1.5, -2.5};
  double e2 = 0.0, e3 = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      e2 += r[i] * r[j];
      for (int k = j + 1; k < 4; ++k) e3 += r[i] * r[j] * r[k];
    }
  const double e4 = r[0] * r[1] * r[2] * r[3];
  for (const double hint : {3.0, 3.5, 0.0, -2.0, 2.0, std::numeric_limits<double>::infinity()}) {
    const Eigen::Vector2d roots = internal::largest_two_quartic_roots(e2, -e3, e4, hint);
    EXPECT_NEAR(roots(0), 3.0, kEigenTolerance) << "hint " << hint;
    EXPECT_NEAR(roots(1), 1.0, kEigenTolerance) << "hint " << hint;
  }
}

TEST(LargestTwoQuarticRoots, MatchKnownRootsOfRandomQuartics) {
  // lambda_2 comes from the resolvent cubic, whose largest root is (r1 + r2)^2: any signs of the
  // roots, hints from exact to the Laguerre-Samuelson fallback. A root r moves by about
  // eps (r^4 + |e2| r^2 + |e3| |r| + |e4|) / |p'(r)| when the coefficients are rounded (its
  // condition), so each root must be within kConditionUlps of that plus the root scale; the
  // roots are kept kSeparation apart so that the condition stays moderate.
  constexpr double kSeparation = 1e-3;
  constexpr double kConditionUlps = 100.0;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  std::mt19937 rng(kSeed + 6);
  std::normal_distribution<double> normal;
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    double r[4];
    for (double& root : r) root = normal(rng);
    const double mean = (r[0] + r[1] + r[2] + r[3]) / 4.0;
    for (double& root : r) root -= mean;
    std::sort(r, r + 4, std::greater<double>());
    const double scale = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    if (r[0] - r[1] < kSeparation * scale || r[1] - r[2] < kSeparation * scale) continue;
    double e2 = 0.0, e3 = 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        e2 += r[i] * r[j];
        for (int k = j + 1; k < 4; ++k) e3 += r[i] * r[j] * r[k];
      }
    const double e4 = r[0] * r[1] * r[2] * r[3];
    auto tolerance = [&](int k) {
      const double x = r[k];
      double derivative = 1.0;  // p'(r_k) = prod_{j != k} (r_k - r_j)
      for (int j = 0; j < 4; ++j)
        if (j != k) derivative *= x - r[j];
      const double condition =
          (x * x * x * x + std::abs(e2) * x * x + std::abs(e3 * x) + std::abs(e4)) /
          std::abs(derivative);
      return kConditionUlps * kEps * (scale + condition);
    };
    const double hint = trial % 2 == 0 ? r[0] : std::numeric_limits<double>::infinity();
    const Eigen::Vector2d roots = internal::largest_two_quartic_roots(e2, -e3, e4, hint);
    EXPECT_NEAR(roots(0), r[0], tolerance(0)) << "trial " << trial;
    EXPECT_NEAR(roots(1), r[1], tolerance(1)) << "trial " << trial;
    ++checked;
  }
  EXPECT_GT(checked, 400);
}

}  // namespace
}  // namespace vantage
