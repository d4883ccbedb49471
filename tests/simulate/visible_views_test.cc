#include "vantage/simulate/visible_views.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "support/eigen_testing.h"
#include "support/sanitized.h"
#include "vantage/analysis/common.h"
#include "vantage/io/layout_formats.h"
#include "vantage/simulate/layout_simulation.h"
#include "vantage/simulate/visibility_check.h"

namespace vantage::simulate {
namespace {

// Rotations and projections of unit-size data, evaluated twice in different orders.
constexpr double kRounding = 1e-12;
// A measured angle may exceed asin t(a) where t(a) is tiny by the rounding Eq. (26) allows
// there: up to ~1e-8 rad for a vector in the image plane (bound_check.h).
constexpr double kNearImagePlaneRad = 1e-7;
// Two non-parallel unit vectors: |u x w| above this (the model's collinearity test uses a
// tighter one; the layouts here have no near-collinear visible triples).
constexpr double kNotParallel = 1e-6;
constexpr double kConeDeg = 70.0;

/// A box [-1, 1]^3 with three markers on each face, outward normals, cones of `cone_deg` (below
/// 54.7 degrees the directions near the corners see no face: not all trackable).
Layout box_layout(double cone_deg = kConeDeg) {
  const double offsets[3][2] = {{0.5, 0.3}, {-0.4, 0.5}, {0.1, -0.6}};
  Layout layout;
  layout.name = "box";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 18);
  MarkerVisibility visibility;
  visibility.normals.resize(3, 18);
  int k = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      for (const auto& o : offsets) {
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        p(axis) = sign;
        p((axis + 1) % 3) = o[0];
        p((axis + 2) % 3) = o[1];
        layout.entries.col(k) = p;
        visibility.normals.col(k) = sign * Eigen::Vector3d::Unit(axis);
        ++k;
      }
    }
  }
  layout.weights = Eigen::VectorXd::Ones(18);
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(18, cone_deg);
  layout.visibility = visibility;
  return layout;
}

Layout satellite_layout() {
  return io::load_layout(
      (std::filesystem::path(VANTAGE_SOURCE_DIR) / "examples/layouts/satellite.json").string());
}

/// The cone test, written out: marker i is in its cone from a iff n_i.a >= cos(theta_i).
std::vector<int> in_cones(const Layout& layout, const Eigen::Vector3d& a) {
  std::vector<int> out;
  const MarkerVisibility& v = *layout.visibility;
  for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
    if (v.normals.col(i).dot(a) >= std::cos(v.cone_half_angle_deg(i) / kDegreesPerRadian)) {
      out.push_back(static_cast<int>(i));
    }
  }
  return out;
}

/// At least 3 markers and two independent directions among them.
bool not_collinear(const Layout& layout, const std::vector<int>& visible) {
  if (visible.size() < 3) return false;
  const Eigen::Vector3d p0 = layout.entries.col(visible[0]);
  const Eigen::Vector3d u = (layout.entries.col(visible[1]) - p0).normalized();
  for (std::size_t k = 2; k < visible.size(); ++k) {
    if (u.cross((layout.entries.col(visible[k]) - p0).normalized()).norm() > kNotParallel) {
      return true;
    }
  }
  return false;
}

/// min |a.u_ij| over the visible pairs, by brute force.
double brute_t(const Layout& layout, const std::vector<int>& visible, const Eigen::Vector3d& a) {
  double t = 1.0;
  for (std::size_t x = 0; x < visible.size(); ++x) {
    for (std::size_t y = x + 1; y < visible.size(); ++y) {
      const Eigen::Vector3d u =
          (layout.entries.col(visible[y]) - layout.entries.col(visible[x])).normalized();
      t = std::min(t, std::abs(a.dot(u)));
    }
  }
  return t;
}

