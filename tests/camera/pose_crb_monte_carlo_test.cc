// Monte Carlo truth for the pose CRB (docs/math.md §22): at S = 0.1 px the perspective (pinhole
// maximum-likelihood) estimator is efficient, so its RMS rotation angle and RMS translation
// error over 10 000 noisy images equal the bound within 5 %, on three layouts.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/analysis/refined_pose.h"
#include "vantage/camera/pose_crb.h"

namespace vantage::camera {
namespace {

using testing::kSeed;

constexpr int kTrials = 10000;
constexpr double kNoisePx = 0.1;
// The agreement. The sampling error of an RMS over 10 000 trials is about
// sqrt(1 / (2 N_eff)) <= 1 % (N_eff >= N / 3 for a 3-D error), so 5 % is beyond 5 sigma.
constexpr double kAgreement = 0.05;

struct Measured {
  double rot_rms_deg = 0.0;
  double trans_rms = 0.0;
  int failures = 0;
};

Measured monte_carlo(const PoseCrbModel& model, const PoseCrbAt& at, std::mt19937& rng,
                     int trials = kTrials) {
  const PoseCrbOptions& o = model.options();
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  model.camera_pose(at.direction, o.distance, &R, &p);
  const Eigen::Matrix2Xd all = model.project(at.direction, o.distance);
  const auto n = static_cast<Eigen::Index>(at.visible_markers.size());
  Eigen::Matrix3Xd points(3, n);
  Eigen::Matrix2Xd image(2, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    points.col(k) = model.points().col(at.visible_markers[k]);
    image.col(k) = all.col(at.visible_markers[k]);
  }
  RefinedPoseOptions options;
  options.camera.focal_length = o.focal_length;
  options.camera.principal_point = o.principal_point;
  std::normal_distribution<double> noise(0.0, o.noise_px);
  double rot2 = 0.0, trans2 = 0.0;
  Measured m;
  for (int trial = 0; trial < trials; ++trial) {
    Eigen::Matrix2Xd noisy = image;
    for (Eigen::Index k = 0; k < noisy.size(); ++k) noisy(k) += noise(rng);
    const RefinedPoseResult r = perspective_pose(points, noisy, {}, options);
    if (r.status != PoseStatus::kOk) ++m.failures;
    const double angle = Eigen::AngleAxisd(r.R_camera_object * R.transpose()).angle();
    rot2 += angle * angle;
    trans2 += (r.p_camera_object - p).squaredNorm();
  }
  m.rot_rms_deg = std::sqrt(rot2 / trials) * kDegreesPerRadian;
  m.trans_rms = std::sqrt(trans2 / trials);
  return m;
}

Layout points_layout(const Eigen::Matrix3Xd& points) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries = points;
  layout.weights = Eigen::VectorXd::Ones(points.cols());
  return layout;
}

struct Case {
  const char* name;
  Layout layout;
  double distance;
  Eigen::Vector3d direction;
};

std::vector<Case> cases() {
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  Eigen::Matrix3Xd cloud(3, 8);
  for (Eigen::Index i = 0; i < cloud.cols(); ++i) cloud.col(i) << u(rng), u(rng), u(rng);
  Eigen::Matrix3Xd board(3, 16);  // a planar 4 x 4 grid, 0.1 apart
  for (int i = 0; i < 16; ++i) board.col(i) << 0.1 * (i % 4), 0.1 * (i / 4), 0.0;
  Eigen::Matrix3Xd tetra(3, 4);  // the minimal non-planar layout
  tetra << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  return {{"cloud of 8 at 3", points_layout(cloud), 3.0, Eigen::Vector3d(0.2, -0.4, 0.9)},
          {"planar board at 1", points_layout(board), 1.0, Eigen::Vector3d(0.3, 0.2, 1.0)},
          {"tetrahedron at 4", points_layout(tetra), 4.0, Eigen::Vector3d(1.0, 0.8, 0.6)}};
}

TEST(PoseCrbMonteCarlo, PerspectiveEstimatorReachesTheBoundAtSmallNoise) {
  std::mt19937 rng(kSeed + 7);
  int checked = 0;
  for (const Case& c : cases()) {
    PoseCrbOptions o;
    o.distance = c.distance;
    o.focal_length = 900.0;
    o.principal_point = {640.0, 360.0};
    o.noise_px = kNoisePx;
    const PoseCrbModel model(c.layout, o);
    const PoseCrbAt at = model.at(c.direction);
    ASSERT_TRUE(at.trackable) << c.name;
    const Measured m = monte_carlo(model, at, rng);
    EXPECT_EQ(m.failures, 0) << c.name;
    EXPECT_NEAR(m.rot_rms_deg / at.rot_rms_deg, 1.0, kAgreement)
        << c.name << ": measured " << m.rot_rms_deg << " deg, bound " << at.rot_rms_deg;
    EXPECT_NEAR(m.trans_rms / at.trans_rms, 1.0, kAgreement)
        << c.name << ": measured " << m.trans_rms << ", bound " << at.trans_rms;
    RecordProperty(std::string(c.name) + " rot ratio",
                   std::to_string(m.rot_rms_deg / at.rot_rms_deg));
    RecordProperty(std::string(c.name) + " trans ratio",
                   std::to_string(m.trans_rms / at.trans_rms));
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

// Where the bound stops describing the estimator (docs/math.md §22, "Monte Carlo"): the measured
// RMS over the bound at growing noise, recorded for the docs; the bound is a small-noise
// statement, so the departure at 0.1 px is below kAgreement and at the largest noise it is
// larger than at 0.1 px on at least one layout (a control that the measurement can depart).
TEST(PoseCrbMonteCarlo, DepartsFromTheBoundAtLargeNoise) {
  constexpr int kDepartureTrials = 2000;
  const double noises[] = {0.1, 1.0, 3.0, 10.0};
  std::mt19937 rng(kSeed + 8);
  int grew = 0;
  for (const Case& c : cases()) {
    double first = 0.0, last = 0.0;
    for (double noise : noises) {
      PoseCrbOptions o;
      o.distance = c.distance;
      o.focal_length = 900.0;
      o.noise_px = noise;
      const PoseCrbModel model(c.layout, o);
      const PoseCrbAt at = model.at(c.direction);
      const Measured m = monte_carlo(model, at, rng, kDepartureTrials);
      const double departure = std::abs(m.rot_rms_deg / at.rot_rms_deg - 1.0);
      RecordProperty(std::string(c.name) + " S=" + std::to_string(noise),
                     "rot " + std::to_string(m.rot_rms_deg / at.rot_rms_deg) + " trans " +
                         std::to_string(m.trans_rms / at.trans_rms) + " failures " +
                         std::to_string(m.failures) + " bound_deg " +
                         std::to_string(at.rot_rms_deg));
      if (noise == noises[0]) first = departure;
      last = departure;
    }
    EXPECT_LT(first, 2 * kAgreement) << c.name;
    grew += last > first;
  }
  EXPECT_GT(grew, 0);
}

}  // namespace
}  // namespace vantage::camera
