#include "vantage/analysis/absolute_orientation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "support/eigen_testing.h"
#include "support/message_of.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::IsRotation;
using testing::IsRotationWithin;
using testing::kSeed;
using testing::message_of;

// Noise-free recovery: rounding of O(n) sums of unit-size data.
constexpr double kNoiseFreeRadians = 1e-10;
constexpr double kNoiseFreeRelative = 1e-10;
// Methods solve the same problem exactly, so even on noisy data they agree to rounding.
constexpr double kMethodAgreementRadians = 1e-9;
// The same solver from a different root-iteration start (optimal_rotation() knows only H): the
// roots agree to a few ulps of ||H||, and the gap is their difference.
constexpr double kSameSolverGap = 1e-13;

// Noise-free translation, unit-size data: the rotation's and scale's rounding times the object
// size.
constexpr double kNoiseFreeTranslation = 1e-9;
// Methods solve the same problem exactly: scale and residual agree to rounding (like the rotation).
constexpr double kMethodAgreement = 1e-9;
// The eigen-gap is a difference of two eigenvalues: each method's rounding of both.
constexpr double kGapAgreement = 1e-8;
// The residual recomputed here from its definition: rounding of a weighted sum.
constexpr double kRounding = 1e-12;
// D built two ways from the same unit-size terms: rounding of a few sums.
constexpr double kMatrixRounding = 1e-14;
// A swap's change of D, directly and as a difference of two D: rounding of unit-size sums.
constexpr double kSwapDeltaRounding = 1e-13;
// A noise-free residual is a sum of squares of rounding errors: ~1e-30 per term.
constexpr double kNoiseFreeResidualZero = 1e-18;
// The chosen weights balance the chosen points exactly, up to rounding of one small sum.
constexpr double kBalancedWeights = 1e-15;
// A degenerate layout's optimum still maps its one direction: rounding of a unit vector.
constexpr double kDirectionRounding = 1e-9;
// A noise-free residual in expanded form cancels O(n) unit-size terms: rounding per point.
constexpr double kExpandedResidualPerPoint = 1e-12;
// optimal_rotation() and absolute_orientation() run the same solver on the same H.
constexpr double kSameSolverRadians = 1e-12;

const OrientationMethod kMethods[] = {OrientationMethod::kQMethod, OrientationMethod::kSvd,
                                      OrientationMethod::kFoam};

OrientationOptions with_method(OrientationMethod method) {
  OrientationOptions options;
  options.method = method;
  return options;
}

class EveryMethod : public ::testing::TestWithParam<OrientationMethod> {};

TEST_P(EveryMethod, NoiseFreeDirectionsReturnTruth) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 2 + trial % 9;
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const double alpha = 0.5 + trial * 0.1;
    const Eigen::Matrix3Xd z = testing::random_points(rng, n);
    const Eigen::Matrix3Xd v = R * z / alpha;
    Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 0.5, 2.0);
    const OrientationResult result = absolute_orientation(z, v, w, with_method(GetParam()));
    EXPECT_EQ(result.status, OrientationStatus::kOk) << result.message;
    EXPECT_THAT(result.R_camera_object, IsRotation());
    EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kNoiseFreeRadians);
    EXPECT_NEAR(result.alpha, alpha, kNoiseFreeRelative * alpha);
    EXPECT_LT(result.residual, kExpandedResidualPerPoint * n);
    EXPECT_GT(result.eigen_gap, 0.0);
  }
}

TEST_P(EveryMethod, NoiseFreePointsReturnPose) {
  std::mt19937 rng(kSeed + 1);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 3 + trial % 8;
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Vector3d p = testing::random_points(rng, 1, 5.0).col(0);
    const double alpha = 2.0;
    const Eigen::Matrix3Xd z = testing::random_points(rng, n);
    const Eigen::Matrix3Xd q = ((R * z).colwise() + p) / alpha;
    const PoseResult result = absolute_pose(z, q, {}, with_method(GetParam()));
    EXPECT_EQ(result.status, OrientationStatus::kOk);
    EXPECT_THAT(result.R_camera_object, IsRotation());
    EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kNoiseFreeRadians);
    EXPECT_EIGEN_NEAR(result.p_camera_object, p, kNoiseFreeTranslation);
    EXPECT_NEAR(result.alpha, alpha, kNoiseFreeRelative * alpha);
  }
}

