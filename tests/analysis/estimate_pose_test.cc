// estimate_pose(): the one front door of every pose method. Noise-free data return the truth
// through it for every method, it returns what the method's own solver returns, and bad input
// names the Correspondences field.

#include "vantage/analysis/estimate_pose.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <string>

#include "affine_testing.h"
#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/refined_pose.h"

namespace vantage {
namespace {

using testing::IsRotation;
using testing::kSeed;

// Noise-free recovery: closed forms and converged refinements on unit-size data reach the truth
// to rounding of O(n) sums; the refinements stop at a 1e-12 step.
constexpr double kExactRadians = 1e-8;
constexpr double kExactRelative = 1e-8;
constexpr double kFocal = 800.0;

/// A random non-planar model seen by a known pose; images under both camera models.
struct Truth {
  Eigen::Matrix3Xd model;
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  Eigen::Matrix3Xd camera_points;  // R model + p
};

Truth make_truth(std::mt19937& rng, int n) {
  Truth t;
  t.model = testing::random_points(rng, n);
  t.R = testing::random_rotation(rng);
  t.p = Eigen::Vector3d(0.3, -0.2, 12.0);
  t.camera_points = (t.R * t.model).colwise() + t.p;
  return t;
}

/// f (x / z, y / z) of camera-frame points.
Eigen::Matrix2Xd project(const Eigen::Matrix3Xd& x) {
  Eigen::Matrix2Xd image(2, x.cols());
  for (Eigen::Index i = 0; i < x.cols(); ++i) image.col(i) = kFocal * x.col(i).head<2>() / x(2, i);
  return image;
}

Eigen::Matrix2Xd pinhole_image(const Truth& t) { return project(t.camera_points); }

double angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return rotation_angle_between(a, b);
}

TEST(PoseMethod, NamesRoundTripAndUnknownNamesAreRefusedWithTheField) {
  std::set<std::string> names;
  for (PoseMethod method : kPoseMethods) {
    const std::string name = to_string(method);
    EXPECT_TRUE(names.insert(name).second) << name << " twice";
    ASSERT_TRUE(parse_pose_method(name).has_value()) << name;
    EXPECT_EQ(*parse_pose_method(name), method);
    EXPECT_NE(std::string(describe(method)), "unknown");
  }
  EXPECT_EQ(names.size(), kPoseMethods.size());
  EXPECT_FALSE(parse_pose_method("affine-spanning").has_value());
  try {
    parse_pose_method_or_throw("posit", "--method");
    FAIL() << "no throw";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "--method");
    EXPECT_NE(e.problem().find("perspective"), std::string::npos) << e.what();
  }
}

TEST(EstimatePose, NoiseFreeDataReturnTheTruthForEveryImageMethod) {
  std::mt19937 rng(kSeed + 60);
  for (int trial = 0; trial < 5; ++trial) {
    const Truth t = make_truth(rng, 7 + trial);
    Correspondences pinhole;
    pinhole.model = t.model;
    pinhole.image = pinhole_image(t);
    pinhole.camera.focal_length = kFocal;
    for (PoseMethod method : {PoseMethod::kPerspective, PoseMethod::kOiFoam, PoseMethod::kOiSvd}) {
      const PoseEstimate e = estimate_pose(method, pinhole);
      EXPECT_EQ(e.method, method);
      EXPECT_EQ(e.status, PoseStatus::kOk) << to_string(method) << ": " << e.message;
      EXPECT_THAT(e.R_camera_object, IsRotation());
      EXPECT_LT(angle(e.R_camera_object, t.R), kExactRadians) << to_string(method);
      EXPECT_LT((e.p_camera_object - t.p).norm(), kExactRelative * t.p.norm()) << to_string(method);
      EXPECT_EQ(e.camera.focal_length, kFocal);
    }
    // The affine camera: alpha (q - c) = P (R z + p) with alpha = p_z / f.
    Correspondences affine = pinhole;
    const double alpha = t.p.z() / kFocal;
    affine.image = t.camera_points.topRows<2>() / alpha;
    const PoseEstimate refined = estimate_pose(PoseMethod::kAffineRefined, affine);
    EXPECT_EQ(refined.status, PoseStatus::kOk) << refined.message;
    EXPECT_LT(angle(refined.R_camera_object, t.R), kExactRadians);
    EXPECT_NEAR(refined.alpha, alpha, kExactRelative * alpha);
    EXPECT_NEAR(refined.p_camera_object.z(), t.p.z(), kExactRelative * t.p.z());
  }
}

