// The camera objective of place_markers() (docs/math.md §21, "Objectives") against an
// enumeration of every K-subset scored by `vantage crb`'s own model (camera::PoseCrbModel).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "support/message_of.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"
#include "vantage/visibility/visibility.h"

namespace vantage::design {
namespace {

using ::testing::HasSubstr;
using testing::message_of;

constexpr unsigned kSeed = 20261204;
// The lattice of the camera objective: small, so that the enumeration stays quick.
constexpr int kSamples = 600;
// Both sides evaluate the same Fisher information in the same marker order: they agree to
// rounding.
constexpr double kSameValue = 1e-12;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// n sites on a 2 x 1 x 0.5 box's top and sides (seeded), normals of their faces, cones 75 deg,
// min_visible 3, the workspace 60 deg about +z.
Layout box_sites(int n, unsigned seed) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Layout out;
  out.mode = LayoutMode::kPoints;
  out.entries.resize(3, n);
  MarkerVisibility v;
  v.normals.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const int face = i % 3;  // top, +x side, -y side
    if (face == 0) {
      out.entries.col(i) = Eigen::Vector3d(u(engine), 0.5 * u(engine), 0.25);
      v.normals.col(i) = Eigen::Vector3d::UnitZ();
    } else if (face == 1) {
      out.entries.col(i) = Eigen::Vector3d(1.0, 0.5 * u(engine), 0.25 * u(engine));
      v.normals.col(i) = Eigen::Vector3d::UnitX();
    } else {
      out.entries.col(i) = Eigen::Vector3d(u(engine), -0.5, 0.25 * u(engine));
      v.normals.col(i) = -Eigen::Vector3d::UnitY();
    }
  }
  out.weights = Eigen::VectorXd::Ones(n);
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(n, 75.0);
  out.visibility = v;
  out.workspace = LayoutWorkspace{Eigen::Vector3d::UnitZ(), 60.0};
  return out;
}

// The sites as place_markers() takes them.
visibility::VisibilityProblem as_problem(const Layout& sites) {
  visibility::VisibilityProblem out;
  out.points = sites.entries;
  out.normals = sites.visibility->normals;
  out.cos_cone = (sites.visibility->cone_half_angle_deg * kPi / 180.0).array().cos();
  out.min_visible = sites.visibility->min_visible;
  out.workspace = visibility::Workspace{sites.workspace->axis,
                                        std::cos(sites.workspace->half_angle_deg * kPi / 180.0)};
  return out;
}

Layout subset(const Layout& sites, const std::vector<int>& chosen) {
  Layout out = sites;
  const Eigen::Index k = static_cast<Eigen::Index>(chosen.size());
  out.entries.resize(3, k);
  out.weights = Eigen::VectorXd::Ones(k);
  out.visibility->normals.resize(3, k);
  out.visibility->cone_half_angle_deg.resize(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int s = chosen[static_cast<std::size_t>(j)];
    out.entries.col(j) = sites.entries.col(s);
    out.visibility->normals.col(j) = sites.visibility->normals.col(s);
    out.visibility->cone_half_angle_deg(j) = sites.visibility->cone_half_angle_deg(s);
  }
  return out;
}

camera::PoseCrbOptions camera_options() {
  camera::PoseCrbOptions o;
  o.distance = 6.0;
  o.focal_length = 800.0;
  o.noise_px = 0.5;
  o.samples = kSamples;
  o.aim = Eigen::Vector3d(0.0, 0.0, 0.0);
  return o;
}

// The statistic of `vantage crb`'s samples of a subset: +inf unless every workspace direction
// of the lattice is trackable (min_coverage 1).
double crb_value(const Layout& sites, const std::vector<int>& chosen, CrbStatistic statistic) {
  const camera::PoseCrbModel model(subset(sites, chosen), camera_options());
  const Eigen::Matrix3Xd lattice = visibility::fibonacci_directions(kSamples);
  std::vector<double> values;
  for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
    if (!model.in_workspace(lattice.col(k))) continue;
    const camera::PoseCrbAt at = model.at(lattice.col(k));
    if (!at.trackable) return kInfinity;
    values.push_back(at.rot_rms_deg);
  }
  std::sort(values.begin(), values.end());
  if (statistic == CrbStatistic::kWorst) return values.back();
  const double q = statistic == CrbStatistic::kP95 ? 0.95 : 0.5;
  const auto rank = static_cast<std::size_t>(std::max(1.0, std::ceil(q * values.size())));
  return values[rank - 1];
}

struct Best {
  double value = kInfinity;
  std::vector<int> chosen;
};

// Every K-subset, lexicographic; the first of the least value.
Best enumerate(const Layout& sites, int k, CrbStatistic statistic) {
  const int n = static_cast<int>(sites.entries.cols());
  std::vector<int> idx(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) idx[static_cast<std::size_t>(i)] = i;
  Best best;
  while (true) {
    const double v = crb_value(sites, idx, statistic);
    if (v < best.value) best = {v, idx};
    int i = k - 1;
    while (i >= 0 && idx[static_cast<std::size_t>(i)] == n - k + i) --i;
    if (i < 0) break;
    ++idx[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < k; ++j)
      idx[static_cast<std::size_t>(j)] = idx[static_cast<std::size_t>(j - 1)] + 1;
  }
  return best;
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
    const Best truth = enumerate(sites, 4, statistic);
    ASSERT_TRUE(std::isfinite(truth.value));
    const PlacementResult result = place_markers(problem, camera_place_options(sites, statistic));
    EXPECT_EQ(result.search, "exhaustive");
    EXPECT_EQ(result.status, PlacementResult::Status::kComplete);
    EXPECT_NEAR(result.value.objective, truth.value, kSameValue * truth.value);
    EXPECT_NEAR(crb_value(sites, result.chosen, statistic), truth.value, kSameValue * truth.value);
  }
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
  const Best truth = enumerate(sites, 5, CrbStatistic::kWorst);
  EXPECT_EQ(result.search, "greedy+swap");
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
