#include "vantage/analysis/orthogonal_iteration.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>

#include "support/allocation_counter.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::IsRotation;
using testing::kSeed;

// Noise-free recovery. The iteration converges linearly and stops once E <= kTightAbsolute
// (squared object units); with object points ~1 unit from the centroid this leaves residual
// distances ~1e-11, i.e. rotation errors ~1e-11 rad, far below these bounds.
constexpr double kTightAbsolute = 1e-22;
constexpr double kNoiseFreeRadians = 1e-9;
constexpr double kNoiseFreeTranslation = 1e-8;  // object units, at depths 4-8
// FOAM and SVD compute the same rotation per step (to rounding), so the iterations agree to the
// stopping accuracy.
constexpr double kStepAgreementRadians = 1e-8;
constexpr double kStepAgreementTranslation = 1e-7;  // object units, at depths 4-8
// Noise of 1e-3 in normalised image coordinates (about 1 pixel at f = 1000) on 20 points spread
// over ~0.25 rad of field of view: rotation errors of a few milliradians at most.
constexpr double kImageNoise = 1e-3;
constexpr double kNoisyRadians = 2e-2;
constexpr double kNoisyTranslation = 0.1;  // object units, mostly along the line of sight

// The object-space error recomputed here from its definition: rounding of six small squared norms.
constexpr double kObjectSpaceRounding = 1e-15;
// An iteration never raises the objective beyond the relative rounding of its evaluation.
constexpr double kObjectiveRelative = 1e-12;
// All weights scaled by 7 scale the objective by 7: the two runs stop at their own tolerances.
constexpr double kScaledObjectiveRelative = 1e-9;
// A noise-free objective is rounding itself, below the stopping level kTightAbsolute.
constexpr double kObjectiveFloor = 1e-24;

/// A random perspective scene: n object points in [-1, 1]^3, a random rotation, the object's
/// origin at depth 4-8 with a small lateral offset, so every point is in front of the camera.
struct Scene {
  Eigen::Matrix3Xd model;
  Eigen::Matrix2Xd image;
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
};

Scene random_scene(std::mt19937& rng, int n, double noise = 0.0, double focal = 1.0) {
  std::uniform_real_distribution<double> depth(4.0, 8.0);
  std::uniform_real_distribution<double> lateral(-0.5, 0.5);
  std::normal_distribution<double> normal(0.0, noise);
  Scene s;
  s.model = testing::random_points(rng, n);
  s.R = testing::random_rotation(rng);
  s.p = Eigen::Vector3d(lateral(rng), lateral(rng), depth(rng));
  s.image.resize(2, n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d x = s.R * s.model.col(i) + s.p;
    s.image.col(i) = focal * x.head<2>() / x.z();
    if (noise > 0.0) s.image.col(i) += focal * Eigen::Vector2d(normal(rng), normal(rng));
  }
  return s;
}

/// sum |x_i - x_bar|^2: the scale of OrthogonalIterationOptions::absolute_tolerance.
double spread(const Eigen::Matrix3Xd& model) {
  return (model.colwise() - model.rowwise().mean()).squaredNorm();
}

/// The defaults with image points in normalised coordinates (f = 1, c = 0).
OrthogonalIterationOptions normalised() {
  OrthogonalIterationOptions options;
  options.camera.focal_length = 1.0;
  return options;
}

OrthogonalIterationOptions tight(OrientationMethod step) {
  OrthogonalIterationOptions options = normalised();
  options.rotation_step = step;
  options.absolute_tolerance = kTightAbsolute;
  options.relative_tolerance = 0.0;
  options.pose_tolerance = 0.0;
  options.max_iterations = 5000;
  return options;
}

class EveryStep : public ::testing::TestWithParam<OrientationMethod> {};