TEST_P(EveryMethod, ReflectedDataStillGiveARotation) {
  // Measured vectors are the mirror image of the model: the unconstrained optimum is a
  // reflection (det = -1); Haralick's guard and the quaternion methods must return a rotation.
  std::mt19937 rng(kSeed + 2);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 6);
  const Eigen::Matrix3d mirror = Eigen::Vector3d(1, 1, -1).asDiagonal();
  const OrientationResult result = absolute_orientation(z, mirror * z, {}, with_method(GetParam()));
  EXPECT_THAT(result.R_camera_object, IsRotationWithin(1e-10));
  const OrientationResult reference = absolute_orientation(z, mirror * z);
  EXPECT_LT(rotation_angle_between(result.R_camera_object, reference.R_camera_object),
            kMethodAgreementRadians);
}

INSTANTIATE_TEST_SUITE_P(AbsoluteOrientation, EveryMethod, ::testing::ValuesIn(kMethods),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(AbsoluteOrientation, MethodsAgreeOnNoisyData) {
  std::mt19937 rng(kSeed + 3);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 3 + trial % 10;
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Matrix3Xd z = testing::random_points(rng, n);
    Eigen::Matrix3Xd v = R * z;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < 3; ++i) v(i, j) += noise(rng);
    const OrientationResult q = absolute_orientation(z, v);
    for (OrientationMethod method : {OrientationMethod::kSvd, OrientationMethod::kFoam}) {
      const OrientationResult other = absolute_orientation(z, v, {}, with_method(method));
      EXPECT_LT(rotation_angle_between(q.R_camera_object, other.R_camera_object),
                kMethodAgreementRadians)
          << to_string(method);
      EXPECT_NEAR(q.alpha, other.alpha, kMethodAgreement);
      EXPECT_NEAR(q.residual, other.residual, kMethodAgreement);
      EXPECT_NEAR(q.eigen_gap, other.eigen_gap, kGapAgreement);
    }
  }
}

TEST(AbsoluteOrientation, AgreesWithEigenUmeyama) {
  std::mt19937 rng(kSeed + 4);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 4 + trial % 7;
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Matrix3Xd z = testing::random_points(rng, n);
    Eigen::Matrix3Xd q = (R * z).colwise() + Eigen::Vector3d(1, 2, 3);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < 3; ++i) q(i, j) += noise(rng);
    const Eigen::Matrix4d T = Eigen::umeyama(z, q, false);
    const PoseResult pose = absolute_pose(z, q);
    EXPECT_LT(rotation_angle_between(pose.R_camera_object, T.topLeftCorner<3, 3>()),
              kMethodAgreementRadians);
  }
}

TEST(AbsoluteOrientation, ResidualIsTheObjective) {
  std::mt19937 rng(kSeed + 5);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 7);
  const Eigen::Matrix3Xd v = testing::random_points(rng, 7);
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(7, 1.0, 3.0);
  const OrientationResult r = absolute_orientation(z, v, w);
  double J = 0.0;
  for (int i = 0; i < 7; ++i)
    J += w(i) * (r.R_camera_object * z.col(i) - r.alpha * v.col(i)).squaredNorm();
  EXPECT_NEAR(r.residual, J, kRounding);
  // Optimality: no nearby rotation does better (first-order condition).
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Matrix3d dR =
        Eigen::AngleAxisd(1e-4, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
    double J_perturbed = 0.0;
    for (int i = 0; i < 7; ++i)
      J_perturbed += w(i) * (dR * r.R_camera_object * z.col(i) - r.alpha * v.col(i)).squaredNorm();
    EXPECT_GE(J_perturbed, J - kRounding);
  }
}

