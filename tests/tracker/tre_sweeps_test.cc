// The TRE sweeps of `vantage plot --tre` (docs/math.md §23, "Sweeps and figures"): every value
// is the first-order RMS at the sweep's target and fixed line of sight, recomputed here from the
// geometry (centroid, tip axis, circles) and the visibility; along the tip axis RMS² is a
// parabola in s; Fitzpatrick's formula, from the principal axes, for isotropic FLE; the circles
// close; bad options name their field.

#include "vantage/tracker/tre_sweeps.h"
#include "vantage/analysis/common.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "support/message_of.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/visibility/visibility.h"

namespace vantage::tracker {
namespace {

// The sweep and the test evaluate the same formula at targets built by the same arithmetic up
// to the order of a few operations: a few roundings of the RMS.
constexpr double kTreSweepRecompute = 1e-12;
// Second differences of RMS² (values ~1) along 61 samples: cancellation of a few roundings of
// the largest value, times the 4 terms of the difference.
constexpr double kTreSweepParabola = 1e-10;
constexpr std::uint32_t kTreSweepSeed = 20;

Layout tre_sweep_layout(const Eigen::Matrix3Xd& points) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries = points;
  layout.weights = Eigen::VectorXd::Ones(points.cols());
  return layout;
}

// An NDI-like plate of four markers facing +z with 90-degree cones (examples/tools/ndi_like).
Layout tre_sweep_plate() {
  Eigen::Matrix3Xd points(3, 4);
  points << -30, 35, 25, -30, -28, -20, 40, 8, 0, 0, 0, 0;
  Layout layout = tre_sweep_layout(points);
  MarkerVisibility visibility;
  visibility.normals = Eigen::Matrix3Xd::Zero(3, 4);
  visibility.normals.row(2).setOnes();
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(4, 90.0);
  layout.visibility = visibility;
  return layout;
}

// RMS at target r from line of sight a, straight from the visibility and Eq. (23.2).
double tre_sweep_truth(const Layout& layout, const TreModel& model, const Eigen::Vector3d& r,
                       const Eigen::Vector3d& a, const FleModel& fle) {
  const visibility::DirectionVisibility seen = visibility::direction_visibility(model.problem(), a);
  EXPECT_TRUE(seen.trackable);
  return std::sqrt(tre_covariance(layout.entries, seen.visible, r, fle, a).trace());
}

// Fitzpatrick, West & Maurer (1998), Eq. (23.3), from the principal axes of the markers.
double tre_sweep_fitzpatrick(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& r,
                             double fle_rms) {
  const Eigen::Vector3d g = points.rowwise().mean();
  const Eigen::Matrix3Xd q = points.colwise() - g;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(q * q.transpose());
  const double n = static_cast<double>(points.cols());
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = axes.eigenvectors().col(k);
    const double f2 = (q.colwise().squaredNorm().array() - (axis.transpose() * q).array().square())
                          .mean();  // mean squared distance of the markers from axis k
    const Eigen::Vector3d d = r - g;
    const double d2 = d.squaredNorm() - std::pow(axis.dot(d), 2);
    sum += d2 / f2;
  }
  return fle_rms * std::sqrt((1.0 + sum / 3.0) / n);
}