TEST_P(EveryStep, NoiseFreeSceneReturnsTruth) {
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 54; ++trial) {
    const int n = 4 + trial % 27;  // n = 4..30, twice each
    const Scene s = random_scene(rng, n);
    const OrthogonalIterationResult result =
        orthogonal_iteration_pose(s.model, s.image, {}, tight(GetParam()));
    ASSERT_EQ(result.status, PoseStatus::kOk)
        << "trial " << trial << ", n = " << n << ": " << result.message;
    EXPECT_THAT(result.R_camera_object, IsRotation());
    EXPECT_LT(rotation_angle_between(result.R_camera_object, s.R), kNoiseFreeRadians)
        << "trial " << trial << ", n = " << n;
    EXPECT_EIGEN_NEAR(result.p_camera_object, s.p, kNoiseFreeTranslation);
    EXPECT_LE(result.objective, kTightAbsolute * spread(s.model));
    EXPECT_LE(result.objective, result.initial_objective);
    EXPECT_EQ(result.points_behind_camera, 0);
    EXPECT_TRUE(result.message.empty());
  }
}

TEST_P(EveryStep, NoisySceneGivesSmallErrorAndStops) {
  std::mt19937 rng(kSeed + 1);
  OrthogonalIterationOptions options = normalised();  // the defaults, as a caller would use them
  options.rotation_step = GetParam();
  for (int trial = 0; trial < 20; ++trial) {
    const Scene s = random_scene(rng, 20, kImageNoise);
    const OrthogonalIterationResult result =
        orthogonal_iteration_pose(s.model, s.image, {}, options);
    EXPECT_EQ(result.status, PoseStatus::kOk) << result.message;
    EXPECT_LT(result.iterations, options.max_iterations);
    EXPECT_THAT(result.R_camera_object, IsRotation());
    EXPECT_LT(rotation_angle_between(result.R_camera_object, s.R), kNoisyRadians);
    EXPECT_LT((result.p_camera_object - s.p).norm(), kNoisyTranslation);
    EXPECT_GT(result.objective, 0.0);
    // The true pose is a feasible point: the minimiser cannot be worse than it.
    EXPECT_LE(result.objective, object_space_error(s.model, s.image, s.R, s.p, {}, options));
  }
}

TEST_P(EveryStep, ErrorNeverIncreases) {
  // Lu et al.: each step minimises over t, then over R for fixed projections, so E decreases.
  std::mt19937 rng(kSeed + 2);
  const Scene s = random_scene(rng, 12, kImageNoise);
  OrthogonalIterationOptions options = tight(GetParam());
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 30; ++k) {
    options.max_iterations = k;
    const OrthogonalIterationResult result =
        orthogonal_iteration_pose(s.model, s.image, {}, options);
    EXPECT_EQ(result.iterations, k);
    EXPECT_LE(result.objective, previous * (1.0 + kObjectiveRelative)) << "step " << k;
    previous = result.objective;
  }
}

TEST_P(EveryStep, StartAtTruthStopsAtOnce) {
  std::mt19937 rng(kSeed + 3);
  const Scene s = random_scene(rng, 8);
  OrthogonalIterationOptions options = normalised();
  options.rotation_step = GetParam();
  options.absolute_tolerance = 1e-20;  // E at the truth is rounding only: ~1e-30
  const OrthogonalIterationResult result =
      orthogonal_iteration_pose(s.model, s.image, s.R, {}, options);
  EXPECT_EQ(result.status, PoseStatus::kOk);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_LT(rotation_angle_between(result.R_camera_object, s.R), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.p_camera_object, s.p, kNoiseFreeTranslation);
}

TEST_P(EveryStep, MaxIterationsIsReported) {
  std::mt19937 rng(kSeed + 4);
  const Scene s = random_scene(rng, 10);
  OrthogonalIterationOptions options = tight(GetParam());
  options.max_iterations = 1;
  const OrthogonalIterationResult result = orthogonal_iteration_pose(s.model, s.image, {}, options);
  EXPECT_EQ(result.status, PoseStatus::kMaxIterations);
  EXPECT_EQ(result.iterations, 1);
  EXPECT_FALSE(result.message.empty());
  EXPECT_THAT(result.R_camera_object, IsRotation());
}