TEST(AbsoluteOrientation, DIsTheSumOfK) {
  std::mt19937 rng(kSeed + 6);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 5);
  const Eigen::Matrix3Xd v = testing::random_points(rng, 5);
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(5, 1.0, 2.0);
  Eigen::Matrix4d D = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 5; ++i) D += w(i) * quaternion_k(v.col(i), z.col(i));
  EXPECT_EIGEN_NEAR(orientation_matrix_d(z, v, w), D, kMatrixRounding);
  const OrientationResult r = absolute_orientation(z, v, w);
  EXPECT_LT(rotation_angle_between(rotation_from_d(D), r.R_camera_object), kNoiseFreeRadians);
}

TEST(AbsoluteOrientation, OptimalRotationFromCrossCovarianceMatchesSolver) {
  std::mt19937 rng(kSeed + 11);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 6);
  const Eigen::Matrix3Xd v = testing::random_points(rng, 6);
  const Eigen::Matrix3d H = z * v.transpose();
  for (OrientationMethod method : kMethods) {
    double gap = -1.0;
    const Eigen::Matrix3d R = optimal_rotation(H, with_method(method), &gap);
    const OrientationResult reference = absolute_orientation(z, v, {}, with_method(method));
    EXPECT_LT(rotation_angle_between(R, reference.R_camera_object), kSameSolverRadians);
    EXPECT_NEAR(gap, reference.eigen_gap, kSameSolverGap) << to_string(method);
  }
}

TEST(AbsoluteOrientation, ParallelVectorsAreDegenerate) {
  Eigen::Matrix3Xd z(3, 3);
  z << 1, 2, -1, 0, 0, 0, 0, 0, 0;
  for (OrientationMethod method : kMethods) {
    const OrientationResult r = absolute_orientation(z, z, {}, with_method(method));
    EXPECT_EQ(r.status, OrientationStatus::kDegenerate) << to_string(method);
    EXPECT_THAT(r.R_camera_object, IsRotationWithin(1e-10));
    EXPECT_FALSE(r.message.empty());
    // Any optimum still maps the one direction correctly.
    EXPECT_EIGEN_NEAR(r.R_camera_object * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(),
                      kDirectionRounding);
  }
}

TEST(AbsoluteOrientation, TwoVectorsDetermineTheRotation) {
  std::mt19937 rng(kSeed + 7);
  const Eigen::Matrix3d R = testing::random_rotation(rng);
  Eigen::Matrix3Xd z(3, 2);
  z << 1, 0, 0, 1, 0, 0;
  const OrientationResult r = absolute_orientation(z, R * z);
  EXPECT_EQ(r.status, OrientationStatus::kOk);
  EXPECT_LT(rotation_angle_between(r.R_camera_object, R), kNoiseFreeRadians);
}

TEST(AbsoluteOrientation, BadInputThrowsNamingTheArgument) {
  const Eigen::Matrix3Xd z = Eigen::Matrix3Xd::Random(3, 4);
  EXPECT_THAT(message_of([&] { absolute_orientation(z, Eigen::Matrix3Xd::Random(3, 3)); }),
              ::testing::HasSubstr("columns"));
  EXPECT_THAT(message_of([&] { absolute_orientation(z, z, Eigen::VectorXd::Ones(3)); }),
              ::testing::HasSubstr("weights"));
  EXPECT_THAT(message_of([&] { absolute_orientation(z, z, -Eigen::VectorXd::Ones(4)); }),
              ::testing::HasSubstr("weights[0]"));
  Eigen::Matrix3Xd nan = z;
  nan(1, 2) = std::nan("");
  EXPECT_THAT(message_of([&] { absolute_orientation(nan, z); }),
              ::testing::HasSubstr("z_object[2]"));
  EXPECT_THAT(message_of([&] { absolute_orientation(z, Eigen::Matrix3Xd::Zero(3, 4)); }),
              ::testing::HasSubstr("zero"));
  EXPECT_THAT(
      message_of([&] { absolute_orientation(Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xd(3, 0)); }),
      ::testing::HasSubstr("need at least 1 correspondence"));
  OrientationOptions bad;
  bad.degenerate_gap = -1.0;
  EXPECT_THAT(message_of([&] { absolute_orientation(z, z, {}, bad); }),
              ::testing::HasSubstr("degenerate_gap"));
}