TEST(VisibleViews, EveryDrawnViewIsTrackableAndTheImageHoldsExactlyItsVisibleMarkers) {
  constexpr double kNarrowConeDeg = 45.0;
  for (const bool cap : {false, true}) {
    for (const double cone : {kConeDeg, kNarrowConeDeg}) {
      Layout layout = box_layout(cone);
      LayoutWorkspace workspace;
      workspace.axis = Eigen::Vector3d(1.0, 1.0, 2.0).normalized();
      workspace.half_angle_deg = 40.0;
      if (cap) layout.workspace = workspace;
      const VisibleViews views(layout);
      LayoutSceneOptions options;
      options.noise_px = 0.0;
      long accepted = 0;
      long rejected = 0;
      for (long trial = 0; trial < 400; ++trial) {
        TrialRandom random = TrialRandom::for_trial(testing::kSeed, trial);
        const VisibleScenes s = views.scenes(layout.entries, options, random);
        const Eigen::Vector3d& a = s.view.direction;
        ASSERT_NEAR(a.norm(), 1.0, kRounding);
        const std::vector<int> visible = in_cones(layout, a);
        ASSERT_EQ(s.view.visibility.visible, visible) << "trial " << trial;
        ASSERT_TRUE(not_collinear(layout, visible)) << "trial " << trial;
        if (cap) {
          ASSERT_GE(a.dot(workspace.axis), std::cos(workspace.half_angle_deg / kDegreesPerRadian));
        }
        ASSERT_GE(s.view.draws, 1);
        rejected += s.view.draws - 1;
        // The camera looks along -a: the third row of R is the optical axis.
        EXPECT_EIGEN_NEAR(s.visible.R_true.row(2).transpose(), -a, kRounding);
        EXPECT_EIGEN_NEAR(s.whole.R_true, s.visible.R_true, 0.0);
        ASSERT_EQ(s.visible.model.cols(), static_cast<Eigen::Index>(visible.size()));
        ASSERT_EQ(s.visible.image.cols(), s.visible.model.cols());
        for (std::size_t k = 0; k < visible.size(); ++k) {
          const Eigen::Index c = static_cast<Eigen::Index>(k);
          EXPECT_EIGEN_NEAR(s.visible.model.col(c), layout.entries.col(visible[k]), 0.0);
          // The scaled orthographic image of that marker (Eq. 14), placed as the whole layout is:
          // the depth is 10 sizes of the whole box, no offset.
          const double depth = options.range * layout.entries.colwise().norm().maxCoeff();
          const Eigen::Vector3d x =
              s.visible.R_true * layout.entries.col(visible[k]) + Eigen::Vector3d(0.0, 0.0, depth);
          const Eigen::Vector2d q = x.head<2>() / (depth / options.focal_px);
          EXPECT_EIGEN_NEAR(s.visible.image_clean.col(c), q, kRounding * (1.0 + q.norm()));
        }
        accepted += 1;
      }
      EXPECT_EQ(accepted, 400);
      if (cone == kNarrowConeDeg && !cap) {
        EXPECT_GT(rejected, 0) << "some directions are lost";
      }
    }
  }
}

TEST(VisibleViews, MonteCarloNeverExceedsThePerViewBoundOrTheCertificate) {
  // 3000 views each (600 under the sanitizers, where every view's brute-force check is slow).
  const int views = testing::kUnderSanitizer ? 600 : 3000;
  for (const Layout& layout : {box_layout(), satellite_layout()}) {
    LayoutSimulationOptions options;
    options.monte_carlo.trials = views;
    options.monte_carlo.seed = testing::kSeed;
    options.monte_carlo.keep_trials = true;
    options.methods = {"affine"};
    options.scene.noise_px = 0.5;  // the estimators' images; the checks use the noise-free ones
    const LayoutSimulation run = simulate_layout(layout, options);
    ASSERT_TRUE(run.has_visibility);
    const VisibilityCheck& check = run.visibility;
    EXPECT_TRUE(check.passed) << layout.name << ": " << check.message;
    EXPECT_TRUE(run.bound.passed) << layout.name << ": " << run.bound.message;
    ASSERT_EQ(run.visibility_trials.size(), static_cast<std::size_t>(views));
    const bool with_body = layout.visibility->body.has_value();
    for (std::size_t k = 0; k < run.visibility_trials.size(); ++k) {
      const VisibilityTrial& trial = run.visibility_trials[k];
      const std::vector<int> cones = in_cones(layout, trial.direction);
      if (with_body) {  // the body can only hide markers of their cones
        EXPECT_TRUE(
            std::includes(cones.begin(), cones.end(), trial.visible.begin(), trial.visible.end()))
            << layout.name << " trial " << k;
      } else {
        EXPECT_EQ(trial.visible, cones) << layout.name << " trial " << k;
      }
      ASSERT_TRUE(not_collinear(layout, trial.visible)) << layout.name << " trial " << k;
      const double t = brute_t(layout, trial.visible, trial.direction);
      EXPECT_NEAR(trial.t, t, kRounding);
      EXPECT_LE(trial.max_error_rad, std::asin(t) + kNearImagePlaneRad)
          << layout.name << " trial " << k;
      EXPECT_LE(t, check.setup.t_upper + kRounding) << layout.name << " trial " << k;
    }
    EXPECT_LE(check.max_ratio, 1.0 + kBoundRatioTolerance) << layout.name;
    EXPECT_GE(check.visible_markers.median, 3.0);
    EXPECT_GE(check.draws, check.trials);
  }
}

TEST(VisibleViews, TheWorstViewpointReachesTheCertifiedBound) {
  // At the certified worst viewpoint under visibility the limiting visible vector's error is
  // asin(t_lower), the bound asin(t_upper): the certificate tolerance (1e-9) apart.
  constexpr double kAtWorstViewpoint = 1e-6;
  for (const Layout& layout : {box_layout(), satellite_layout()}) {
    LayoutSimulationOptions options;
    options.monte_carlo.trials = 20;
    options.worst_viewpoint = true;
    options.methods = {"affine"};
    const LayoutSimulation run = simulate_layout(layout, options);
    EXPECT_NEAR(run.visibility.max_ratio, 1.0, kAtWorstViewpoint) << layout.name;
    EXPECT_EQ(run.visibility.draws, 0);
    EXPECT_TRUE(run.visibility.passed) << run.visibility.message;
  }
}

