#include "vantage/analysis/haralick_2d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "support/eigen_testing.h"
#include "support/message_of.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::kSeed;
using testing::message_of;

// Noise-free recovery: rounding of O(n) sums of unit-size coordinates.
constexpr double kNoiseFreeRadians = 1e-12;
constexpr double kNoiseFreeTranslation = 1e-11;
constexpr double kNoiseFreeResidual = 1e-20;
// The closed form is the exact minimiser, so no scanned angle may beat it beyond rounding.
constexpr double kResidualRounding = 1e-12;

// A zero weight, or all weights scaled, leaves the same least-squares problem: the angle agrees to
// the rounding of a few weighted sums.
constexpr double kSameProblemRadians = 1e-14;
// ... and the translation (unit-size coordinates) to the rounding of the rotated centroid.
constexpr double kSameProblemTranslation = 1e-13;
// ... and the residual to the rounding of its weighted sum.
constexpr double kSameProblemResidual = 1e-14;
// The residual with every weight scaled by 7 is 7 times the residual: rounding of the larger sum.
constexpr double kScaledResidual = 1e-12;
// The translation maps the centroid onto the centroid: rounding of unit-size coordinates.
constexpr double kCentroidRounding = 1e-12;

/// Signed difference a - b wrapped into [-pi, pi].
double angle_difference(double a, double b) { return std::remainder(a - b, 2.0 * kPi); }

Eigen::Matrix2d rotation_2d(double theta) {
  Eigen::Matrix2d R;
  R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return R;
}

Eigen::Matrix2Xd random_points_2d(std::mt19937& rng, int n, double half_width) {
  std::uniform_real_distribution<double> uniform(-half_width, half_width);
  Eigen::Matrix2Xd points(2, n);
  for (int j = 0; j < n; ++j) points.col(j) = Eigen::Vector2d(uniform(rng), uniform(rng));
  return points;
}

/// eps^2 of Sec. 2.1 at angle theta with the optimal translation y_bar - R x_bar.
double objective(const Eigen::Matrix2Xd& from, const Eigen::Matrix2Xd& to, const Eigen::VectorXd& w,
                 double theta) {
  const Eigen::Vector2d from_bar = (from * w).eval() / w.sum();
  const Eigen::Vector2d to_bar = (to * w).eval() / w.sum();
  const Eigen::Matrix2d R = rotation_2d(theta);
  const Eigen::Vector2d t = to_bar - R * from_bar;
  double sum = 0.0;
  for (int i = 0; i < from.cols(); ++i)
    sum += w(i) * (to.col(i) - R * from.col(i) - t).squaredNorm();
  return sum;
}

TEST(Pose2d, NoiseFreeDataReturnTheTruth) {
  // The setting of Sec. 2.3 without noise: points in [-2, 2]^2, translations in [-1, 1]^2, but
  // angles over the whole circle.
  std::mt19937 rng(kSeed + 40);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::uniform_real_distribution<double> positive(0.1, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 2 + trial % 11;
    const double theta = angle(rng);
    const Eigen::Vector2d t = random_points_2d(rng, 1, 1.0).col(0);
    const Eigen::Matrix2Xd from = random_points_2d(rng, n, 2.0);
    const Eigen::Matrix2Xd to = (rotation_2d(theta) * from).colwise() + t;
    Eigen::VectorXd w(n);
    for (int i = 0; i < n; ++i) w(i) = positive(rng);
    const Pose2dResult result = pose_2d(from, to, w);
    EXPECT_EQ(result.status, Pose2dStatus::kOk) << result.message;
    EXPECT_LT(std::abs(angle_difference(result.theta, theta)), kNoiseFreeRadians);
    EXPECT_EIGEN_NEAR(result.R_to_from, rotation_2d(theta), kNoiseFreeRadians);
    EXPECT_EIGEN_NEAR(result.t_to_from, t, kNoiseFreeTranslation);
    EXPECT_LT(result.residual, kNoiseFreeResidual * n);
    EXPECT_GT(result.rejected_residual, result.residual);
  }
}