TEST(TreSweeps, TipAxisIsTheRmsAtTheCentroidThroughTheTargetAtEachDirection) {
  const Layout layout = tre_sweep_plate();
  const FleModel fle{0.0995, 0.2985};
  const TreModel model(layout, fle);
  TreOptions options;
  options.fle = fle;
  options.direction = Eigen::Vector3d(0.3, 0.0, 1.0);
  const Eigen::Vector3d target(5.0, -3.0, -150.0);
  const TreSweeps sweeps = tre_sweeps(model, {target}, options);
  const TreTipAxisSweep& tip = sweeps.tip_axis;
  const Eigen::Vector3d g = layout.entries.rowwise().mean();
  const double d1 = (target - g).norm();
  EXPECT_NEAR(tip.target_distance, d1, kTreSweepRecompute * d1);
  ASSERT_EQ(tip.distance.size(), 61u);
  EXPECT_EQ(tip.distance.front(), 0.0);
  EXPECT_NEAR(tip.distance.back(), 1.5 * d1, kTreSweepRecompute * d1);
  ASSERT_EQ(tip.curves.size(), 3u);
  EXPECT_EQ(tip.curves[0].label, "worst");
  EXPECT_EQ(tip.curves[1].label, "best");
  EXPECT_EQ(tip.curves[2].label, "direction");
  EXPECT_TRUE(tip.rms_isotropic.empty());  // anisotropic FLE: no classic formula
  const TreTargetReport& report = sweeps.report.targets.front();
  EXPECT_EQ(tip.curves[0].direction, report.extremes.worst.direction);
  EXPECT_EQ(tip.curves[1].direction, report.extremes.best.direction);
  for (const TreCurve& curve : tip.curves) {
    SCOPED_TRACE(curve.label);
    ASSERT_TRUE(curve.tracked);
    ASSERT_EQ(curve.rms.size(), tip.distance.size());
    for (std::size_t k = 0; k < tip.distance.size(); ++k) {
      const Eigen::Vector3d r = g + tip.distance[k] * (target - g) / d1;
      const double truth = tre_sweep_truth(layout, model, r, curve.direction, fle);
      EXPECT_NEAR(curve.rms[k], truth, kTreSweepRecompute * truth) << k;
    }
    // RMS² is a quadratic polynomial in s (docs/math.md §23): constant second differences.
    const double second =
        curve.rms[2] * curve.rms[2] - 2 * curve.rms[1] * curve.rms[1] + curve.rms[0] * curve.rms[0];
    const double scale = curve.rms.back() * curve.rms.back();
    for (std::size_t k = 1; k + 1 < curve.rms.size(); ++k) {
      const double d2 = curve.rms[k + 1] * curve.rms[k + 1] - 2 * curve.rms[k] * curve.rms[k] +
                        curve.rms[k - 1] * curve.rms[k - 1];
      EXPECT_NEAR(d2, second, kTreSweepParabola * scale) << k;
    }
  }
  // The worst curve at the first target is the report's worst.
  const double at_target = tre_sweep_truth(layout, model, target, tip.curves[0].direction, fle);
  EXPECT_NEAR(at_target, report.extremes.worst.rms, kTreSweepRecompute * at_target);
}

TEST(TreSweeps, PolarCirclesAboutEachAxisAtTheWorstDirection) {
  const Layout layout = tre_sweep_plate();
  const FleModel fle{0.0995, 0.2985};
  const TreModel model(layout, fle);
  TreOptions options;
  options.fle = fle;
  const Eigen::Vector3d target(0.0, 0.0, -150.0);
  TreSweepOptions sweep;
  sweep.polar_step_deg = 5;
  const TreSweeps sweeps = tre_sweeps(model, {target}, options, sweep);
  const TrePolarSweep& polar = sweeps.polar;
  const Eigen::Vector3d g = layout.entries.rowwise().mean();
  const double radius = (target - g).norm();  // the default: D1
  EXPECT_NEAR(polar.radius, radius, kTreSweepRecompute * radius);
  ASSERT_EQ(polar.angle_deg.size(), 73u);
  const Eigen::Vector3d a = sweeps.report.targets.front().extremes.worst.direction;
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    const TreCurve& curve = polar.curves[static_cast<std::size_t>(axis)];
    ASSERT_TRUE(curve.tracked);
    EXPECT_EQ(curve.direction, a);
    ASSERT_EQ(curve.rms.size(), polar.angle_deg.size());
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    for (std::size_t k = 0; k < polar.angle_deg.size(); ++k) {
      const double t = polar.angle_deg[k] * kPi / 180.0;
      Eigen::Vector3d r = g;
      r[i] += radius * std::cos(t);
      r[j] += radius * std::sin(t);
      EXPECT_NEAR((r - g).norm(), radius, kTreSweepRecompute * radius);
      const double truth = tre_sweep_truth(layout, model, r, a, fle);
      EXPECT_NEAR(curve.rms[k], truth, kTreSweepRecompute * truth) << k;
    }
    EXPECT_NEAR(curve.rms.front(), curve.rms.back(), kTreSweepRecompute * curve.rms.front());
  }
  // The target lies at 270 degrees about x ((y, z) = R (cos, sin)) and 180 about y ((z, x)).
  const double at_target = sweeps.report.targets.front().extremes.worst.rms;
  EXPECT_NEAR(polar.curves[0].rms[270 / 5], at_target, kTreSweepRecompute * at_target);
  EXPECT_NEAR(polar.curves[1].rms[180 / 5], at_target, kTreSweepRecompute * at_target);
}

