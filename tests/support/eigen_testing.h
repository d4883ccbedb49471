#pragma once

/// Eigen-aware GoogleTest helpers shared by every suite: EXPECT_EIGEN_NEAR, IsRotation(),
/// IsNearQuaternion() (accepts q and -q), and seeded random geometry.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <sstream>

namespace vantage::testing {

/// Seed of every random test in the suite: results are reproducible run to run.
constexpr unsigned kSeed = 20061122;

template <typename A, typename B>
::testing::AssertionResult eigen_near(const char* a_expr, const char* b_expr, const char*,
                                      const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b,
                                      double tolerance) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    return ::testing::AssertionFailure() << a_expr << " and " << b_expr << " differ in size";
  }
  const double error = (a - b).template lpNorm<Eigen::Infinity>();
  if (error <= tolerance) return ::testing::AssertionSuccess();
  Eigen::IOFormat fmt(Eigen::FullPrecision, 0, ", ", ";\n", "[", "]");
  return ::testing::AssertionFailure()
         << a_expr << " and " << b_expr << " differ by " << error << " > " << tolerance << "\n"
         << a_expr << " =\n"
         << a.format(fmt) << "\n"
         << b_expr << " =\n"
         << b.format(fmt);
}

#define EXPECT_EIGEN_NEAR(a, b, tol) EXPECT_PRED_FORMAT3(::vantage::testing::eigen_near, a, b, tol)
#define ASSERT_EIGEN_NEAR(a, b, tol) ASSERT_PRED_FORMAT3(::vantage::testing::eigen_near, a, b, tol)

/// R^T R = I and det R = +1 within tolerance.
MATCHER_P(IsRotationWithin, tolerance, "is a rotation matrix") {
  const Eigen::Matrix3d R = arg;
  const double orthogonality = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  const double det = R.determinant();
  *result_listener << "|R^T R - I| = " << orthogonality << ", det = " << det;
  return R.allFinite() && orthogonality <= tolerance && std::abs(det - 1.0) <= tolerance;
}
inline auto IsRotation() { return IsRotationWithin(1e-12); }

/// Quaternion equality up to sign ([e; eps4] and -[e; eps4] are the same rotation).
MATCHER_P2(IsNearQuaternion, expected, tolerance, "is the same unit quaternion up to sign") {
  const Eigen::Vector4d q = arg;
  const Eigen::Vector4d e = expected;
  const double error = std::min((q - e).norm(), (q + e).norm());
  *result_listener << "distance up to sign = " << error;
  return error <= tolerance;
}

/// Uniformly random rotation (from a normalised Gaussian quaternion).
inline Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

/// Uniformly random unit vector.
inline Eigen::Vector3d random_unit_vector(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector3d v(normal(rng), normal(rng), normal(rng));
  return v.normalized();
}

/// 3 x n matrix of entries uniform in [-scale, scale].
inline Eigen::Matrix3Xd random_points(std::mt19937& rng, int n, double scale = 1.0) {
  std::uniform_real_distribution<double> uniform(-scale, scale);
  Eigen::Matrix3Xd points(3, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < 3; ++i) points(i, j) = uniform(rng);
  return points;
}

}  // namespace vantage::testing