INSTANTIATE_TEST_SUITE_P(OrthogonalIteration, EveryStep,
                         ::testing::Values(OrientationMethod::kFoam, OrientationMethod::kSvd,
                                           OrientationMethod::kQMethod),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(OrthogonalIteration, FoamAndSvdStepsConvergeToTheSamePose) {
  std::mt19937 rng(kSeed + 5);
  for (int trial = 0; trial < 20; ++trial) {
    const Scene s = random_scene(rng, 4 + trial, kImageNoise);
    const OrthogonalIterationResult foam =
        orthogonal_iteration_pose(s.model, s.image, {}, tight(OrientationMethod::kFoam));
    const OrthogonalIterationResult svd =
        orthogonal_iteration_pose(s.model, s.image, {}, tight(OrientationMethod::kSvd));
    ASSERT_NE(foam.status, PoseStatus::kDegenerate);
    EXPECT_LT(rotation_angle_between(foam.R_camera_object, svd.R_camera_object),
              kStepAgreementRadians)
        << "trial " << trial;
    EXPECT_EIGEN_NEAR(foam.p_camera_object, svd.p_camera_object, kStepAgreementTranslation);
    EXPECT_NEAR(foam.objective, svd.objective,
                kObjectiveRelative * svd.objective + kObjectiveFloor);
  }
}

TEST(OrthogonalIteration, FocalLengthScalesImageUnits) {
  constexpr double kFocal = 800.0;  // pixels
  std::mt19937 rng(kSeed + 6);
  const Scene s = random_scene(rng, 9, 0.0, kFocal);
  OrthogonalIterationOptions options = tight(OrientationMethod::kFoam);
  options.camera.focal_length = kFocal;
  const OrthogonalIterationResult result = orthogonal_iteration_pose(s.model, s.image, {}, options);
  EXPECT_EQ(result.status, PoseStatus::kOk);
  EXPECT_LT(rotation_angle_between(result.R_camera_object, s.R), kNoiseFreeRadians);
  EXPECT_EIGEN_NEAR(result.p_camera_object, s.p, kNoiseFreeTranslation);
}

TEST(OrthogonalIteration, WeightsAreRelative) {
  // Scaling every weight scales E but not its minimiser.
  std::mt19937 rng(kSeed + 7);
  const Scene s = random_scene(rng, 15, kImageNoise);
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(15, 0.5, 3.0);
  const OrthogonalIterationOptions options = tight(OrientationMethod::kFoam);
  const OrthogonalIterationResult a = orthogonal_iteration_pose(s.model, s.image, w, options);
  const OrthogonalIterationResult b =
      orthogonal_iteration_pose(s.model, s.image, Eigen::VectorXd(7.0 * w), options);
  EXPECT_LT(rotation_angle_between(a.R_camera_object, b.R_camera_object), kStepAgreementRadians);
  EXPECT_NEAR(b.objective, 7.0 * a.objective, kScaledObjectiveRelative * b.objective);
}

TEST(OrthogonalIteration, DownweightedOutlierIsIgnored) {
  std::mt19937 rng(kSeed + 8);
  Scene s = random_scene(rng, 10);
  s.image.col(3) += Eigen::Vector2d(0.2, -0.1);  // a gross mismatch
  Eigen::VectorXd w = Eigen::VectorXd::Ones(10);
  w(3) = 1e-15;
  // The outlier's pull on E is ~1e-15 * 0.2^2 against an exact fit elsewhere: negligible.
  constexpr double kDownweightedRadians = 1e-6;
  const OrthogonalIterationResult result =
      orthogonal_iteration_pose(s.model, s.image, w, tight(OrientationMethod::kFoam));
  EXPECT_LT(rotation_angle_between(result.R_camera_object, s.R), kDownweightedRadians);
}

TEST(OrthogonalIteration, ObjectSpaceErrorMatchesDefinition) {
  std::mt19937 rng(kSeed + 9);
  const Scene s = random_scene(rng, 6, kImageNoise);
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(6, 1.0, 2.0);
  double expected = 0.0;
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d m(s.image(0, i), s.image(1, i), 1.0);
    const Eigen::Matrix3d V = m * m.transpose() / m.squaredNorm();
    expected +=
        w(i) * ((Eigen::Matrix3d::Identity() - V) * (s.R * s.model.col(i) + s.p)).squaredNorm();
  }
  EXPECT_NEAR(object_space_error(s.model, s.image, s.R, s.p, w, normalised()), expected,
              kObjectSpaceRounding);
}

