#include "vantage/analysis/two_view.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <random>

#include "support/eigen_testing.h"
#include "support/message_of.h"
#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::IsRotation;
using testing::IsRotationWithin;
using testing::kSeed;

// Noise-free recovery: E is a null vector of an n x 9 matrix with entries O(1) and a condition
// number of ~1e3-1e4 for these scenes, so rounding leaves errors ~1e-12.
constexpr double kNoiseFreeRadians = 1e-9;
constexpr double kNoiseFreeDirection = 1e-9;
constexpr double kNoiseFreeResidual = 1e-12;
// The cofactor formula returns a rotation only up to the rounding of E's SVD.
constexpr double kRotationRounding = 1e-10;
// Noise of 1e-4 in normalised coordinates (0.1 pixel at f = 1000) on 50 points: the linear
// algorithm's errors stay below a few milliradians (Haralick et al., Table 1: SNR above ~60 dB).
constexpr double kImageNoise = 1e-4;
constexpr double kNoisyRadians = 1e-2;
constexpr double kNoisyDirectionRadians = 5e-2;

// The translation direction and the essential matrix's singular values, constraint and product form
// are normalised unit-size quantities: rounding.
constexpr double kUnitRounding = 1e-12;
// Noise-free: the eight-point matrix's smallest singular value is rounding next to its second.
constexpr double kNoiseFreeNullSpace = 1e-9;

/// Two views of n random points: camera 1 sees them at depths 3-7 in a +-1.5 box; camera 2 is
/// displaced by a random T (length 0.5-1.5) and rotated by up to 0.6 rad. Points that would be
/// behind camera 2 are redrawn, so every point is in front of both cameras.
struct TwoViews {
  Eigen::Matrix2Xd image1;
  Eigen::Matrix2Xd image2;
  Eigen::Matrix3d R;
  Eigen::Vector3d T;
};

Eigen::Matrix3d random_small_rotation(std::mt19937& rng, double max_angle) {
  std::uniform_real_distribution<double> angle(0.0, max_angle);
  return Eigen::AngleAxisd(angle(rng), testing::random_unit_vector(rng)).toRotationMatrix();
}

TwoViews random_views(std::mt19937& rng, int n, double noise = 0.0, double focal = 1.0) {
  std::uniform_real_distribution<double> lateral(-1.5, 1.5);
  std::uniform_real_distribution<double> depth(3.0, 7.0);
  std::uniform_real_distribution<double> length(0.5, 1.5);
  std::normal_distribution<double> normal(0.0, noise);
  TwoViews v;
  v.R = random_small_rotation(rng, 0.6);
  v.T = length(rng) * testing::random_unit_vector(rng);
  v.image1.resize(2, n);
  v.image2.resize(2, n);
  for (int i = 0; i < n;) {
    const Eigen::Vector3d x1(lateral(rng), lateral(rng), depth(rng));
    const Eigen::Vector3d x2 = v.R * x1 + v.T;
    if (x2.z() < 1.0) continue;
    v.image1.col(i) = focal * x1.head<2>() / x1.z();
    v.image2.col(i) = focal * x2.head<2>() / x2.z();
    if (noise > 0.0) {
      v.image1.col(i) += focal * Eigen::Vector2d(normal(rng), normal(rng));
      v.image2.col(i) += focal * Eigen::Vector2d(normal(rng), normal(rng));
    }
    ++i;
  }
  return v;
}

double direction_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(TwoView, NoiseFreeViewsReturnTheMotion) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 8 + trial;  // n = 8..47
    const TwoViews v = random_views(rng, n);
    const TwoViewResult result = two_view_pose(v.image1, v.image2);
    ASSERT_EQ(result.status, TwoViewStatus::kOk) << "trial " << trial << ": " << result.message;
    EXPECT_THAT(result.R_camera2_camera1, IsRotationWithin(kRotationRounding));
    EXPECT_LT(rotation_angle_between(result.R_camera2_camera1, v.R), kNoiseFreeRadians)
        << "trial " << trial;
    EXPECT_NEAR(result.t_camera2_camera1.norm(), 1.0, kUnitRounding);
    EXPECT_EIGEN_NEAR(result.t_camera2_camera1, v.T.normalized(), kNoiseFreeDirection);
    EXPECT_EQ(result.points_in_front, n);
    EXPECT_LT(result.residual, kNoiseFreeResidual);
    EXPECT_LT(result.null_space_ratio, kNoiseFreeNullSpace);
    EXPECT_TRUE(result.message.empty());
  }
}

