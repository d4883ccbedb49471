// The camera objective of place_markers() (docs/math.md §21, "Objectives") against an
// enumeration of every K-subset scored by `vantage crb`'s own model (camera::PoseCrbModel).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "support/message_of.h"
#include "support/placement_sites.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"
#include "vantage/visibility/workspace_lattice.h"

namespace vantage::design {
namespace {

using testing::as_problem;
using testing::box_sites;
using ::testing::HasSubstr;
using testing::message_of;
using testing::subset;

constexpr unsigned kSeed = 20261204;
// The lattice of the camera objective: small, so that the enumeration stays quick.
constexpr int kSamples = 600;
// Both sides evaluate the same Fisher information in the same marker order: they agree to
// rounding.
constexpr double kSameValue = 1e-12;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

camera::PoseCrbOptions camera_options(double distance = 6.0) {
  camera::PoseCrbOptions o;
  o.distance = distance;
  o.focal_length = 800.0;
  o.noise_px = 0.5;
  o.samples = kSamples;
  o.aim = Eigen::Vector3d(0.0, 0.0, 0.0);
  return o;
}

// The statistic of `vantage crb`'s samples of a subset, first order (docs/math.md §21: the
// search ranks past §22's 45 degree reporting limit too): +inf unless the first-order bound
// exists at every workspace direction of the lattice (min_coverage 1).
double crb_value(const Layout& sites, const std::vector<int>& chosen, CrbStatistic statistic,
                 double distance = 6.0) {
  const camera::PoseCrbModel model(subset(sites, chosen), camera_options(distance));
  const Eigen::Matrix3Xd lattice =
      visibility::workspace_lattice(model.workspace(), kSamples).directions;
  std::vector<double> values;
  for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
    EXPECT_TRUE(model.in_workspace(lattice.col(k)));
    const camera::PoseCrbAt at = model.at(lattice.col(k));
    if (!std::isfinite(at.first_order_rot_rms_deg)) return kInfinity;
    EXPECT_EQ(at.trackable, at.first_order_rot_rms_deg <= camera::PoseCrbAt::kMaxRotRmsDeg);
    values.push_back(at.first_order_rot_rms_deg);
  }
  std::sort(values.begin(), values.end());
  if (statistic == CrbStatistic::kWorst) return values.back();
  const double q = statistic == CrbStatistic::kP95 ? 0.95 : 0.5;
  const auto rank = static_cast<std::size_t>(std::max(1.0, std::ceil(q * values.size())));
  return values[rank - 1];
}

// Every K-subset, lexicographic; the first of the least value.
testing::BestSubset enumerate(const Layout& sites, int k, CrbStatistic statistic) {
  return testing::enumerate_subsets(
      static_cast<int>(sites.entries.cols()), k,
      [&](const std::vector<int>& chosen) { return crb_value(sites, chosen, statistic); });
}

PlaceOptions camera_place_options(const Layout& sites, CrbStatistic statistic) {
  PlaceOptions options;
  options.random_trials = 50;
  options.min_coverage = 1.0;
  CameraObjective camera;
  camera.sites = sites;
  camera.crb = camera_options();
  camera.statistic = statistic;
  options.camera = camera;
  return options;
}

TEST(PlaceCamera, FindsTheExhaustiveOptimumOfEachStatistic) {
  const Layout sites = box_sites(10, kSeed);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  for (CrbStatistic statistic : {CrbStatistic::kWorst, CrbStatistic::kP95, CrbStatistic::kMedian}) {
    SCOPED_TRACE(to_string(statistic));
    const testing::BestSubset truth = enumerate(sites, 4, statistic);
    ASSERT_TRUE(std::isfinite(truth.value));
    const PlacementResult result = place_markers(problem, camera_place_options(sites, statistic));
    EXPECT_EQ(result.search, "exhaustive");
    EXPECT_EQ(result.status, PlacementResult::Status::kComplete);
    EXPECT_NEAR(result.value.objective, truth.value, kSameValue * truth.value);
    EXPECT_NEAR(crb_value(sites, result.chosen, statistic), truth.value, kSameValue * truth.value);
  }
}

// An approach (docs/math.md §21, "An approach"): the value of a subset is the largest over the
// distances of its value at each distance alone, every distance covered; the enumeration scores
// each subset by `vantage crb`'s model once per distance.
TEST(PlaceCamera, AnApproachFindsTheExhaustiveOptimumOfTheLargestOverItsDistances) {
  const std::vector<double> distances = {6.0, 2.5, 12.0};
  const Layout sites = box_sites(10, kSeed + 3);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  for (CrbStatistic statistic : {CrbStatistic::kWorst, CrbStatistic::kMedian}) {
    SCOPED_TRACE(to_string(statistic));
    const auto approach_value = [&](const std::vector<int>& chosen) {
      double out = -kInfinity;
      for (double d : distances) out = std::max(out, crb_value(sites, chosen, statistic, d));
      return out;
    };
    const testing::BestSubset truth = testing::enumerate_subsets(10, 4, approach_value);
    ASSERT_TRUE(std::isfinite(truth.value));
    PlaceOptions options = camera_place_options(sites, statistic);
    options.camera->distances = distances;
    options.camera->crb.distance = 0.0;  // not used with an approach
    const PlacementResult result = place_markers(problem, options);
    EXPECT_EQ(result.search, "exhaustive");
    EXPECT_EQ(result.status, PlacementResult::Status::kComplete);
    EXPECT_NEAR(result.value.objective, truth.value, kSameValue * truth.value);
    EXPECT_NEAR(approach_value(result.chosen), truth.value, kSameValue * truth.value);
    // Not the single distance's answer: the approach changes what is best.
    EXPECT_GT(truth.value, enumerate(sites, 4, statistic).value);
  }
}

TEST(PlaceCamera, AnApproachDistanceInsideTheSitesIsRefused) {
  const Layout sites = box_sites(10, kSeed);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  PlaceOptions options = camera_place_options(sites, CrbStatistic::kWorst);
  options.camera->distances = {6.0, 0.5};
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }), HasSubstr("distance"));
  options.camera->distances = {6.0, -1.0};
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }), HasSubstr("camera.distances"));
  options.camera->distances = {6.0, 8.0, 6.0};
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }),
              HasSubstr("camera.distances: a distance repeats"));
  options.camera->distances.assign(CameraObjective::kMaxDistances + 1, 6.0);
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }),
              HasSubstr("camera.distances: at most 64"));
}

