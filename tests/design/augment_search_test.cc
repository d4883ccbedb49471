// The point-mode search of augment_layout(): it finds the best new marker of its search box
// (a branch and bound over the box, docs/math.md §18), and a step depends only on the layout it
// starts from, so `--add 2` is `--add 1` twice (issue 17).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/eigen_testing.h"
#include "support/sanitized.h"
#include "vantage/design/augment.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::design {
namespace {

// The global solver certifies t to 1e-9; p-bar = sqrt(1 - t^2) inherits that at these t.
constexpr double kCertified = 1e-9;
// The search tolerance of the tests that run a coarser search under the sanitizers.
constexpr double kSanitizedSearchTolerance = 1e-3;

// A quadcopter's rigid body (metres): four arm tips about 0.2 from the hub at slightly
// different heights, and a marker on top. Before issue 17 its first addition had p-bar 0.98016
// in the markers' own bounding box (--margin 0) but only 0.97923 in the default box 0.25 larger
// on every side, which contains it.
Layout drone() {
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

AugmentOptions one_step(double margin) {
  AugmentOptions o;
  o.add = 1;
  o.run_direct = false;
  o.margin = margin;
  return o;
}

// t of the layout with a marker added at p: a fresh certified global solve (no augmenter code).
double t_with_marker(const Layout& layout, const Eigen::Vector3d& p) {
  Layout grown = layout;
  grown.names.clear();
  const Eigen::Index n = grown.entries.cols();
  grown.entries.conservativeResize(3, n + 1);
  grown.entries.col(n) = p;
  grown.weights = Eigen::VectorXd::Ones(n + 1);
  return sdp::global_worst_viewpoint(data_vectors(grown).vectors).t;
}

TEST(AugmentSearch, TheLargerBoxNeverFindsLessOnTheDrone) {
  const Layout layout = drone();
  const AugmentResult inner = augment_layout(layout, one_step(0.0));
  const AugmentResult grown = augment_layout(layout, one_step(0.25));
  ASSERT_EQ(inner.steps.size(), 1u);
  ASSERT_EQ(grown.steps.size(), 1u);
  // The 0.25 box contains the markers' own box, so its best position is at least as good.
  EXPECT_GE(grown.final_pbar_min, inner.final_pbar_min - kCertified);
  for (const AugmentResult* r : {&inner, &grown}) {
    const AugmentStep& st = r->steps[0];
    EXPECT_TRUE(st.search_closed) << "the drone's box is searched to the end";
    EXPECT_LE(st.search_t_lower, st.worst.t + kCertified);
    EXPECT_GE(st.search_t_lower, st.worst.t - AugmentOptions{}.search_tolerance - kCertified);
    EXPECT_NEAR(st.worst.t, t_with_marker(layout, st.added), kCertified);
  }
}

TEST(AugmentSearch, NoPointOfABruteForceGridBeatsTheChosenMarker) {
  // Independent truth: a 15 x 15 x 15 grid over the default search box, each position solved
  // from scratch. The search must do at least as well as every grid point.
  const Layout layout = drone();
  const AugmentResult r = augment_layout(layout, one_step(0.25));
  ASSERT_EQ(r.steps.size(), 1u);
  const Eigen::Vector3d lo = layout.entries.rowwise().minCoeff();
  const Eigen::Vector3d hi = layout.entries.rowwise().maxCoeff();
  const double margin = 0.25 * (hi - lo).maxCoeff();
  const Eigen::Vector3d box_lo = lo.array() - margin;
  const Eigen::Vector3d box_hi = hi.array() + margin;
  constexpr int kGrid = 15;
  double best_grid_t = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      for (int k = 0; k < kGrid; ++k) {
        const Eigen::Vector3d f(i, j, k);
        const Eigen::Vector3d p = box_lo + (f / (kGrid - 1.0)).cwiseProduct(box_hi - box_lo);
        best_grid_t = std::min(best_grid_t, t_with_marker(layout, p));
      }
    }
  }
  EXPECT_LE(r.steps[0].worst.t, best_grid_t + kCertified)
      << "p-bar " << r.final_pbar_min << " vs the grid's "
      << std::sqrt(1 - best_grid_t * best_grid_t);
  EXPECT_TRUE((r.steps[0].added.array() >= box_lo.array()).all() &&
              (r.steps[0].added.array() <= box_hi.array()).all())
      << r.steps[0].added.transpose();
}

