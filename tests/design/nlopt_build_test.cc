// With and without NLopt (VANTAGE_WITH_NLOPT): design's continuous direct optimiser either runs
// or is skipped with "not run: built without NLopt"; the greedy steps and the exhaustive search
// over the candidates need no NLopt and give the same answers in both builds.

#include <gtest/gtest.h>

#include <cmath>

#include "vantage/analysis/build_options.h"
#include "vantage/analysis/common.h"
#include "vantage/design/augment.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::design {
namespace {

// The global solver certifies t to 1e-9; p-bar = sqrt(1 - t^2) inherits that at these t.
constexpr double kCertified = 1e-9;

Layout triad() {
  Layout layout;
  layout.name = "triad";
  layout.entries = Eigen::Matrix3d::Identity();
  layout.weights = Eigen::VectorXd::Ones(3);
  return layout;
}

TEST(NloptBuild, DirectOptimiserRunsOrSaysItDidNot) {
  AugmentOptions o;
  o.add = 1;
  o.direct_starts = 1;
  o.direct_evaluations_per_start = 20;
  const AugmentResult r = augment_layout(triad(), o);
  ASSERT_EQ(r.status, AugmentResult::Status::kOk) << r.message;
  ASSERT_EQ(r.steps.size(), 1u);
  if (built_with_nlopt()) {
    EXPECT_EQ(r.direct.status, DirectResult::Status::kOk) << r.direct.message;
    EXPECT_EQ(r.direct.method, "nlopt_sbplx_multistart");
    EXPECT_GE(r.direct.worst.pbar_min, r.final_pbar_min - kCertified)
        << "the direct optimiser starts from the greedy answer";
  } else {
    EXPECT_EQ(r.direct.status, DirectResult::Status::kSkipped);
    EXPECT_EQ(r.direct.message, "not run: built without NLopt");
    EXPECT_TRUE(r.direct.added.empty());
  }
  // The greedy step is the same in both builds: a fresh certified solve of the layout it reports.
  Eigen::Matrix3Xd grown(3, 4);
  grown << Eigen::Matrix3d::Identity(), r.steps[0].added.normalized();
  EXPECT_NEAR(r.final_pbar_min, sdp::global_worst_viewpoint(grown).pbar_min, kCertified);
}

TEST(NloptBuild, ExhaustiveCandidatesNeedNoNlopt) {
  // Three candidates, one of them the best single addition by a fresh solve of each.
  Layout layout = triad();
  layout.candidates.resize(3, 3);
  layout.candidates << 1.0, 0.0, 1.0,  //
      1.0, 0.0, -1.0,                  //
      1.0, 1.0, 0.0;
  AugmentOptions o;
  o.add = 1;
  o.candidates_only = true;
  const AugmentResult r = augment_layout(layout, o);
  ASSERT_EQ(r.direct.status, DirectResult::Status::kOk) << r.direct.message;
  EXPECT_EQ(r.direct.method, "exhaustive_candidates");
  double best = 1.0;
  for (int c = 0; c < 3; ++c) {
    Eigen::Matrix3Xd grown(3, 4);
    grown << Eigen::Matrix3d::Identity(), layout.candidates.col(c).normalized();
    best = std::min(best, sdp::global_worst_viewpoint(grown).t);
  }
  EXPECT_NEAR(r.direct.worst.t, best, kCertified);
}

}  // namespace
}  // namespace vantage::design