TEST(OrthogonalIteration, WeakPerspectiveStartIsExactForDistantIsotropicObjects) {
  // Lu et al.'s start aligns the centred model with the centred rays. Under scaled orthographic
  // projection (depth 1000 >> size 1) the rays are s P R x_i (P keeps x, y), so H^T = s P R C
  // with C = sum x_i x_i^T; for an isotropic model (cube corners, C = 8 I) the start is R itself
  // up to the O(size / depth) perspective terms. (For anisotropic models it is biased, which is
  // why the iteration follows.)
  constexpr double kWeakPerspectiveRadians = 1e-2;
  std::mt19937 rng(kSeed + 10);
  Eigen::Matrix3Xd model(3, 8);
  for (int i = 0; i < 8; ++i)
    model.col(i) = Eigen::Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  const Eigen::Matrix3d R = testing::random_rotation(rng);
  Eigen::Matrix2Xd image(2, 8);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d x = R * model.col(i) + Eigen::Vector3d(1.0, -2.0, 1000.0);
    image.col(i) = x.head<2>() / x.z();
  }
  const Eigen::Matrix3d R0 = weak_perspective_rotation(model, image, {}, normalised());
  EXPECT_THAT(R0, IsRotation());
  EXPECT_LT(rotation_angle_between(R0, R), kWeakPerspectiveRadians);
}

TEST(OrthogonalIteration, ParallelLinesOfSightAreDegenerate) {
  std::mt19937 rng(kSeed + 11);
  const Eigen::Matrix3Xd model = testing::random_points(rng, 6);
  const Eigen::Matrix2Xd image = Eigen::Matrix2Xd::Constant(2, 6, 0.1);
  const OrthogonalIterationResult result =
      orthogonal_iteration_pose(model, image, {}, normalised());
  EXPECT_EQ(result.status, PoseStatus::kDegenerate);
  EXPECT_FALSE(result.message.empty());
}

TEST(OrthogonalIteration, CollinearModelIsDegenerate) {
  std::mt19937 rng(kSeed + 12);
  Eigen::Matrix3Xd model(3, 5);
  for (int i = 0; i < 5; ++i) model.col(i) = Eigen::Vector3d(1.0, 2.0, -1.0) * (i - 2.0);
  const Eigen::Matrix3d R = testing::random_rotation(rng);
  Eigen::Matrix2Xd image(2, 5);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d x = R * model.col(i) + Eigen::Vector3d(0.1, 0.0, 10.0);
    image.col(i) = x.head<2>() / x.z();
  }
  const OrthogonalIterationResult result =
      orthogonal_iteration_pose(model, image, {}, normalised());
  EXPECT_EQ(result.status, PoseStatus::kDegenerate);
}

TEST(OrthogonalIteration, SolveAllocatesNothing) {
  std::mt19937 rng(kSeed + 13);
  const Scene s = random_scene(rng, 30, kImageNoise);
  const OrthogonalIterationOptions options = normalised();
  OrthogonalIterationResult result;
  long allocations = -1;
  {
    testing::CountAllocations counter;
    result = orthogonal_iteration_pose(s.model, s.image, {}, options);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(result.status, PoseStatus::kOk);
}

TEST(OrthogonalIteration, BadInputThrowsNamingTheArgument) {
  std::mt19937 rng(kSeed + 14);
  const Scene s = random_scene(rng, 5);
  auto message_of = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const InvalidArgument& error) {
      return error.what();
    }
    return "no exception";
  };
  auto solve = [&](const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                   const Eigen::VectorXd& w = {},
                   const OrthogonalIterationOptions& o = normalised()) {
    return [=] { orthogonal_iteration_pose(model, image, w, o); };
  };
  EXPECT_THAT(message_of(solve(s.model, s.image.leftCols(4))), ::testing::HasSubstr("image"));
  EXPECT_THAT(message_of(solve(s.model.leftCols(2), s.image.leftCols(2))),
              ::testing::HasSubstr("at least 3"));
  Eigen::Matrix3Xd bad_model = s.model;
  bad_model(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(message_of(solve(bad_model, s.image)), ::testing::HasSubstr("model_object[2]"));
  Eigen::Matrix2Xd bad_image = s.image;
  bad_image(0, 4) = std::numeric_limits<double>::infinity();
  EXPECT_THAT(message_of(solve(s.model, bad_image)), ::testing::HasSubstr("image[4]"));
  EXPECT_THAT(message_of(solve(s.model, s.image, Eigen::VectorXd::Ones(4))),
              ::testing::HasSubstr("weights"));
  Eigen::VectorXd negative = Eigen::VectorXd::Ones(5);
  negative(1) = -1.0;
  EXPECT_THAT(message_of(solve(s.model, s.image, negative)), ::testing::HasSubstr("weights[1]"));
  OrthogonalIterationOptions options;  // no focal length: refused, never guessed
  EXPECT_THAT(message_of(solve(s.model, s.image, {}, options)),
              ::testing::HasSubstr("camera.focal_length"));
  options = normalised();
  options.max_iterations = -1;
  EXPECT_THAT(message_of(solve(s.model, s.image, {}, options)),
              ::testing::HasSubstr("max_iterations"));
  EXPECT_THAT(message_of([&] {
                orthogonal_iteration_pose(s.model, s.image, Eigen::Matrix3d(2.0 * s.R), {},
                                          normalised());
              }),
              ::testing::HasSubstr("initial_R_camera_object"));
}

