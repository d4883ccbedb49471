// The tracker objective of place_markers() (docs/math.md §21, "Objectives") against an
// enumeration of every K-subset scored by `vantage tre`'s own report (tracker::tre_report on the
// subset as a layout), with coverage counted independently from the cones.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "support/message_of.h"
#include "support/placement_sites.h"
#include "support/sanitized.h"
#include "vantage/analysis/common.h"
#include "vantage/design/placement.h"
#include "vantage/tracker/tre_report.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/workspace_lattice.h"

namespace vantage::design {
namespace {

using testing::as_problem;
using testing::box_sites;
using ::testing::HasSubstr;
using testing::message_of;
using testing::subset;

constexpr unsigned kSeed = 20261205;
constexpr int kCoverageSamples = 2000;
// Both sides run §23's search, each certified to 1e-6 of an attained value; the two problems are
// built by different paths (the cone cosines may differ in the last bit), so their bounds agree
// to twice that.
constexpr double kCertified = 2e-6;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Every workspace direction of the coverage lattice sees min_visible markers of `layout` inside
// their cones (no body: the cones decide).
bool covers_everything(const Layout& layout) {
  const double cos_workspace = std::cos(layout.workspace->half_angle_deg * kPi / 180.0);
  const Eigen::Matrix3Xd lattice =
      visibility::workspace_lattice(visibility::Workspace{layout.workspace->axis, cos_workspace},
                                    kCoverageSamples)
          .directions;
  for (Eigen::Index d = 0; d < lattice.cols(); ++d) {
    const Eigen::Vector3d a = lattice.col(d);
    int seen = 0;
    for (Eigen::Index i = 0; i < layout.entries.cols(); ++i) {
      const double cone = layout.visibility->cone_half_angle_deg(i) * kPi / 180.0;
      if (layout.visibility->normals.col(i).dot(a) >= std::cos(cone)) ++seen;
    }
    if (seen < layout.visibility->min_visible) return false;
  }
  return true;
}

// What `vantage tre` reports of a subset: the largest worst.rms_bound over the targets (+inf
// when the subset does not cover the workspace or tracks a target nowhere).
double tre_value(const Layout& sites, const std::vector<int>& chosen,
                 const std::vector<Eigen::Vector3d>& targets, const tracker::FleModel& fle) {
  const Layout layout = subset(sites, chosen);
  if (!covers_everything(layout)) return kInfinity;
  tracker::TreOptions options;
  options.fle = fle;
  const tracker::TreReport report = tracker::tre_report(layout, targets, options);
  double out = 0.0;
  for (const tracker::TreTargetReport& t : report.targets) {
    if (t.extremes.worst.status != tracker::TreExtreme::Status::kCertified) return kInfinity;
    out = std::max(out, t.extremes.worst.rms_bound);
  }
  return out;
}

// Every K-subset, lexicographic; the first of the least value.
testing::BestSubset enumerate(const Layout& sites, int k,
                              const std::vector<Eigen::Vector3d>& targets,
                              const tracker::FleModel& fle) {
  return testing::enumerate_subsets(
      static_cast<int>(sites.entries.cols()), k,
      [&](const std::vector<int>& chosen) { return tre_value(sites, chosen, targets, fle); });
}

PlaceOptions tracker_place_options(const std::vector<Eigen::Vector3d>& targets,
                                   const tracker::FleModel& fle) {
  PlaceOptions options;
  options.random_trials = 50;
  options.min_coverage = 1.0;
  options.coverage_samples = kCoverageSamples;
  TrackerObjective tracker;
  tracker.targets = targets;
  tracker.fle = fle;
  options.tracker = tracker;
  return options;
}

TEST(PlaceTracker, FindsTheExhaustiveOptimum) {
  const Layout sites = box_sites(10, kSeed);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  const std::vector<Eigen::Vector3d> targets = {Eigen::Vector3d(0.0, 0.0, -1.5)};
  const tracker::FleModel fle = tracker::FleModel::isotropic(0.25);
  const testing::BestSubset truth = enumerate(sites, 4, targets, fle);
  ASSERT_TRUE(std::isfinite(truth.value));
  const PlacementResult result = place_markers(problem, tracker_place_options(targets, fle));
  EXPECT_EQ(result.search, "exhaustive");
  EXPECT_EQ(result.status, PlacementResult::Status::kComplete);
  EXPECT_NEAR(result.value.objective, truth.value, kCertified * truth.value);
  EXPECT_NEAR(tre_value(sites, result.chosen, targets, fle), truth.value, kCertified * truth.value);
}

TEST(PlaceTracker, TwoTargetsAndAnAnisotropicFleGreedyAgainstTheOptimum) {
  // 14 sites, K = 5 (2 002 subsets; under the sanitizers 11 sites, 462 subsets): greedy and
  // swaps alone, against the enumeration.
  constexpr double kGreedyGap = 0.10;
  const Layout sites = box_sites(testing::kUnderSanitizer ? 11 : 14, kSeed + 1);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 5;
  const std::vector<Eigen::Vector3d> targets = {Eigen::Vector3d(0.0, 0.0, -1.5),
                                                Eigen::Vector3d(2.0, 0.0, 0.0)};
  tracker::FleModel fle;
  fle.sigma_perp = 0.1;
  fle.sigma_axial = 0.3;
  PlaceOptions options = tracker_place_options(targets, fle);
  options.exhaustive_limit = 0;
  const PlacementResult result = place_markers(problem, options);
  const testing::BestSubset truth = enumerate(sites, 5, targets, fle);
  ASSERT_TRUE(std::isfinite(truth.value));
  EXPECT_EQ(result.search, "greedy+swap");
  EXPECT_GE(result.value.objective, truth.value * (1.0 - kCertified));
  EXPECT_LE(result.value.objective, truth.value * (1.0 + kGreedyGap));
  std::cout << "[ gap      ] tracker, " << sites.entries.cols() << " sites, K 5: greedy+swap "
            << result.value.objective << ", optimum " << truth.value << "\n";
}

TEST(PlaceTracker, PrefersSpreadMarkersWhereTheAffineBoundCannotTell) {
  // A 1 cm square (at the large one's centre) and a 1 m square of the same shape, all facing +z:
  // the affine bound is scale-free and ties them; the TRE of a target 0.5 m below prefers the large
  // one.
  Layout sites;
  sites.mode = LayoutMode::kPoints;
  sites.entries.resize(3, 8);
  const double corners[4][2] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.7}, {0.0, 0.7}};
  for (int i = 0; i < 4; ++i) {
    sites.entries.col(i) =
        Eigen::Vector3d(0.5 + 0.01 * corners[i][0], 0.35 + 0.01 * corners[i][1], 0.0);
    sites.entries.col(4 + i) = Eigen::Vector3d(corners[i][0], corners[i][1], 0.0);
  }
  sites.weights = Eigen::VectorXd::Ones(8);
  MarkerVisibility v;
  v.normals = Eigen::Matrix3Xd::Zero(3, 8);
  v.normals.row(2).setOnes();
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(8, 80.0);
  sites.visibility = v;
  sites.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 50.0};
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  const std::vector<Eigen::Vector3d> targets = {Eigen::Vector3d(0.5, 0.35, -0.5)};
  const PlacementResult result =
      place_markers(problem, tracker_place_options(targets, tracker::FleModel::isotropic(0.001)));
  EXPECT_EQ(result.chosen, (std::vector<int>{4, 5, 6, 7}));
}