TEST(PlaceCamera, GreedyWithSwapsAgainstTheOptimum) {
  // 18 sites, K = 5 (8 568 subsets): greedy and swaps alone, against the enumeration.
  constexpr double kGreedyGap = 0.10;
  const Layout sites = box_sites(18, kSeed + 1);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 5;
  PlaceOptions options = camera_place_options(sites, CrbStatistic::kWorst);
  options.exhaustive_limit = 0;
  const PlacementResult result = place_markers(problem, options);
  const testing::BestSubset truth = enumerate(sites, 5, CrbStatistic::kWorst);
  EXPECT_EQ(result.search, "greedy+swap");
  // A greedy step of fewer markers than a direction must see has no value (+inf), not 1 degree.
  ASSERT_FALSE(result.steps.empty());
  for (const PlacementStep& step : result.steps) {
    if (step.k < 3) {
      EXPECT_EQ(step.value.objective, kInfinity) << step.k;
    }
  }
  EXPECT_GE(result.value.objective, truth.value * (1.0 - kSameValue));
  EXPECT_LE(result.value.objective, truth.value * (1.0 + kGreedyGap));
  std::cout << "[ gap      ] camera, 18 sites, K 5: greedy+swap " << result.value.objective
            << " deg, optimum " << truth.value << " deg\n";
}

TEST(PlaceCamera, IsTheSameForEveryThreadCount) {
  const Layout sites = box_sites(30, kSeed + 2);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 6;
  PlaceOptions one = camera_place_options(sites, CrbStatistic::kWorst);
  one.threads = 1;
  PlaceOptions two = one;
  two.threads = 2;
  const PlacementResult a = place_markers(problem, one);
  const PlacementResult b = place_markers(problem, two);
  EXPECT_EQ(a.chosen, b.chosen);
  EXPECT_EQ(a.value.objective, b.value.objective);
  EXPECT_EQ(a.random_baseline.best, b.random_baseline.best);
}

TEST(PlaceCamera, RejectsACameraWithoutAnAim) {
  const Layout sites = box_sites(10, kSeed);
  PlacementProblem problem;
  problem.sites = as_problem(sites);
  problem.markers = 4;
  PlaceOptions options = camera_place_options(sites, CrbStatistic::kWorst);
  options.camera->crb.aim.reset();
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }), HasSubstr("camera.aim"));
  options = camera_place_options(sites, CrbStatistic::kWorst);
  options.camera->crb.focal_length = -1.0;
  EXPECT_THAT(message_of([&] { place_markers(problem, options); }), HasSubstr("focal_length"));
}

}  // namespace
}  // namespace vantage::design