TEST(EstimatePose, NoiseFreeMeasurementsReturnTheTruth) {
  std::mt19937 rng(kSeed + 61);
  const Truth t = make_truth(rng, 9);
  const double alpha = 2.5;  // alpha measured = R model + p
  Correspondences data;
  data.model = t.model;
  data.measured = t.camera_points / alpha;
  for (PoseMethod method : {PoseMethod::kFull3d, PoseMethod::kHaralick3d}) {
    const PoseEstimate e = estimate_pose(method, data);
    EXPECT_EQ(e.status, PoseStatus::kOk) << e.message;
    EXPECT_LT(angle(e.R_camera_object, t.R), kExactRadians) << to_string(method);
    EXPECT_LT((e.p_camera_object - t.p).norm(), kExactRelative * t.p.norm());
    EXPECT_NEAR(e.alpha, alpha, kExactRelative * alpha);
    EXPECT_TRUE(std::isnan(e.reprojection_rms_px)) << "no image residual";
  }
}

TEST(EstimatePose, NoiseFreeTwoViewsAndPlanarPointsReturnTheTruth) {
  std::mt19937 rng(kSeed + 62);
  // Two views of points in front of both cameras: x2 = R x1 + T.
  Eigen::Matrix3Xd x1 = testing::random_points(rng, 12);
  x1.row(2).array() += 6.0;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.2, Eigen::Vector3d(0.3, 1.0, 0.1).normalized()).toRotationMatrix();
  const Eigen::Vector3d T(1.0, 0.2, 0.1);
  const Eigen::Matrix3Xd x2 = (R * x1).colwise() + T;
  Correspondences views;
  views.image1 = project(x1);
  views.image2 = project(x2);
  views.camera.focal_length = kFocal;
  const PoseEstimate two = estimate_pose(PoseMethod::kTwoView, views);
  EXPECT_EQ(two.status, PoseStatus::kOk) << two.message;
  EXPECT_LT(angle(two.R_camera_object, R), kExactRadians);
  EXPECT_LT((two.p_camera_object - T.normalized()).norm(), kExactRelative);
  ASSERT_TRUE(two.diagnostics.essential.has_value());

  // The principal point is taken off both views (the same answer at any c).
  Correspondences shifted = views;
  shifted.camera.principal_point << 320.0, 240.0;
  shifted.image1.colwise() += shifted.camera.principal_point;
  shifted.image2.colwise() += shifted.camera.principal_point;
  EXPECT_LT(angle(estimate_pose(PoseMethod::kTwoView, shifted).R_camera_object, R), kExactRadians);

  Correspondences planar;
  planar.model = testing::random_points(rng, 6);
  planar.model.row(2).setZero();
  const Eigen::Rotation2Dd turn(0.7);
  planar.image =
      (turn.toRotationMatrix() * planar.model.topRows<2>()).colwise() + Eigen::Vector2d(0.5, -1.0);
  const PoseEstimate flat = estimate_pose(PoseMethod::kHaralick2d, planar);
  EXPECT_EQ(flat.status, PoseStatus::kOk);
  EXPECT_LT((flat.R_camera_object.topLeftCorner<2, 2>() - turn.toRotationMatrix()).norm(),
            kExactRelative);
  EXPECT_LT((flat.p_camera_object - Eigen::Vector3d(0.5, -1.0, 0.0)).norm(), kExactRelative);
}

