// WorstViewpointOptions::hints and ::stop_above: they change the branch and bound's work, never
// its answer (hints), and stop it only once t* > stop_above is proven (stop_above).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/sdp/worst_viewpoint_additions.h"

namespace vantage::sdp {
namespace {

using testing::kSeed;

// Hinted and plain searches solve the same cells by different paths; their t agree to rounding.
constexpr double kRounding = 1e-14;
// The certificate's width.
constexpr double kCertified = 1e-9;

// Hints change the search order, not the optimum: the viewpoints agree to the certificate.
constexpr double kSameOptimum = 1e-9;

Eigen::Matrix3Xd random_unit_columns(std::mt19937& rng, int m) {
  Eigen::Matrix3Xd z(3, m);
  for (int i = 0; i < m; ++i) z.col(i) = testing::random_unit_vector(rng);
  return z;
}

// Same t, t_upper, the same set of optima (up to sign and rounding).
void expect_same_answer(const WorstViewpoint& hinted, const WorstViewpoint& plain) {
  ASSERT_EQ(hinted.status, WorstViewpoint::Status::kCertified) << hinted.message;
  EXPECT_EQ(hinted.t, plain.t) << "the reported cell optimum is re-solved on the whole cell";
  EXPECT_LE(hinted.t_upper - hinted.t_lower, kCertified);
  EXPECT_EIGEN_NEAR(hinted.viewpoint, plain.viewpoint, kSameOptimum);
  ASSERT_EQ(hinted.viewpoints.size(), plain.viewpoints.size());
  for (std::size_t k = 0; k < plain.viewpoints.size(); ++k) {
    EXPECT_EIGEN_NEAR(hinted.viewpoints[k], plain.viewpoints[k], kSameOptimum) << "optimum " << k;
  }
}

TEST(WorstViewpointHints, ChangeTheWorkNotTheAnswer) {
  std::mt19937 rng(kSeed + 40);
  int fewer = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const Eigen::Matrix3Xd z = random_unit_columns(rng, 40 + 60 * trial);
    const WorstViewpoint plain = global_worst_viewpoint(z);
    // The optimum itself (scaled and negated: any length and sign), a random point, and the
    // optimum of the layout without its last five vectors (what the augmenter passes).
    for (int kind = 0; kind < 3; ++kind) {
      WorstViewpointOptions options;
      if (kind == 0) options.hints = {-3.0 * plain.viewpoint};
      if (kind == 1) options.hints = {testing::random_unit_vector(rng)};
      if (kind == 2) {
        options.hints = global_worst_viewpoint(z.leftCols(z.cols() - 5)).viewpoints;
      }
      const WorstViewpoint hinted = global_worst_viewpoint(z, options);
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " hint kind " << kind);
      expect_same_answer(hinted, plain);
      if (kind == 0) {
        EXPECT_LE(hinted.patches, plain.patches);
        fewer += hinted.patches < plain.patches ? 1 : 0;
      }
    }
  }
  EXPECT_GT(fewer, 0) << "the optimum as a hint never saved a patch";
}

TEST(WorstViewpointHints, TiesAreStillEveryOptimum) {
  // Z = I: four tied optima (+-1, +-1, 1) / sqrt(3); a hint at one of them must not hide the
  // others, and a hint is never reported as an optimum itself.
  const Eigen::Matrix3Xd z = Eigen::Matrix3d::Identity();
  WorstViewpointOptions options;
  options.hints = {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0.3, 0.2, 0.9)};
  const WorstViewpoint hinted = global_worst_viewpoint(z, options);
  expect_same_answer(hinted, global_worst_viewpoint(z));
  EXPECT_EQ(hinted.viewpoints.size(), 4u);
}

TEST(WorstViewpointStop, StopsOnlyWhenTStarExceedsTheLevel) {
  std::mt19937 rng(kSeed + 41);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Matrix3Xd z = random_unit_columns(rng, 30 + 50 * trial);
    const WorstViewpoint plain = global_worst_viewpoint(z);
    WorstViewpointOptions below;
    below.stop_above = 0.9 * plain.t;
    const WorstViewpoint stopped = global_worst_viewpoint(z, below);
    EXPECT_EQ(stopped.status, WorstViewpoint::Status::kStoppedAbove);
    EXPECT_GT(stopped.t, below.stop_above);
    EXPECT_LE(stopped.t, plain.t_upper);
    EXPECT_NEAR(stopped.t, min_abs_projection(z, stopped.viewpoint), kRounding);
    EXPECT_EQ(stopped.t_upper, 1.0);
    EXPECT_LE(stopped.patches, plain.patches);

    WorstViewpointOptions above;
    above.stop_above = plain.t + kCertified;
    expect_same_answer(global_worst_viewpoint(z, above), plain);
    EXPECT_EQ(global_worst_viewpoint(z, above).patches, plain.patches);
  }
}