TEST(PlaceTracker, IsTheSameForEveryThreadCount) {
  const Layout sites = box_sites(24, kSeed + 2);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 6;
  PlaceOptions one =
      tracker_place_options({Eigen::Vector3d(0.0, 0.0, -1.0)}, tracker::FleModel::isotropic(0.2));
  one.threads = 1;
  PlaceOptions two = one;
  two.threads = 2;
  const PlacementResult a = place_markers(problem, one);
  const PlacementResult b = place_markers(problem, two);
  EXPECT_EQ(a.chosen, b.chosen);
  EXPECT_EQ(a.value.objective, b.value.objective);
}

TEST(PlaceTracker, BadOptionsNameTheirField) {
  const Layout sites = box_sites(8, kSeed + 3);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  PlaceOptions no_target = tracker_place_options({}, tracker::FleModel::isotropic(0.2));
  EXPECT_THAT(message_of([&] { place_markers(problem, no_target); }), HasSubstr("tracker.targets"));
  PlaceOptions bad_fle =
      tracker_place_options({Eigen::Vector3d::Zero()}, tracker::FleModel::isotropic(0.2));
  bad_fle.tracker->fle.sigma_axial = -1.0;
  EXPECT_THAT(message_of([&] { place_markers(problem, bad_fle); }), HasSubstr("tracker.fle"));
  PlaceOptions infinite = tracker_place_options({Eigen::Vector3d(kInfinity, 0.0, 0.0)},
                                                tracker::FleModel::isotropic(0.2));
  EXPECT_THAT(message_of([&] { place_markers(problem, infinite); }), HasSubstr("tracker.targets"));
  PlaceOptions both =
      tracker_place_options({Eigen::Vector3d::Zero()}, tracker::FleModel::isotropic(0.2));
  both.camera = CameraObjective{};
  EXPECT_THAT(message_of([&] { place_markers(problem, both); }), HasSubstr("tracker"));
}

}  // namespace
}  // namespace vantage::design