TEST(TreSweeps, IsotropicCurvesFollowFitzpatrickWithoutNormals) {
  std::mt19937 rng(kTreSweepSeed);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  Eigen::Matrix3Xd points(3, 6);
  for (Eigen::Index i = 0; i < points.cols(); ++i) points.col(i) << u(rng), u(rng), u(rng);
  const Layout layout = tre_sweep_layout(points);
  const FleModel fle = FleModel::isotropic(0.25);
  const TreModel model(layout, fle);
  TreOptions options;
  options.fle = fle;
  const Eigen::Vector3d target(20.0, 80.0, -120.0);
  TreSweepOptions sweep;
  sweep.radius = 90.0;
  sweep.polar_step_deg = 10;
  const TreSweeps sweeps = tre_sweeps(model, {target, Eigen::Vector3d(1, 2, 3)}, options, sweep);
  const TreTipAxisSweep& tip = sweeps.tip_axis;
  ASSERT_EQ(tip.rms_isotropic.size(), tip.distance.size());
  for (std::size_t k = 0; k < tip.distance.size(); ++k) {
    const double truth = tre_sweep_fitzpatrick(points, tip.target(k), 0.25);
    EXPECT_NEAR(tip.rms_isotropic[k], truth, 1e-9 * truth) << k;
    // Isotropic FLE, every marker seen: the curve at any direction is the formula.
    EXPECT_NEAR(tip.curves[0].rms[k], truth, 1e-9 * truth) << k;
  }
  EXPECT_EQ(sweeps.polar.radius, 90.0);
  for (int axis = 0; axis < 3; ++axis) {
    const auto& iso = sweeps.polar.rms_isotropic[static_cast<std::size_t>(axis)];
    ASSERT_EQ(iso.size(), 37u);
    for (std::size_t k = 0; k < iso.size(); ++k) {
      const Eigen::Vector3d r = sweeps.polar.target(axis, k);
      EXPECT_NEAR((r - tip.centroid).norm(), 90.0, 1e-12 * 90.0);
      const double truth = tre_sweep_fitzpatrick(points, r, 0.25);
      EXPECT_NEAR(iso[k], truth, 1e-9 * truth) << k;
    }
  }
}

TEST(TreSweeps, UntrackedDirectionGivesNoCurve) {
  const Layout layout = tre_sweep_plate();
  const FleModel fle{0.1, 0.3};
  const TreModel model(layout, fle);
  TreOptions options;
  options.fle = fle;
  options.direction = Eigen::Vector3d(0.0, 0.0, -1.0);  // behind the plate: nothing seen
  const TreSweeps sweeps = tre_sweeps(model, {Eigen::Vector3d(0, 0, -150)}, options);
  ASSERT_EQ(sweeps.tip_axis.curves.size(), 3u);
  const TreCurve& behind = sweeps.tip_axis.curves[2];
  EXPECT_FALSE(behind.tracked);
  EXPECT_TRUE(behind.rms.empty());
  EXPECT_TRUE(behind.visible_markers.empty());
  EXPECT_TRUE(sweeps.tip_axis.curves[0].tracked);
}

TEST(TreSweeps, BadInputNamesTheField) {
  const Layout layout = tre_sweep_plate();
  const FleModel fle{0.1, 0.3};
  const TreModel model(layout, fle);
  TreOptions options;
  options.fle = fle;
  const Eigen::Vector3d centroid = layout.entries.rowwise().mean();
  EXPECT_EQ(
      testing::message_of([&] { tre_sweeps(model, {centroid}, options); }).rfind("target[0]: ", 0),
      0u);
  const std::pair<const char*, TreSweepOptions> bad[] = {
      {"radius",
       [] {
         TreSweepOptions o;
         o.radius = -1.0;
         return o;
       }()},
      {"tip_axis_samples",
       [] {
         TreSweepOptions o;
         o.tip_axis_samples = 1;
         return o;
       }()},
      {"tip_axis_extent",
       [] {
         TreSweepOptions o;
         o.tip_axis_extent = std::nan("");
         return o;
       }()},
      {"polar_step_deg",
       [] {
         TreSweepOptions o;
         o.polar_step_deg = 7;
         return o;
       }()},
  };
  for (const auto& [field, sweep] : bad) {
    const std::string message = testing::message_of(
        [&, &s = sweep] { tre_sweeps(model, {Eigen::Vector3d(0, 0, -150)}, options, s); });
    EXPECT_EQ(message.rfind(std::string(field) + ": ", 0), 0u) << message;
  }
}

}  // namespace
}  // namespace vantage::tracker