TEST(WorstViewpointStop, AHintAboveTheLevelStopsAtOnce) {
  const Eigen::Matrix3Xd z = Eigen::Matrix3d::Identity();
  WorstViewpointOptions options;
  options.hints = {Eigen::Vector3d(1, 1, 1)};
  options.stop_above = 0.5;
  const WorstViewpoint w = global_worst_viewpoint(z, options);
  EXPECT_EQ(w.status, WorstViewpoint::Status::kStoppedAbove);
  EXPECT_EQ(w.patches, 0);
  EXPECT_NEAR(w.t, 1.0 / std::sqrt(3.0), kRounding);
  EXPECT_STREQ(to_string(w.status), "stopped_above");
}

TEST(WorstViewpointStop, RejectsBadOptions) {
  const Eigen::Matrix3Xd z = Eigen::Matrix3d::Identity();
  WorstViewpointOptions nan_level;
  nan_level.stop_above = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(global_worst_viewpoint(z, nan_level), InvalidArgument);
  WorstViewpointOptions zero_hint;
  zero_hint.hints = {Eigen::Vector3d::Zero()};
  EXPECT_THROW(global_worst_viewpoint(z, zero_hint), InvalidArgument);
  WorstViewpointOptions infinite_hint;
  infinite_hint.hints = {Eigen::Vector3d(std::numeric_limits<double>::infinity(), 0, 0)};
  EXPECT_THROW(global_worst_viewpoint(z, infinite_hint), InvalidArgument);
}

TEST(WorstViewpointWithAdditions, SameAnswerAsTheWholeLayout) {
  // Random bases, random additions of 1 to 20 vectors: from the frontier (levels that the
  // augmented layouts reach) or by the fallback (a level above t*), always the whole layout's
  // answer.
  std::mt19937 rng(kSeed + 42);
  long from_frontier = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::Matrix3Xd base = random_unit_columns(rng, 30 + 60 * trial);
    const double t_base = global_worst_viewpoint(base).t;
    for (double fraction : {0.3, 0.6, 0.9, 1.0 + 1e-6}) {
      WorstViewpointWithAdditions prepared(base, std::min(1.0, fraction * t_base));
      for (int k : {1, 3, 20}) {
        const Eigen::Matrix3Xd added = 2.5 * random_unit_columns(rng, k);
        Eigen::Matrix3Xd all(3, base.cols() + k);
        all << base, added;
        const WorstViewpoint plain = global_worst_viewpoint(all);
        const long fallbacks = prepared.fallbacks();
        const WorstViewpoint fast = prepared.solve(added);
        SCOPED_TRACE(::testing::Message()
                     << "trial " << trial << " level " << fraction << " k " << k);
        expect_same_answer(fast, plain);
        EXPECT_EQ(prepared.fallbacks() > fallbacks, plain.t < prepared.level());
        from_frontier += prepared.fallbacks() == fallbacks ? 1 : 0;
      }
    }
  }
  EXPECT_GT(from_frontier, 20);
}

TEST(WorstViewpointWithAdditions, FrontierShrinksWithTheLevel) {
  std::mt19937 rng(kSeed + 43);
  const Eigen::Matrix3Xd base = random_unit_columns(rng, 400);
  const double t_base = global_worst_viewpoint(base).t;
  const WorstViewpointWithAdditions low(base, 0.3 * t_base);
  const WorstViewpointWithAdditions high(base, 0.9 * t_base);
  EXPECT_LT(high.frontier_patches(), low.frontier_patches());
  EXPECT_THROW(WorstViewpointWithAdditions(base, 1.5), InvalidArgument);
  EXPECT_THROW(WorstViewpointWithAdditions(base, 0.0), InvalidArgument);
  WorstViewpointWithAdditions prepared(base, 0.5);
  WorstViewpointOptions other_tie;
  other_tie.tie_tolerance = 1e-6;
  EXPECT_THROW(prepared.solve(base.leftCols(1), other_tie), InvalidArgument);
}

}  // namespace
}  // namespace vantage::sdp
