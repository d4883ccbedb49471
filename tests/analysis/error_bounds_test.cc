#include "vantage/analysis/error_bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::kSeed;

// Eq. (18) and the direct reconstruction are the same angle up to rounding of acos near 1
// (acos amplifies a 1e-16 cosine error to ~1e-8 rad at tiny angles).
constexpr double kAngle = 1e-7;

// The same fraction, scale or angle by two formulas of unit-size quantities: rounding.
constexpr double kRounding = 1e-12;
// An angle of 35 degrees from acos away from 1: rounding, in degrees.
constexpr double kDegreesRounding = 1e-9;

// Measured (true) vector v = R z / alpha and the reconstruction v_e from d = P v and alpha_e
// (Eqs. 21-22, same depth sign); returns the angle between them in radians.
double reconstructed_angle(const Eigen::Matrix3d& R, const Eigen::Vector3d& z, double alpha,
                           double alpha_e) {
  const Eigen::Vector3d v = R * z / alpha;
  const Eigen::Vector2d d = v.head<2>();
  const double depth =
      std::sqrt(std::max(0.0, z.squaredNorm() / (alpha_e * alpha_e) - d.squaredNorm()));
  const Eigen::Vector3d v_e(d.x(), d.y(), v.z() >= 0.0 ? depth : -depth);
  return std::acos(std::clamp(v.normalized().dot(v_e.normalized()), -1.0, 1.0));
}

Eigen::Matrix3d rotation_with_third_row(const Eigen::Vector3d& a) {
  Eigen::Vector3d x = a.unitOrthogonal();
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = a.cross(x).transpose();
  R.row(2) = a.transpose();
  return R;
}

TEST(ErrorBounds, Eq18MatchesReconstruction) {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Vector3d z = testing::random_points(rng, 1, 3.0).col(0);
    const double alpha = 0.2 + 2.0 * unit(rng);
    const Eigen::Vector2d d = (R * z / alpha).head<2>();
    const double p = alpha * d.norm() / z.norm();  // Eq. (19)
    const double beta = (0.3 + 0.7 * unit(rng)) / std::max(p, 1e-3);
    if (beta * p > 1.0) continue;
    EXPECT_NEAR(scale_error_angle(beta, p), reconstructed_angle(R, z, alpha, beta * alpha), kAngle)
        << "trial " << trial;
  }
}

TEST(ErrorBounds, Eq26AndEq30AtTheWorstViewpoint) {
  std::mt19937 rng(kSeed + 1);
  for (int trial = 0; trial < 50; ++trial) {
    const int m = 3 + trial % 6;
    const Eigen::Matrix3Xd z = testing::random_points(rng, m, 2.0);
    const Eigen::Vector3d a = testing::random_unit_vector(rng);
    const Eigen::Matrix3d R = rotation_with_third_row(a);
    const double alpha = 0.5 + 0.1 * trial;
    // LUB scale, Eq. (23), from the image: alpha_e = 1 / max ||d_i|| / ||z_i||.
    double ratio = 0.0;
    for (int i = 0; i < m; ++i) {
      ratio = std::max(ratio, (R * z.col(i) / alpha).head<2>().norm() / z.col(i).norm());
    }
    const double alpha_e = 1.0 / ratio;
    const Eigen::VectorXd p = projected_fractions(z, a);
    const double pbar = p.maxCoeff();
    EXPECT_NEAR(alpha_e / alpha, 1.0 / pbar, kRounding) << "Eq. (25): beta = 1 / p-bar";
    const Eigen::VectorXd errors = worst_case_errors_deg(z, a);
    for (int i = 0; i < m; ++i) {
      EXPECT_NEAR(p(i), alpha * (R * z.col(i) / alpha).head<2>().norm() / z.col(i).norm(),
                  kRounding)
          << "Eq. (19)";
      const double measured = reconstructed_angle(R, z.col(i), alpha, alpha_e);
      EXPECT_NEAR(lub_scale_error_angle(p(i), pbar), measured, kAngle);
      EXPECT_NEAR(errors(i), kDegreesPerRadian * measured, kDegreesPerRadian * kAngle);
    }
  }
}