TEST(VisibleViews, ATinyTrackableFractionIsAClearErrorNotAHang) {
  // Three markers sharing one normal with cones of 1 degree: trackable on a cap of 1 degree,
  // (1 - cos 1 deg) / 2 = 7.6e-5 of the sphere, below kMinTrackableFraction.
  constexpr double kBounded = 30.0;  // seconds: the refusal costs one coverage estimate
  Layout layout;
  layout.name = "narrow";
  layout.mode = LayoutMode::kPoints;
  layout.entries = (Eigen::Matrix3Xd(3, 3) << 0, 1, 0, 0, 0, 1, 0, 0, 0).finished();
  layout.weights = Eigen::VectorXd::Ones(3);
  MarkerVisibility visibility;
  visibility.normals = Eigen::Vector3d::UnitZ().replicate(1, 3);
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(3, 1.0);
  layout.visibility = visibility;
  const auto start = std::chrono::steady_clock::now();
  try {
    VisibleViews views(layout);
    FAIL() << "a trackable fraction of 7.6e-5 was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "visibility");
    EXPECT_THAT(e.what(), ::testing::HasSubstr("trackable"));
  }
  // None at all: a workspace facing away from every marker.
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(3, 30.0);
  layout.visibility = visibility;
  layout.workspace = LayoutWorkspace{-Eigen::Vector3d::UnitZ(), 20.0};
  try {
    VisibleViews views(layout);
    FAIL() << "an untrackable workspace was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "visibility");
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no direction"));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, kBounded);
}

TEST(VisibleViews, AFixedViewpointMustBeTrackable) {
  const Layout layout = box_layout();
  LayoutSimulationOptions options;
  options.monte_carlo.trials = 5;
  // From a = (0, 0, 1) (the camera looks along -z): the top face's three markers: trackable.
  options.scene.viewpoint = -Eigen::Vector3d::UnitZ();
  EXPECT_TRUE(simulate_layout(layout, options).visibility.passed);
  // From between two faces, 45 degrees from both normals: no cone of 30 degrees reaches it.
  Layout narrow = layout;
  narrow.visibility->cone_half_angle_deg.setConstant(30.0);
  options.scene.viewpoint = -Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  EXPECT_THROW(simulate_layout(narrow, options), InvalidArgument);
}

// The pinhole camera sees each marker by its own line of sight to its centre c (docs/math.md §22),
// not by the common direction a. From a 25 degrees below the horizontal towards +x, direction a
// sees the +x and -z faces (n.a = 0.91 and 0.42 against cos 70 = 0.34); the camera 1.5 sizes
// from the origin has c_z = -0.75, above the -z face's plane, so it sees the +x face only. Each
// visible set equals the cone test written out.
TEST(VisibleViews, ThePinholeCameraSeesEachMarkerByItsOwnLineOfSight) {
  const Layout layout = box_layout();
  const double below = 25.0 / kDegreesPerRadian;
  const Eigen::Vector3d a(std::cos(below), 0.0, -std::sin(below));
  VisibleViews views(layout);
  views.look_from(a, "a");
  LayoutSceneOptions options;
  options.range = 1.5;
  options.camera = CameraModel::kAffine;
  TrialRandom random = TrialRandom::for_trial(testing::kSeed, 0);
  const VisibleScenes affine = views.scenes(layout.entries, options, random);
  EXPECT_EQ(affine.view.visibility.visible, in_cones(layout, a));
  options.camera = CameraModel::kPinhole;
  random = TrialRandom::for_trial(testing::kSeed, 0);
  const VisibleScenes pinhole = views.scenes(layout.entries, options, random);
  // The centre, written out: the aim (the origin) plus range sizes along a.
  const double size = layout.entries.colwise().norm().maxCoeff();
  const Eigen::Vector3d c = 1.5 * size * a;
  EXPECT_LT((-pinhole.whole.R_true.transpose() * pinhole.whole.p_true - c).norm(), kRounding);
  std::vector<int> expected;
  const MarkerVisibility& v = *layout.visibility;
  for (int i = 0; i < 18; ++i) {
    const Eigen::Vector3d sight = (c - layout.entries.col(i)).normalized();
    if (v.normals.col(i).dot(sight) >= std::cos(v.cone_half_angle_deg(i) / kDegreesPerRadian)) {
      expected.push_back(i);
    }
  }
  EXPECT_EQ(pinhole.view.visibility.visible, expected);
  EXPECT_NE(pinhole.view.visibility.visible, affine.view.visibility.visible);
  EXPECT_EQ(pinhole.visible.model.cols(), static_cast<Eigen::Index>(expected.size()));
}

}  // namespace
}  // namespace vantage::simulate