void expect_same_step(const AugmentStep& a, const AugmentStep& b) {
  EXPECT_TRUE((a.added.array() == b.added.array()).all())
      << a.added.transpose() << " vs " << b.added.transpose();
  EXPECT_EQ(a.worst.t, b.worst.t);
  EXPECT_EQ(a.worst.viewpoints.size(), b.worst.viewpoints.size());
  EXPECT_EQ(a.vector_count, b.vector_count);
}

TEST(AugmentSearch, TheSecondOfTwoStepsIsAFreshStepOnTheFirstsLayout) {
  const Layout layout = drone();
  // Any box and search make the same two paths; under the sanitizers the markers' own box and a
  // coarser search.
  AugmentOptions one = one_step(testing::kUnderSanitizer ? 0.0 : 0.25);
  if (testing::kUnderSanitizer) {
    one.search_tolerance = kSanitizedSearchTolerance;
    one.grid_samples = 7;
  }
  AugmentOptions two = one;
  two.add = 2;
  const AugmentResult both = augment_layout(layout, two);
  const AugmentResult first = augment_layout(layout, one);
  const AugmentResult second = augment_layout(first.augmented, one);
  ASSERT_EQ(both.steps.size(), 2u);
  expect_same_step(both.steps[0], first.steps[0]);
  expect_same_step(both.steps[1], second.steps[0]);
  EXPECT_EQ(both.final_pbar_min, second.final_pbar_min);
  // The additions are named after the layout's names, the same way on both paths.
  const std::vector<std::string> names = {"arm1", "arm2",   "arm3",  "arm4",
                                          "top",  "added1", "added2"};
  EXPECT_EQ(both.augmented.names, names);
  EXPECT_EQ(second.augmented.names, names);
}

TEST(AugmentSearch, UsedCandidatesLeaveTheLayoutSoStepsRepeatTheSame) {
  Layout layout = drone();
  layout.candidates.resize(3, 3);
  layout.candidates << 0.0, 0.2, -0.2,  //
      0.0, 0.0, 0.05,                   //
      -0.08, 0.03, 0.06;
  AugmentOptions two = one_step(0.25);
  two.add = 2;
  two.candidates_only = true;
  const AugmentResult both = augment_layout(layout, two);
  AugmentOptions one = two;
  one.add = 1;
  const AugmentResult first = augment_layout(layout, one);
  ASSERT_EQ(first.augmented.candidates.cols(), 2);
  const AugmentResult second = augment_layout(first.augmented, one);
  ASSERT_EQ(both.steps.size(), 2u);
  expect_same_step(both.steps[1], second.steps[0]);
  EXPECT_EQ(both.augmented.candidates.cols(), 1);
  EXPECT_TRUE((both.augmented.candidates.array() == second.augmented.candidates.array()).all());
  // Indices refer to the input's candidates; the fresh run's to what was left of them.
  EXPECT_NE(both.steps[0].candidate_index, both.steps[1].candidate_index);
}

TEST(AugmentSearch, DirectionStepsRepeatTheSameToo) {
  std::mt19937 rng(testing::kSeed + 17);
  Layout layout;
  layout.entries.resize(3, 6);
  for (Eigen::Index i = 0; i < 6; ++i) layout.entries.col(i) = testing::random_unit_vector(rng);
  layout.weights = Eigen::VectorXd::Ones(6);
  AugmentOptions two = one_step(0.25);
  two.add = 2;
  const AugmentResult both = augment_layout(layout, two);
  const AugmentResult second =
      augment_layout(augment_layout(layout, one_step(0.25)).augmented, one_step(0.25));
  ASSERT_EQ(both.steps.size(), 2u);
  expect_same_step(both.steps[1], second.steps[0]);
}

}  // namespace
}  // namespace vantage::design
