// With and without NLopt (VANTAGE_WITH_NLOPT): the cross-check of the global worst viewpoint
// either runs and agrees with an independent truth, or says "built without NLopt" and claims
// nothing; it checks its input in both builds.

#include <gtest/gtest.h>

#include <cmath>

#include "vantage/analysis/build_options.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {
namespace {

// The orthogonal triad (Z = I): t* = 1/sqrt(3) at a = (1, 1, 1)/sqrt(3) (docs/math.md §1).
const double kTriadT = 1.0 / std::sqrt(3.0);
// CrossCheckOptions::agreement, the threshold the cross-check itself applies.
constexpr double kAgreement = 1e-6;

TEST(NloptBuild, CrossCheckRunsOrSaysItDidNot) {
  const CrossCheck check = crosscheck_worst_viewpoint(Eigen::Matrix3d::Identity(), kTriadT);
  if (built_with_nlopt()) {
    EXPECT_EQ(check.skipped, "");
    EXPECT_EQ(check.method, "nlopt_multistart_cobyla");
    EXPECT_TRUE(check.agrees) << check.message;
    EXPECT_NEAR(check.t, kTriadT, kAgreement);
    EXPECT_GT(check.polished, 0);
  } else {
    EXPECT_EQ(check.skipped, kWithoutNlopt);
    EXPECT_EQ(check.method, "skipped");
    EXPECT_FALSE(check.agrees) << "nothing was compared, so nothing agrees";
    EXPECT_EQ(check.message, "cross-check skipped: built without NLopt");
    EXPECT_EQ(check.samples, 0);
    EXPECT_EQ(check.polished, 0);
  }
}

TEST(NloptBuild, CrossCheckChecksItsInputEitherWay) {
  EXPECT_THROW(crosscheck_worst_viewpoint(Eigen::Matrix3Xd(3, 1), 0.0), InvalidArgument);
  EXPECT_THROW(
      crosscheck_worst_viewpoint(Eigen::Matrix3d::Identity(), 0.5, {}, {Eigen::Vector3d::Zero()}),
      InvalidArgument);
  CrossCheckOptions bad;
  bad.polish_starts = 0;
  EXPECT_THROW(crosscheck_worst_viewpoint(Eigen::Matrix3d::Identity(), 0.5, bad), InvalidArgument);
}

}  // namespace
}  // namespace vantage::sdp