TEST(TwoView, LargeRotationsAndEverySignCase) {
  // Translations in every octant, including along and against the optical axis, and rotations up
  // to 1.5 rad: the sign choice has to pick the right one of four candidates each time.
  std::mt19937 rng(kSeed + 1);
  std::uniform_real_distribution<double> lateral(-1.0, 1.0);
  std::uniform_real_distribution<double> depth(4.0, 9.0);
  int solved = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Matrix3d R = random_small_rotation(rng, 1.5);
    const Eigen::Vector3d T = testing::random_unit_vector(rng);
    Eigen::Matrix2Xd image1(2, 20);
    Eigen::Matrix2Xd image2(2, 20);
    int i = 0;
    for (int attempt = 0; i < 20 && attempt < 10000; ++attempt) {
      const Eigen::Vector3d x1(lateral(rng), lateral(rng), depth(rng));
      const Eigen::Vector3d x2 = R * x1 + T;
      if (x2.z() < 0.5) continue;
      image1.col(i) = x1.head<2>() / x1.z();
      image2.col(i) = x2.head<2>() / x2.z();
      ++i;
    }
    if (i < 20) continue;  // camera 2 turned away from the cloud: not a two-view problem
    const TwoViewResult result = two_view_pose(image1, image2);
    ASSERT_EQ(result.status, TwoViewStatus::kOk) << "trial " << trial << ": " << result.message;
    EXPECT_LT(rotation_angle_between(result.R_camera2_camera1, R), kNoiseFreeRadians);
    EXPECT_EIGEN_NEAR(result.t_camera2_camera1, T, kNoiseFreeDirection);
    ++solved;
  }
  EXPECT_GE(solved, 30);
}

TEST(TwoView, EssentialMatrixIsRankTwoAndConsistent) {
  std::mt19937 rng(kSeed + 2);
  const TwoViews v = random_views(rng, 15, kImageNoise);
  const TwoViewResult result = two_view_pose(v.image1, v.image2);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(result.essential);
  EXPECT_EIGEN_NEAR(svd.singularValues(), Eigen::Vector3d(1.0, 1.0, 0.0), kUnitRounding);
  EXPECT_EIGEN_NEAR(result.essential, hat(result.t_camera2_camera1) * result.R_camera2_camera1,
                    kUnitRounding);
  EXPECT_EIGEN_NEAR(result.essential.transpose() * result.t_camera2_camera1,
                    Eigen::Vector3d::Zero(), kUnitRounding);
  EXPECT_THAT(result.R_camera2_camera1, IsRotationWithin(kRotationRounding));
}

TEST(TwoView, SwappingTheViewsInvertsTheMotion) {
  // x1 = R^T x2 - R^T T, so the reverse motion is (R^T, -R^T T / |T|).
  std::mt19937 rng(kSeed + 3);
  for (int trial = 0; trial < 10; ++trial) {
    const TwoViews v = random_views(rng, 12, kImageNoise);
    const TwoViewResult forward = two_view_pose(v.image1, v.image2);
    const TwoViewResult backward = two_view_pose(v.image2, v.image1);
    ASSERT_EQ(forward.status, TwoViewStatus::kOk);
    ASSERT_EQ(backward.status, TwoViewStatus::kOk);
    EXPECT_LT(
        rotation_angle_between(backward.R_camera2_camera1, forward.R_camera2_camera1.transpose()),
        kNoisyRadians);
    EXPECT_LT(direction_angle(backward.t_camera2_camera1,
                              -forward.R_camera2_camera1.transpose() * forward.t_camera2_camera1),
              kNoisyDirectionRadians);
  }
}