TEST(EstimatePose, ReturnsWhatTheMethodsOwnSolverReturns) {
  std::mt19937 rng(kSeed + 63);
  const Truth t = make_truth(rng, 8);
  Correspondences data;
  data.model = t.model;
  data.image = pinhole_image(t);
  data.image.array() += 0.3;  // not exact: the comparison is not with the truth
  data.camera.focal_length = kFocal;
  RefinedPoseOptions options;
  options.camera = data.camera;
  const RefinedPoseResult direct = perspective_pose(data.model, data.image, {}, options);
  const PoseEstimate front = estimate_pose(PoseMethod::kPerspective, data);
  EXPECT_EQ(front.R_camera_object, direct.R_camera_object);
  EXPECT_EQ(front.p_camera_object, direct.p_camera_object);
  EXPECT_EQ(front.reprojection_rms_px, direct.reprojection_rms_px);
  EXPECT_EQ(front.diagnostics.branches, direct.branches);

  AffinePoseOptions affine;
  affine.camera = data.camera;
  const AffinePoseResult prop8 = affine_pose(data.model, data.image, {}, affine);
  const PoseEstimate via = estimate_pose(PoseMethod::kAffine, data);
  EXPECT_EQ(via.R_camera_object, prop8.R_camera_object);
  EXPECT_EQ(via.alpha, prop8.alpha);
  EXPECT_EQ(via.diagnostics.sign_patterns, prop8.orientation.sign_patterns);
  EXPECT_EQ(via.diagnostics.free_vector_count, prop8.pairs.cols());
}

TEST(EstimatePose, PinholeMethodsReadAnImageWithoutFocalAsNormalisedCoordinates) {
  std::mt19937 rng(kSeed + 64);
  const Truth t = make_truth(rng, 6);
  Correspondences data;
  data.model = t.model;
  data.image = pinhole_image(t) / kFocal;
  const PoseEstimate e = estimate_pose(PoseMethod::kPerspective, data);
  EXPECT_EQ(e.camera.focal_length, 1.0);
  EXPECT_LT(angle(e.R_camera_object, t.R), kExactRadians);
  // The affine methods leave the depth unknown instead.
  const PoseEstimate affine = estimate_pose(PoseMethod::kAffine, data);
  EXPECT_TRUE(std::isnan(affine.p_camera_object.z()));
  EXPECT_FALSE(affine.camera.has_focal_length());
}

TEST(EstimatePose, DegenerateDataGiveAStatusWithAReasonInTheUsersWords) {
  // Collinear model points: no method can fix the rotation about their line.
  Correspondences data;
  data.model.resize(3, 5);
  for (int i = 0; i < 5; ++i) data.model.col(i) = Eigen::Vector3d(i, 2.0 * i, -i);
  Eigen::Matrix3Xd camera = data.model;
  camera.row(2).array() += 20.0;
  data.image = project(camera);
  data.camera.focal_length = kFocal;
  data.measured = camera;
  for (PoseMethod method : {PoseMethod::kAffine, PoseMethod::kStandard, PoseMethod::kFull3d,
                            PoseMethod::kPerspective, PoseMethod::kOiSvd}) {
    const PoseEstimate e = estimate_pose(method, data);
    EXPECT_EQ(e.status, PoseStatus::kDegenerate) << to_string(method);
    EXPECT_FALSE(e.message.empty()) << to_string(method);
    for (const char* internal : {"degenerate_gap", "sign pattern", "eigen gap"}) {
      EXPECT_EQ(e.message.find(internal), std::string::npos)
          << to_string(method) << ": " << e.message;
    }
  }
}

struct BadInput {
  const char* name;
  PoseMethod method;
  void (*spoil)(Correspondences*);
  const char* field;
  long index;  // -1: none
};

Correspondences good_input() {
  std::mt19937 rng(kSeed + 65);
  const Truth t = make_truth(rng, 8);
  Correspondences data;
  data.model = t.model;
  data.image = pinhole_image(t);
  data.measured = t.camera_points;
  data.image1 = data.image;
  data.image2 = data.image.array() + 1.0;
  data.camera.focal_length = kFocal;
  return data;
}

class EstimatePoseBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(EstimatePoseBadInput, NamesTheField) {
  const BadInput& bad = GetParam();
  Correspondences data = good_input();
  bad.spoil(&data);
  try {
    estimate_pose(bad.method, data);
    FAIL() << bad.name << ": no throw";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), bad.field) << e.what();
    if (bad.index >= 0) {
      ASSERT_TRUE(e.index().has_value()) << e.what();
      EXPECT_EQ(*e.index(), bad.index) << e.what();
    }
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, EstimatePoseBadInput,
    ::testing::Values(
        BadInput{"NoImage", PoseMethod::kAffine, [](Correspondences* d) { d->image.resize(2, 0); },
                 "image", -1},
        BadInput{"ShortImage", PoseMethod::kPerspective,
                 [](Correspondences* d) { d->image.conservativeResize(2, 7); }, "image", -1},
        BadInput{"TooFew", PoseMethod::kOiFoam,
                 [](Correspondences* d) {
                   d->model.conservativeResize(3, 2);
                   d->image.conservativeResize(2, 2);
                 },
                 "model", -1},
        BadInput{
            "NotFinite", PoseMethod::kStandard,
            [](Correspondences* d) { d->image(1, 4) = std::numeric_limits<double>::quiet_NaN(); },
            "image", 4},
        BadInput{"Huge", PoseMethod::kAffine, [](Correspondences* d) { d->model(0, 3) = 1e308; },
                 "model", 3},
        BadInput{"HugeMeasured", PoseMethod::kFull3d,
                 [](Correspondences* d) { d->measured(2, 5) = -1e200; }, "measured", 5},
        BadInput{"Coincident", PoseMethod::kAffineRefined,
                 [](Correspondences* d) { d->model.col(6) = d->model.col(2); }, "model", 6},
        BadInput{"BadWeight", PoseMethod::kAffine,
                 [](Correspondences* d) {
                   d->weights = Eigen::VectorXd::Ones(8);
                   d->weights(3) = -1.0;
                 },
                 "weights", 3},
        BadInput{"WeightsCount", PoseMethod::kFull3d,
                 [](Correspondences* d) { d->weights = Eigen::VectorXd::Ones(5); }, "weights", -1},
        BadInput{"TwoViewWeights", PoseMethod::kTwoView,
                 [](Correspondences* d) { d->weights = Eigen::VectorXd::Ones(8); }, "weights", -1},
        BadInput{"TwoViewFew", PoseMethod::kTwoView,
                 [](Correspondences* d) {
                   d->image1.conservativeResize(2, 7);
                   d->image2.conservativeResize(2, 7);
                 },
                 "image1", -1},
        BadInput{"HugeFocal", PoseMethod::kOiSvd,
                 [](Correspondences* d) { d->camera.focal_length = 1e308; }, "camera.focal", -1},
        BadInput{"DirectionsForPinhole", PoseMethod::kPerspective,
                 [](Correspondences* d) { d->directions = true; }, "directions", -1},
        BadInput{"PlanarNeedsZ0", PoseMethod::kHaralick2d, [](Correspondences*) {}, "model", 0}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

TEST(EstimatePose, ExplicitFreeVectorsBeyondProp4sLimitAreRefused) {
  std::mt19937 rng(kSeed + 66);
  const Truth t = make_truth(rng, 9);  // 36 pairs > 24
  Correspondences data;
  data.model = t.model;
  data.image = pinhole_image(t);
  PoseOptions options;
  options.free_vectors = FreeVectorSet::kAllPairs;
  try {
    estimate_pose(PoseMethod::kAffine, data, options);
    FAIL() << "no throw";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "model");
    EXPECT_NE(e.problem().find("36 free vectors"), std::string::npos) << e.what();
  }
  // The standard approach solves one pattern: any set is fine.
  EXPECT_NO_THROW(estimate_pose(PoseMethod::kStandard, data, options));
}

TEST(PoseStatus, EveryStatusHasTheNameTheDocsGive) {
  EXPECT_STREQ(to_string(PoseStatus::kOk), "ok");
  EXPECT_STREQ(to_string(PoseStatus::kMaxIterations), "max_iterations");
  EXPECT_STREQ(to_string(PoseStatus::kDegenerate), "degenerate");
  EXPECT_STREQ(to_string(PoseStatus::kNoPointsInFront), "no_points_in_front");
}

}  // namespace
}  // namespace vantage
