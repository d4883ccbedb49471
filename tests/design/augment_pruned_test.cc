// AugmentOptions::prune_solves: the pruned solves (hints, and solves that stop once a candidate
// cannot rank) make the same choices as solving every candidate to its certificate.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "support/eigen_testing.h"
#include "support/sanitized.h"
#include "vantage/design/augment.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::design {
namespace {

using testing::kSeed;

// Both paths certify every t to 1e-9; the same choice gives the same t up to the rounding of
// solving the same cells along different paths.
constexpr double kRounding = 1e-13;

Layout random_points(std::mt19937& rng, int n, int candidates) {
  std::uniform_real_distribution<double> box(-1.0, 1.0);
  Layout layout;
  layout.name = "random points";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, n);
  for (int i = 0; i < n; ++i) layout.entries.col(i) << box(rng), box(rng), box(rng);
  layout.weights = Eigen::VectorXd::Ones(n);
  layout.candidates.resize(3, candidates);
  for (int c = 0; c < candidates; ++c) layout.candidates.col(c) << box(rng), box(rng), box(rng);
  return layout;
}

Layout random_directions(std::mt19937& rng, int m) {
  Layout layout;
  layout.name = "random directions";
  layout.entries.resize(3, m);
  for (int i = 0; i < m; ++i) layout.entries.col(i) = testing::random_unit_vector(rng);
  layout.weights = Eigen::VectorXd::Ones(m);
  return layout;
}

void expect_same_choices(const AugmentResult& pruned, const AugmentResult& reference) {
  EXPECT_EQ(pruned.status, reference.status);
  EXPECT_NEAR(pruned.initial.t, reference.initial.t, kRounding);
  ASSERT_EQ(pruned.steps.size(), reference.steps.size());
  for (std::size_t s = 0; s < reference.steps.size(); ++s) {
    SCOPED_TRACE(::testing::Message() << "step " << s + 1);
    EXPECT_EIGEN_NEAR(pruned.steps[s].added, reference.steps[s].added, kRounding);
    EXPECT_EQ(pruned.steps[s].candidate_index, reference.steps[s].candidate_index);
    EXPECT_NEAR(pruned.steps[s].worst.t, reference.steps[s].worst.t, kRounding);
    EXPECT_EQ(pruned.steps[s].worst.viewpoints.size(), reference.steps[s].worst.viewpoints.size());
    EXPECT_TRUE(pruned.steps[s].worst.certified);
  }
  EXPECT_EQ(pruned.direct.status, reference.direct.status);
  EXPECT_NEAR(pruned.direct.worst.t, reference.direct.worst.t, kRounding);
  EXPECT_EQ(pruned.direct.candidate_indices, reference.direct.candidate_indices);
}

AugmentOptions small_budget(int add, bool prune) {
  AugmentOptions o;
  o.add = add;
  o.grid_samples = 4;
  o.circle_samples = 12;
  o.refine_starts = 2;
  o.refine_tolerance = 1e-4;
  o.direct_starts = 2;
  o.direct_evaluations_per_start = 40;
  o.prune_solves = prune;
  return o;
}

TEST(AugmentPruned, PointModeMakesTheSameChoices) {
  // Under the sanitizers only the 6-marker layout and one step (the 10-marker one takes two
  // minutes there, two steps of the 6-marker one a minute).
  const int trials = testing::kUnderSanitizer ? 1 : 3;
  const int add = testing::kUnderSanitizer ? 1 : 2;
  std::mt19937 rng(kSeed + 50);
  for (int trial = 0; trial < trials; ++trial) {
    const Layout layout = random_points(rng, 6 + 2 * trial, 0);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    expect_same_choices(augment_layout(layout, small_budget(add, true)),
                        augment_layout(layout, small_budget(add, false)));
  }
}

TEST(AugmentPruned, DirectionModeMakesTheSameChoices) {
  std::mt19937 rng(kSeed + 51);
  for (int trial = 0; trial < 3; ++trial) {
    const Layout layout = random_directions(rng, 8 + 4 * trial);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    expect_same_choices(augment_layout(layout, small_budget(2, true)),
                        augment_layout(layout, small_budget(2, false)));
  }
}

TEST(AugmentPruned, CandidatesOnlyPicksTheBestByAFullSolveOfEach) {
  // Independent truth: every remaining candidate solved to its certificate here; the greedy
  // pick has the smallest t (within the tie tolerance), and the exhaustive pair is the best pair.
  std::mt19937 rng(kSeed + 52);
  const Layout layout = random_points(rng, 7, 9);
  AugmentOptions o;
  o.add = 2;
  o.candidates_only = true;
  const AugmentResult r = augment_layout(layout, o);
  expect_same_choices(r, augment_layout(layout, [&] {
                        AugmentOptions ref = o;
                        ref.prune_solves = false;
                        return ref;
                      }()));
  ASSERT_EQ(r.steps.size(), 2u);
  auto t_with = [&](std::initializer_list<int> picks) {
    Layout grown = layout;
    const Eigen::Index n = grown.entries.cols();
    grown.entries.conservativeResize(3, n + static_cast<Eigen::Index>(picks.size()));
    grown.weights = Eigen::VectorXd::Ones(grown.entries.cols());
    Eigen::Index k = n;
    for (int c : picks) grown.entries.col(k++) = layout.candidates.col(c);
    return sdp::global_worst_viewpoint(data_vectors(grown).vectors).t;
  };
  double best_single = std::numeric_limits<double>::infinity();
  double best_pair = std::numeric_limits<double>::infinity();
  for (int c = 0; c < layout.candidates.cols(); ++c) {
    best_single = std::min(best_single, t_with({c}));
    for (int d = c + 1; d < layout.candidates.cols(); ++d) {
      best_pair = std::min(best_pair, t_with({c, d}));
    }
  }
  EXPECT_LE(r.steps[0].worst.t, best_single + o.tie_tolerance);
  ASSERT_EQ(r.direct.status, DirectResult::Status::kOk) << r.direct.message;
  EXPECT_NEAR(r.direct.worst.t, best_pair, kRounding);
}

}  // namespace
}  // namespace vantage::design