TEST(TwoView, NoisyViewsGiveSmallErrors) {
  std::mt19937 rng(kSeed + 4);
  for (int trial = 0; trial < 20; ++trial) {
    const TwoViews v = random_views(rng, 50, kImageNoise);
    const TwoViewResult result = two_view_pose(v.image1, v.image2);
    EXPECT_EQ(result.status, TwoViewStatus::kOk) << result.message;
    EXPECT_THAT(result.R_camera2_camera1, IsRotationWithin(kRotationRounding));
    EXPECT_LT(rotation_angle_between(result.R_camera2_camera1, v.R), kNoisyRadians);
    EXPECT_LT(direction_angle(result.t_camera2_camera1, v.T), kNoisyDirectionRadians);
    EXPECT_GT(result.residual, 0.0);
    EXPECT_GT(result.null_space_ratio, 0.0);
    EXPECT_LT(result.null_space_ratio, 1.0);
  }
}

TEST(TwoView, FocalLengthScalesImageUnits) {
  constexpr double kFocal = 1200.0;  // pixels
  std::mt19937 rng(kSeed + 5);
  const TwoViews v = random_views(rng, 10, 0.0, kFocal);
  TwoViewOptions options;
  options.focal_length = kFocal;
  const TwoViewResult result = two_view_pose(v.image1, v.image2, options);
  ASSERT_EQ(result.status, TwoViewStatus::kOk);
  EXPECT_LT(rotation_angle_between(result.R_camera2_camera1, v.R), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.t_camera2_camera1, v.T.normalized(), kNoiseFreeDirection);
}

TEST(TwoView, PureRotationIsDegenerate) {
  std::mt19937 rng(kSeed + 6);
  TwoViews v = random_views(rng, 20);
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector3d m1(v.image1(0, i), v.image1(1, i), 1.0);
    const Eigen::Vector3d x2 = v.R * m1;
    v.image2.col(i) = x2.head<2>() / x2.z();
  }
  const TwoViewResult result = two_view_pose(v.image1, v.image2);
  EXPECT_EQ(result.status, TwoViewStatus::kDegenerate);
  EXPECT_FALSE(result.message.empty());
}

TEST(TwoView, PlanarSceneIsDegenerate) {
  // A plane is a critical surface of the linear algorithm: its motion equation has a
  // three-dimensional solution space.
  std::mt19937 rng(kSeed + 7);
  std::uniform_real_distribution<double> lateral(-1.5, 1.5);
  const Eigen::Matrix3d R = random_small_rotation(rng, 0.4);
  const Eigen::Vector3d T(0.7, -0.2, 0.3);
  Eigen::Matrix2Xd image1(2, 16);
  Eigen::Matrix2Xd image2(2, 16);
  for (int i = 0; i < 16; ++i) {
    const double x = lateral(rng);
    const double y = lateral(rng);
    const Eigen::Vector3d x1(x, y, 5.0 + 0.3 * x - 0.2 * y);
    const Eigen::Vector3d x2 = R * x1 + T;
    image1.col(i) = x1.head<2>() / x1.z();
    image2.col(i) = x2.head<2>() / x2.z();
  }
  EXPECT_EQ(two_view_pose(image1, image2).status, TwoViewStatus::kDegenerate);
}

TEST(TwoView, BadInputThrowsNamingTheArgument) {
  std::mt19937 rng(kSeed + 8);
  const TwoViews v = random_views(rng, 9);
  auto message = [](const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b,
                    const TwoViewOptions& options = {}) {
    return testing::message_of([&] { two_view_pose(a, b, options); });
  };
  EXPECT_THAT(message(v.image1, v.image2.leftCols(8)), ::testing::HasSubstr("image2"));
  EXPECT_THAT(message(v.image1.leftCols(7), v.image2.leftCols(7)),
              ::testing::HasSubstr("at least 8"));
  Eigen::Matrix2Xd bad = v.image2;
  bad(1, 5) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(message(v.image1, bad), ::testing::HasSubstr("image2[5]"));
  bad = v.image1;
  bad(0, 0) = -std::numeric_limits<double>::infinity();
  EXPECT_THAT(message(bad, v.image2), ::testing::HasSubstr("image1[0]"));
  TwoViewOptions options;
  options.focal_length = -1.0;
  EXPECT_THAT(message(v.image1, v.image2, options), ::testing::HasSubstr("focal_length"));
  options = {};
  options.degenerate_tolerance = 1.0;
  EXPECT_THAT(message(v.image1, v.image2, options), ::testing::HasSubstr("degenerate_tolerance"));
}

}  // namespace
}  // namespace vantage