TEST(ErrorBounds, PbarAtViewpointsIsTheLargestProjectedFraction) {
  std::mt19937_64 rng(kSeed);
  std::normal_distribution<double> normal;
  const Eigen::Matrix3Xd z = Eigen::Matrix3Xd::NullaryExpr(3, 7, [&] { return normal(rng); });
  Eigen::Matrix3Xd viewpoints = Eigen::Matrix3Xd::NullaryExpr(3, 50, [&] { return normal(rng); });
  viewpoints.colwise().normalize();
  const Eigen::VectorXd pbar = pbar_at_viewpoints(z, viewpoints);
  ASSERT_EQ(pbar.size(), 50);
  for (int k = 0; k < 50; ++k) {
    EXPECT_NEAR(pbar(k), projected_fractions(z, viewpoints.col(k)).maxCoeff(), kRounding);
  }
  // Z = I: p_bar is sqrt(2/3) at (1, 1, 1)/sqrt(3) and 1 along a coordinate axis.
  const Eigen::Matrix3Xd a = (Eigen::Matrix3Xd(3, 2) << 1, 1, 1, 0, 1, 0).finished();
  Eigen::Matrix3Xd unit = a;
  unit.colwise().normalize();
  const Eigen::VectorXd identity_pbar = pbar_at_viewpoints(Eigen::Matrix3d::Identity(), unit);
  EXPECT_NEAR(identity_pbar(0), std::sqrt(2.0 / 3.0), kRounding);
  EXPECT_NEAR(identity_pbar(1), 1.0, kRounding);
  EXPECT_THROW(pbar_at_viewpoints(Eigen::Matrix3Xd(3, 0), unit), InvalidArgument);
  EXPECT_THROW(pbar_at_viewpoints(Eigen::Matrix3d::Identity(), a), InvalidArgument);
}

TEST(ErrorBounds, WorstErrorAtAViewpointIsArccosPbar) {
  // docs/math.md §11: Eq. (26) is arcsin(p / p_bar) - arcsin(p), increasing in p, so the largest
  // error over 0 <= p <= p_bar is arccos(p_bar), reached by the vector that sets p_bar.
  constexpr int kPbars = 20;
  constexpr int kSteps = 200;
  for (int b = 1; b <= kPbars; ++b) {
    const double pbar = static_cast<double>(b) / kPbars;
    double previous = -1.0;
    for (int k = 0; k <= kSteps; ++k) {
      const double p = pbar * k / kSteps;
      const double theta = lub_scale_error_angle(p, pbar);
      EXPECT_NEAR(theta, std::asin(p / pbar) - std::asin(p), kAngle)
          << "p " << p << " pbar " << pbar;
      EXPECT_GE(theta, previous - kAngle) << "not increasing at p " << p << " pbar " << pbar;
      EXPECT_LE(theta, std::acos(pbar) + kAngle);
      previous = theta;
    }
    EXPECT_NEAR(previous, std::acos(pbar), kAngle) << "p = p_bar reaches arccos(p_bar)";
  }
  // At any viewpoint the largest Eq. (26) error over the vectors is arccos p_bar(a).
  std::mt19937 rng(kSeed + 2);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 6, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d a = testing::random_unit_vector(rng);
    const double pbar = pbar_at_viewpoints(z, a).maxCoeff();
    EXPECT_NEAR(worst_case_errors_deg(z, a).maxCoeff(), kDegreesPerRadian * std::acos(pbar),
                kDegreesPerRadian * kAngle);
  }
}

TEST(ErrorBounds, KnownValuesAndEdges) {
  EXPECT_EQ(scale_error_angle(1.0, 0.7), 0.0) << "exact scale: no error";
  // beta p = 1 puts v_e in the image plane: the error is v's elevation, acos(p).
  EXPECT_NEAR(scale_error_angle(2.0, 0.5), std::acos(0.5), kRounding);
  EXPECT_EQ(lub_scale_error_angle(0.0, 0.0), 0.0) << "all vectors along the axis";
  EXPECT_NEAR(lub_scale_error_angle(0.5, 1.0), 0.0, kRounding) << "p-bar = 1: no error (Fig. 1)";
  // Z = I at (1, 1, 1)/sqrt(3): every p_i = p-bar = sqrt(2/3), error acos(p-bar).
  const Eigen::VectorXd e =
      worst_case_errors_deg(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Ones().normalized());
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(e(i), kDegreesPerRadian * std::acos(std::sqrt(2.0 / 3.0)), kDegreesRounding);
  EXPECT_THROW(scale_error_angle(2.0, 0.9), InvalidArgument);
  EXPECT_THROW(scale_error_angle(-1.0, 0.5), InvalidArgument);
  EXPECT_THROW(scale_error_angle(1.0, 1.5), InvalidArgument);
  EXPECT_THROW(lub_scale_error_angle(0.8, 0.5), InvalidArgument);
  EXPECT_THROW(projected_fractions(Eigen::Matrix3d::Zero(), Eigen::Vector3d::UnitZ()),
               InvalidArgument);
  EXPECT_THROW(projected_fractions(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 2)),
               InvalidArgument);
}

}  // namespace
}  // namespace vantage
