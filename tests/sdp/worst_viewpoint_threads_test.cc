// Large layouts are searched as two halves of the sphere, on two threads by default: the result
// must not depend on the thread count, and must be the one a serial search finds.

#include <gtest/gtest.h>

#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/sdp/worst_viewpoint_additions.h"

namespace vantage::sdp {
namespace {

using testing::kSeed;

// The default certificate_tolerance.
constexpr double kCertified = 1e-9;

// The answer does not depend on the thread count: bit for bit (docs/math.md §14).
constexpr double kIdentical = 0.0;
// Above the layout size from which the search is split (2000 distinct directions).
constexpr int kSplitLayout = 2500;

Eigen::Matrix3Xd random_directions(std::mt19937& rng, int m) {
  Eigen::Matrix3Xd n(3, m);
  for (int i = 0; i < m; ++i) n.col(i) = testing::random_unit_vector(rng);
  return n;
}

WorstViewpoint search(const Eigen::Matrix3Xd& z, int threads) {
  WorstViewpointOptions options;
  options.threads = threads;
  return global_worst_viewpoint(z, options);
}

void expect_identical(const WorstViewpoint& a, const WorstViewpoint& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.t_lower, b.t_lower);
  EXPECT_EQ(a.t_upper, b.t_upper);
  EXPECT_EQ(a.patches, b.patches);
  EXPECT_EQ(a.cells_solved, b.cells_solved);
  ASSERT_EQ(a.viewpoints.size(), b.viewpoints.size());
  for (std::size_t k = 0; k < a.viewpoints.size(); ++k) {
    EXPECT_EIGEN_NEAR(a.viewpoints[k], b.viewpoints[k], kIdentical);
  }
}

TEST(GlobalWorstViewpointThreads, OneAndTwoThreadsGiveTheSameResult) {
  std::mt19937 rng(kSeed);
  for (int m : {300, kSplitLayout}) {
    const Eigen::Matrix3Xd z = random_directions(rng, m);
    const WorstViewpoint one = search(z, 1);
    const WorstViewpoint two = search(z, 2);
    SCOPED_TRACE(::testing::Message() << "m = " << m);
    EXPECT_EQ(one.status, WorstViewpoint::Status::kCertified) << one.message;
    EXPECT_LE(one.t_upper - one.t_lower, kCertified);
    expect_identical(one, two);
    expect_identical(two, search(z, 2));
  }
}

TEST(GlobalWorstViewpointThreads, SplitSearchFindsWhatTheSerialFrontierSearchFinds) {
  // WorstViewpointWithAdditions searches its frontier serially: on a base of 1200 directions
  // plus 1300 added, its answer is the split search's on all 2500, to the last bit (the reported
  // optimum is the canonical optimum of its cell, whatever the path to it).
  std::mt19937 rng(kSeed + 1);
  const Eigen::Matrix3Xd base = random_directions(rng, 1200);
  const Eigen::Matrix3Xd added = random_directions(rng, kSplitLayout - 1200);
  Eigen::Matrix3Xd all(3, kSplitLayout);
  all << base, added;
  const WorstViewpoint split = global_worst_viewpoint(all);
  WorstViewpointWithAdditions prepared(base, 0.3 * global_worst_viewpoint(base).t);
  const WorstViewpoint serial = prepared.solve(added);
  ASSERT_EQ(prepared.fallbacks(), 0) << "the frontier path, not a whole-sphere search";
  EXPECT_EQ(split.status, WorstViewpoint::Status::kCertified) << split.message;
  EXPECT_EQ(split.t, serial.t);
  ASSERT_EQ(split.viewpoints.size(), serial.viewpoints.size());
  for (std::size_t k = 0; k < split.viewpoints.size(); ++k) {
    EXPECT_EIGEN_NEAR(split.viewpoints[k], serial.viewpoints[k], kIdentical);
  }
  EXPECT_LE(split.t_upper - split.t_lower, kCertified);
  EXPECT_LE(serial.t_upper - serial.t_lower, kCertified);
}

TEST(GlobalWorstViewpointThreads, ThreadsMustBeOneOrTwo) {
  for (int threads : {0, 3, -1}) {
    WorstViewpointOptions options;
    options.threads = threads;
    EXPECT_FALSE(options.is_valid());
    EXPECT_THROW(global_worst_viewpoint(Eigen::Matrix3d::Identity(), options), InvalidArgument);
  }
}

}  // namespace
}  // namespace vantage::sdp
