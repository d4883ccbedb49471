// AugmentOptions::min_distance_difference (issue 20, docs/math.md §18 and §24): every point-mode
// addition keeps the least difference between two inter-marker distances at or above D, checked
// here by brute force over every two distinct pairs; a step that cannot stops the run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/sanitized.h"
#include "vantage/analysis/common.h"
#include "vantage/design/augment.h"

namespace vantage::design {
namespace {

// The drone of augment_search_test.cc: a quadcopter's rigid body (metres).
Layout distance_drone() {
  Layout layout;
  layout.name = "drone";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 5);
  layout.entries << 0.1263, -0.1183, -0.1448, 0.1499, 0.0280,  //
      0.1632, 0.1462, -0.1299, -0.1345, -0.0209,               //
      -0.0053, -0.0111, 0.0016, -0.0101, 0.0431;
  layout.weights = Eigen::VectorXd::Ones(5);
  layout.names = {"arm1", "arm2", "arm3", "arm4", "top"};
  return layout;
}

// Eq. (24.1) by brute force, O(n^4): every two distinct unordered pairs {i, j} != {k, l}.
double brute_distance_difference(const Eigen::Matrix3Xd& p) {
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Index n = p.cols();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      for (Eigen::Index k = 0; k < n; ++k) {
        for (Eigen::Index l = k + 1; l < n; ++l) {
          if (i == k && j == l) continue;
          const double dij = (p.col(i) - p.col(j)).norm();
          const double dkl = (p.col(k) - p.col(l)).norm();
          best = std::min(best, std::abs(dij - dkl));
        }
      }
    }
  }
  return best;
}

// The markers after the first `steps` greedy additions of r to `input`.
Eigen::Matrix3Xd markers_after(const Eigen::Matrix3Xd& input, const AugmentResult& r,
                               std::size_t steps) {
  Eigen::Matrix3Xd out(3, input.cols() + static_cast<Eigen::Index>(steps));
  out.leftCols(input.cols()) = input;
  for (std::size_t s = 0; s < steps; ++s) out.col(input.cols() + s) = r.steps[s].added;
  return out;
}

// Under the sanitizers the point search stops at a coarser tolerance and the direct optimiser
// runs two short starts: every addition still keeps the gap, which is what these tests check.
constexpr double kSanitizedSearchTolerance = 1e-3;

AugmentOptions distance_options(double gap) {
  AugmentOptions o;
  o.add = 2;
  o.run_direct = true;
  o.min_distance_difference = gap;
  if (testing::kUnderSanitizer) {
    o.search_tolerance = kSanitizedSearchTolerance;
    o.direct_starts = 2;
    o.direct_evaluations_per_start = 150;
  }
  return o;
}

TEST(AugmentDistance, EveryStepAndTheDirectAnswerKeepTheGapTheFreeRunBreaks) {
  const Layout layout = distance_drone();
  const double own = brute_distance_difference(layout.entries);
  AugmentOptions free_options = distance_options(0.0);
  free_options.run_direct = false;
  const AugmentResult free = augment_layout(layout, free_options);
  ASSERT_EQ(free.steps.size(), 2u);
  const double free_gap = brute_distance_difference(free.augmented.entries);
  // The free run squeezes two distances closer than the drone's own: a gap between the two is
  // kept by the drone and broken by the free run, so the constraint has work to do.
  ASSERT_LT(free_gap, own);
  const double gap = 0.5 * (free_gap + own);

  const AugmentResult r = augment_layout(layout, distance_options(gap));
  EXPECT_EQ(r.status, AugmentResult::Status::kOk) << r.message;
  ASSERT_EQ(r.steps.size(), 2u);
  for (std::size_t s = 1; s <= r.steps.size(); ++s) {
    EXPECT_GE(brute_distance_difference(markers_after(layout.entries, r, s)), gap)
        << "after step " << s;
  }
  EXPECT_GE(brute_distance_difference(r.augmented.entries), gap);
  if (r.direct.status == DirectResult::Status::kOk) {
    Eigen::Matrix3Xd direct(3, layout.entries.cols() + 2);
    direct.leftCols(layout.entries.cols()) = layout.entries;
    for (Eigen::Index j = 0; j < 2; ++j) direct.col(layout.entries.cols() + j) = r.direct.added[j];
    EXPECT_GE(brute_distance_difference(direct), gap);
  }
}

// A triangle with sides 2.9, 1 and 2 (distance difference 0.9) in its own bounding box
// (margin 0): a fourth marker makes six distances, each at most the box's diagonal, and six
// numbers in [0, diagonal] at least D apart need 5 D <= diagonal. With D = 0.8 > diagonal / 5
// no position of the box can keep D.
Layout distance_triangle() {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  const double cx = (1.0 + 2.9 * 2.9 - 4.0) / (2.0 * 2.9);
  layout.entries.resize(3, 3);
  layout.entries << 0.0, 2.9, cx,  //
      0.0, 0.0, std::sqrt(1.0 - cx * cx), 0.0, 0.0, 0.0;
  layout.weights = Eigen::VectorXd::Ones(3);
  return layout;
}

TEST(AugmentDistance, NoFeasiblePositionStopsWithTheInputIntact) {
  const Layout layout = distance_triangle();
  constexpr double kGap = 0.8;
  ASSERT_GE(brute_distance_difference(layout.entries), kGap);
  const Eigen::Vector3d side =
      layout.entries.rowwise().maxCoeff() - layout.entries.rowwise().minCoeff();
  ASSERT_GT(5.0 * kGap, side.norm()) << "the pigeonhole argument needs D > diagonal / 5";
  AugmentOptions o = distance_options(kGap);
  o.margin = 0.0;
  o.search_budget = 30'000;
  const AugmentResult r = augment_layout(layout, o);
  EXPECT_EQ(r.status, AugmentResult::Status::kNoFeasibleAddition);
  EXPECT_STREQ(to_string(r.status), "no_feasible_addition");
  EXPECT_NE(r.message.find("0.8"), std::string::npos) << r.message;
  EXPECT_TRUE(r.steps.empty());
  EXPECT_EQ(r.augmented.entries, layout.entries);
  EXPECT_EQ(r.final_pbar_min, r.initial.pbar_min);
  EXPECT_EQ(r.direct.status, DirectResult::Status::kSkipped);
}

TEST(AugmentDistance, BadGapsAndLayoutsAreRefusedNamingTheOption) {
  for (double bad :
       {-1e-3, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    AugmentOptions o = distance_options(bad);
    std::string why;
    EXPECT_FALSE(o.is_valid(&why)) << bad;
    EXPECT_NE(why.find("min_distance_difference"), std::string::npos) << why;
  }
  // The drone's own distances differ by 0.0037: a larger D is refused before any search.
  try {
    augment_layout(distance_drone(), distance_options(0.01));
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("min_distance_difference"), std::string::npos) << e.what();
  }
  Layout directions;
  directions.mode = LayoutMode::kVectors;
  directions.entries = Eigen::Matrix3d::Identity();
  directions.weights = Eigen::VectorXd::Ones(3);
  try {
    augment_layout(directions, distance_options(0.1));
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("min_distance_difference"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vantage::design