TEST(SwapSensitivity, DeltaDEqualsRecomputedD) {
  // Prop. 2, Eq. (10).
  std::mt19937 rng(kSeed + 8);
  const int n = 6;
  const Eigen::Matrix3Xd z = testing::random_points(rng, n);
  const Eigen::Matrix3Xd v = testing::random_points(rng, n);
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 0.5, 3.0);
  const Eigen::Matrix4d D = orientation_matrix_d(z, v, w);
  for (int j = 0; j < n; ++j) {
    for (int k = j + 1; k < n; ++k) {
      Eigen::Matrix3Xd swapped = v;
      swapped.col(j) = v.col(k);
      swapped.col(k) = v.col(j);
      const Eigen::Matrix4d expected = orientation_matrix_d(z, swapped, w) - D;
      EXPECT_EIGEN_NEAR(swap_delta_d(v.col(j), v.col(k), z.col(j), z.col(k), w(j), w(k)), expected,
                        kSwapDeltaRounding);
    }
  }
}

TEST(DecoupledPose, CentredDataGivePoseWithKnownScale) {
  // Prop. 3: symmetric pairs z, -z with equal weights satisfy Eq. (11).
  std::mt19937 rng(kSeed + 9);
  const Eigen::Matrix3Xd half = testing::random_points(rng, 4);
  Eigen::Matrix3Xd z(3, 8);
  z << half, -half;
  const Eigen::Matrix3d R = testing::random_rotation(rng);
  const Eigen::Vector3d p(0.3, -0.2, 10.0);
  const double alpha = 4.0;
  const Eigen::Matrix3Xd q = ((R * z).colwise() + p) / alpha;
  const PoseResult result = decoupled_pose(z, q, alpha);
  ASSERT_EQ(result.status, OrientationStatus::kOk) << result.message;
  EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.p_camera_object, p, kNoiseFreeTranslation);
  EXPECT_NEAR(result.residual, 0.0, kNoiseFreeResidualZero);
}

TEST(DecoupledPose, NonCentredDataAreReportedNotSolved) {
  std::mt19937 rng(kSeed + 10);
  const Eigen::Matrix3Xd z = testing::random_points(rng, 5).array() + 2.0;
  const PoseResult result = decoupled_pose(z, z, 1.0);
  EXPECT_EQ(result.status, OrientationStatus::kNotCentred);
  EXPECT_THAT(result.message, ::testing::HasSubstr("Eq. 11"));
}

TEST(DecoupledPose, WeightsCanCentreTheData) {
  // Columns (1,0,0.5), (-2,0,-1), (0,1,0), (0,-1,0) with weights (2,1,0.5,0.5): sum w z = 0.
  Eigen::Matrix3Xd z(3, 4);
  z << 1, -2, 0, 0, 0, 0, 1, -1, 0.5, -1, 0, 0;
  const Eigen::VectorXd w = (Eigen::VectorXd(4) << 2, 1, 0.5, 0.5).finished();
  ASSERT_NEAR((z * w).norm(), 0.0, kBalancedWeights);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d p(1, 2, 30);
  const PoseResult result = decoupled_pose(z, (R * z).colwise() + p, 1.0, w);
  ASSERT_EQ(result.status, OrientationStatus::kOk);
  EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.p_camera_object, p, kNoiseFreeTranslation);
}

}  // namespace
}  // namespace vantage