class AngleRange : public ::testing::TestWithParam<double> {};

TEST_P(AngleRange, EveryAngleIncludingTheHalfTurnIsRecovered) {
  const double theta = GetParam();
  std::mt19937 rng(kSeed + 41);
  const Eigen::Matrix2Xd from = random_points_2d(rng, 5, 2.0);
  const Eigen::Vector2d t(0.3, -0.7);
  const Eigen::Matrix2Xd to = (rotation_2d(theta) * from).colwise() + t;
  const Pose2dResult result = pose_2d(from, to);
  EXPECT_EQ(result.status, Pose2dStatus::kOk);
  EXPECT_GT(result.theta, -kPi);  // range (-pi, pi]
  EXPECT_LE(result.theta, kPi);
  EXPECT_LT(std::abs(angle_difference(result.theta, theta)), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.R_to_from, rotation_2d(theta), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.t_to_from, t, kNoiseFreeTranslation);
}

INSTANTIATE_TEST_SUITE_P(Pose2d, AngleRange,
                         ::testing::Values(0.0, 1e-9, -1e-9, kPi / 2, -kPi / 2, 3.0, -3.0,
                                           kPi - 1e-9, -kPi + 1e-9, kPi, -kPi));

TEST(Pose2d, HalfTurnIsReportedAsPlusPi) {
  const Eigen::Matrix2Xd from = Eigen::Matrix2Xd::Identity(2, 2);
  const Pose2dResult result = pose_2d(from, -from);
  EXPECT_EQ(result.status, Pose2dStatus::kOk);
  EXPECT_DOUBLE_EQ(result.theta, kPi);
}

TEST(Pose2d, AgreesWithABruteForceAngleScanOnNoisyData) {
  // The closed form must be the global minimum of eps^2(theta) and the rejected candidate its
  // maximum: compare with a dense scan of the whole circle.
  std::mt19937 rng(kSeed + 42);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  constexpr int kSteps = 20000;
  constexpr double kStep = 2.0 * kPi / kSteps;
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 3 + trial;
    const Eigen::Matrix2Xd from = random_points_2d(rng, n, 2.0);
    Eigen::Matrix2Xd to = (rotation_2d(angle(rng)) * from).colwise() + Eigen::Vector2d(0.5, 0.2);
    for (int j = 0; j < n; ++j) to.col(j) += Eigen::Vector2d(noise(rng), noise(rng));
    const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 0.5, 1.5);
    const Pose2dResult result = pose_2d(from, to, w);
    ASSERT_EQ(result.status, Pose2dStatus::kOk);
    double best = std::numeric_limits<double>::infinity(), best_theta = 0.0;
    double worst = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < kSteps; ++k) {
      const double theta = -kPi + k * kStep;
      const double value = objective(from, to, w, theta);
      if (value < best) {
        best = value;
        best_theta = theta;
      }
      worst = std::max(worst, value);
    }
    EXPECT_NEAR(result.residual, objective(from, to, w, result.theta), kResidualRounding);
    EXPECT_LE(result.residual, best + kResidualRounding);
    EXPECT_GE(result.rejected_residual, worst - kResidualRounding);
    EXPECT_LE(std::abs(angle_difference(result.theta, best_theta)), kStep);
  }
}