TEST(OrthogonalIteration, ExactFarRangeDataStopsAsConverged) {
  // Range 1000 object sizes, f = 1000 px, principal point (320, 240): E shrinks geometrically
  // and slowly, so only the pose-change rule can stop it; it must stop as kOk, at the truth.
  constexpr double kFarRadians = 1e-8;
  std::mt19937 rng(kSeed + 15);
  OrthogonalIterationOptions options;
  options.camera.focal_length = 1000.0;
  options.camera.principal_point = Eigen::Vector2d(320.0, 240.0);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Matrix3Xd model = testing::random_points(rng, 6 + trial);
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Vector3d p(0.5, -0.3, 1000.0);
    Eigen::Matrix2Xd image(2, model.cols());
    for (Eigen::Index i = 0; i < model.cols(); ++i) {
      const Eigen::Vector3d x = R * model.col(i) + p;
      image.col(i) = options.camera.principal_point + 1000.0 * x.head<2>() / x.z();
    }
    const OrthogonalIterationResult result = orthogonal_iteration_pose(model, image, {}, options);
    EXPECT_EQ(result.status, PoseStatus::kOk) << trial << ": " << result.message;
    EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kFarRadians) << trial;
    EXPECT_LT(result.reprojection_rms_px, 1e-6);
  }
}

TEST(OrthogonalIteration, PlanarTargetRunsBothBranchesAndKeepsTheBetter) {
  // Eight coplanar points at range 10: the weak-perspective start only fixes the rotation about
  // the axis and often ends in the wrong basin. IPPE's two poses both run; one of them is exact
  // on noise-free images, so every trial stops as converged at the truth, no worse than the
  // single weak-perspective run.
  constexpr double kPlanarRadians = 1e-8;
  constexpr double kRoundingObjective = 1e-18;  // E of an exact fit is rounding, ~1e-23
  std::mt19937 rng(kSeed + 16);
  OrthogonalIterationOptions options;
  options.camera.focal_length = 1000.0;
  int alternatives = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Eigen::Matrix3Xd model = testing::random_points(rng, 8);
    model.row(2).setZero();
    const Eigen::Matrix3d R = testing::random_rotation(rng);
    const Eigen::Vector3d p(0.3, -0.2, 10.0);
    Eigen::Matrix2Xd image(2, 8);
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d x = R * model.col(i) + p;
      image.col(i) = 1000.0 * x.head<2>() / x.z();
    }
    const OrthogonalIterationResult result = orthogonal_iteration_pose(model, image, {}, options);
    EXPECT_EQ(result.branches, 2);
    ASSERT_EQ(result.status, PoseStatus::kOk) << trial << ": " << result.message;
    EXPECT_LT(rotation_angle_between(result.R_camera_object, R), kPlanarRadians) << trial;
    EXPECT_FALSE(result.ambiguous) << trial;  // perspective separates the pair at range 10
    if (result.alternative) {
      ++alternatives;
      EXPECT_GT(result.alternative->reprojection_rms_px, result.reprojection_rms_px);
    }
    const OrthogonalIterationResult single = orthogonal_iteration_pose(
        model, image, weak_perspective_rotation(model, image, {}, options), {}, options);
    EXPECT_LE(result.objective, single.objective + kRoundingObjective);
  }
  EXPECT_GT(alternatives, 0);  // the second branch is a distinct local minimum
}

}  // namespace
}  // namespace vantage