TEST(Pose2d, ZeroWeightIgnoresAPointAndScaledWeightsChangeNothing) {
  std::mt19937 rng(kSeed + 43);
  std::normal_distribution<double> noise(0.0, 0.05);
  const Eigen::Matrix2Xd from = random_points_2d(rng, 6, 2.0);
  Eigen::Matrix2Xd to = (rotation_2d(1.0) * from).colwise() + Eigen::Vector2d(1.0, -1.0);
  for (int j = 0; j < 6; ++j) to.col(j) += Eigen::Vector2d(noise(rng), noise(rng));
  to.col(5) += Eigen::Vector2d(10.0, -4.0);  // an outlier, removed by its zero weight

  Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(6, 1.0, 2.0);
  w(5) = 0.0;
  const Pose2dResult weighted = pose_2d(from, to, w);
  const Pose2dResult dropped = pose_2d(from.leftCols(5), to.leftCols(5), w.head(5));
  EXPECT_NEAR(weighted.theta, dropped.theta, kSameProblemRadians);
  EXPECT_EIGEN_NEAR(weighted.t_to_from, dropped.t_to_from, kSameProblemTranslation);
  EXPECT_NEAR(weighted.residual, dropped.residual, kSameProblemResidual);

  const Pose2dResult scaled = pose_2d(from, to, 7.0 * w);
  EXPECT_NEAR(scaled.theta, weighted.theta, kSameProblemRadians);
  EXPECT_EIGEN_NEAR(scaled.t_to_from, weighted.t_to_from, kSameProblemTranslation);
  EXPECT_NEAR(scaled.residual, 7.0 * weighted.residual, kScaledResidual);
}

TEST(Pose2d, CoincidentPointsAreDegenerate) {
  Eigen::Matrix2Xd from(2, 3);
  from << 1, 1, 1, 2, 2, 2;
  const Eigen::Matrix2Xd to = (rotation_2d(0.4) * from).colwise() + Eigen::Vector2d(3, 4);
  const Pose2dResult result = pose_2d(from, to);
  EXPECT_EQ(result.status, Pose2dStatus::kDegenerate);
  EXPECT_FALSE(result.message.empty());
  // Whatever the angle, the translation maps the centroid onto the centroid.
  EXPECT_EIGEN_NEAR(result.R_to_from * from.col(0) + result.t_to_from, to.col(0),
                    kCentroidRounding);

  const Pose2dResult single = pose_2d(from.leftCols(1), to.leftCols(1));
  EXPECT_EQ(single.status, Pose2dStatus::kDegenerate);
  EXPECT_EQ(single.theta, 0.0);
  EXPECT_EIGEN_NEAR(single.t_to_from, to.col(0) - from.col(0), kCentroidRounding);
}

TEST(Pose2d, BadInputThrowsNamingTheArgument) {
  const Eigen::Matrix2Xd p = Eigen::Matrix2Xd::Random(2, 4);
  using ::testing::HasSubstr;
  EXPECT_THAT(message_of([&] { pose_2d(p, Eigen::Matrix2Xd::Random(2, 3)); }),
              HasSubstr("columns"));
  EXPECT_THAT(message_of([&] { pose_2d(Eigen::Matrix2Xd(2, 0), Eigen::Matrix2Xd(2, 0)); }),
              HasSubstr("need at least 1 correspondence"));
  EXPECT_THAT(message_of([&] { pose_2d(p, p, Eigen::VectorXd::Ones(3)); }), HasSubstr("weights"));
  Eigen::VectorXd negative = Eigen::VectorXd::Ones(4);
  negative(2) = -1.0;
  EXPECT_THAT(message_of([&] { pose_2d(p, p, negative); }), HasSubstr("weights[2]"));
  EXPECT_THAT(message_of([&] { pose_2d(p, p, Eigen::VectorXd::Zero(4)); }),
              HasSubstr("weights: all zero"));
  Eigen::Matrix2Xd nan = p;
  nan(1, 3) = std::nan("");
  EXPECT_THAT(message_of([&] { pose_2d(nan, p); }), HasSubstr("from[3]"));
  EXPECT_THAT(message_of([&] { pose_2d(p, nan); }), HasSubstr("to[3]"));
  Pose2dOptions bad;
  bad.degenerate_tolerance = 1.5;
  EXPECT_THAT(message_of([&] { pose_2d(p, p, {}, bad); }), HasSubstr("degenerate_tolerance"));
}

}  // namespace
}  // namespace vantage
