#include "vantage/design/augment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/eigen_testing.h"
#include "support/nlopt_build.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::design {
namespace {

using testing::kSeed;

// The global solver certifies t to 1e-9; p-bar = sqrt(1 - t^2) inherits that at these t.
constexpr double kCertified = 1e-9;
// A coplanar design reaches its ceiling up to the compass search's stopping step (1e-7 rad),
// which moves p-bar by at most ~1e-7.
constexpr double kCeilingReach = 1e-6;

// The augmenter copies its input and candidate vectors: bit for bit.
constexpr double kExact = 0.0;
// cos(pi / (2 m)) computed twice, or against a 16-digit literal: an ulp of a number below 1.
constexpr double kCosRounding = 1e-15;
// A closed-form level or an SVD of a few unit vectors: tens of ulps of O(1) values.
constexpr double kRounding = 1e-12;
// The compass search stops at a step of 1e-7 rad (see kCeilingReach), 6e-6 degrees.
constexpr double kCompassAngleDeg = 1e-4;
const double kTriadPbar = std::sqrt(2.0 / 3.0);  // docs/math.md §12: 0.8165

Layout direction_layout(const Eigen::Matrix3Xd& vectors) {
  Layout layout;
  layout.name = "test";
  layout.entries = vectors;
  layout.weights = Eigen::VectorXd::Ones(vectors.cols());
  return layout;
}

Eigen::Matrix3Xd planar(std::initializer_list<double> degrees) {
  Eigen::Matrix3Xd v(3, degrees.size());
  int i = 0;
  for (double d : degrees) {
    v.col(i++) << std::cos(d * kPi / 180.0), std::sin(d * kPi / 180.0), 0.0;
  }
  return v;
}

AugmentOptions greedy_only(int k) {
  AugmentOptions o;
  o.add = k;
  o.run_direct = false;
  return o;
}

// Every reported p-bar_min equals a fresh global analysis of the layout it describes.
void expect_agrees_with_fresh_analysis(const AugmentResult& r, const Layout& input) {
  Layout partial = input;
  for (size_t s = 0; s < r.steps.size(); ++s) {
    const Eigen::Index n = partial.entries.cols();
    partial.entries.conservativeResize(3, n + 1);
    partial.entries.col(n) = r.steps[s].added;
    partial.weights.conservativeResize(n + 1);
    partial.weights(n) = 1.0;
    const sdp::WorstViewpoint fresh = sdp::global_worst_viewpoint(data_vectors(partial).vectors);
    EXPECT_NEAR(r.steps[s].worst.pbar_min, fresh.pbar_min, kCertified) << "step " << s + 1;
    EXPECT_EQ(r.steps[s].vector_count, data_vectors(partial).vectors.cols());
    EXPECT_NEAR(r.steps[s].ceiling, std::cos(kPi / (2.0 * r.steps[s].vector_count)), kCosRounding);
  }
  EXPECT_EIGEN_NEAR(r.augmented.entries, partial.entries, kExact);
  const sdp::WorstViewpoint final_fresh =
      sdp::global_worst_viewpoint(data_vectors(r.augmented).vectors);
  EXPECT_NEAR(r.final_pbar_min, final_fresh.pbar_min, kCertified);
}

void expect_never_lowers(const AugmentResult& r) {
  double previous = r.initial.pbar_min;
  for (const AugmentStep& st : r.steps) {
    EXPECT_GE(st.worst.pbar_min, previous - kCertified);
    EXPECT_LE(st.worst.pbar_min, st.ceiling + kCertified) << "the ceiling of docs/math.md §15";
    EXPECT_EQ(st.improved, st.worst.pbar_min > previous + kCertified);
    previous = st.worst.pbar_min;
  }
}

TEST(Augment, TriadPlusOneVectorNeverExceedsItsValue) {
  const Layout triad = direction_layout(Eigen::Matrix3d::Identity());
  const AugmentResult r = augment_layout(triad, greedy_only(1));
  EXPECT_EQ(r.status, AugmentResult::Status::kOk) << r.message;
  EXPECT_NEAR(r.initial.pbar_min, kTriadPbar, kCertified);
  EXPECT_EQ(r.initial.viewpoints.size(), 4u);
  ASSERT_EQ(r.steps.size(), 1u);
  const AugmentStep& st = r.steps[0];
  EXPECT_LE(st.worst.pbar_min, kTriadPbar + kCertified);
  EXPECT_FALSE(st.improved);
  EXPECT_FALSE(st.single_vector_can_improve);
  EXPECT_NEAR(st.best_kill_level, 1.0 / std::sqrt(3.0), kRounding);
  EXPECT_NE(st.note.find("no single vector can raise"), std::string::npos) << st.note;
  // The tie-break keeps the fewest worst viewpoints: (1,1,-1)/sqrt(3) kills three of four.
  EXPECT_EQ(st.worst.viewpoints.size(), 1u);
  expect_agrees_with_fresh_analysis(r, triad);

  // Independently: no random vector added to Z = I lifts the global p-bar_min (Fig. 3's 0.95
  // is a single-cell artefact, docs/math.md §13).
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::Matrix3Xd v(3, 4);
    v << Eigen::Matrix3d::Identity(), testing::random_unit_vector(rng);
    EXPECT_LE(evaluate_worst_case(v).pbar_min, kTriadPbar + kCertified) << "trial " << trial;
  }
  Eigen::Matrix3Xd fig3(3, 4);
  fig3 << Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 1, -2).normalized();
  EXPECT_NEAR(evaluate_worst_case(fig3).pbar_min, kTriadPbar, kCertified);
}

TEST(Augment, CoplanarStartReachesItsCeiling) {
  // 0, 45, 90 degrees: the worst viewpoint is in-plane at 45 degrees, and the vector at 135
  // degrees in its a^perp completes the equal-angle fan of docs/math.md §15: cos(pi / 8).
  const Layout three = direction_layout(planar({0.0, 45.0, 90.0}));
  const AugmentResult r = augment_layout(three, greedy_only(1));
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_TRUE(r.initial_coplanarity.nearly_coplanar);
  EXPECT_NEAR(r.initial_coplanarity.smallest_singular_value, 0.0, kRounding);
  EXPECT_NEAR(r.steps[0].worst.pbar_min, pbar_ceiling(4), kCeilingReach);
  EXPECT_NEAR(std::abs(r.steps[0].added.dot(Eigen::Vector3d(-1, 1, 0).normalized())), 1.0,
              kCeilingReach);
  EXPECT_NEAR(r.steps[0].angle_from_worst_plane_deg, 0.0, kCompassAngleDeg)
      << "the paper's a^perp rule";
  EXPECT_TRUE(r.final_coplanarity.nearly_coplanar) << "the two-fold ambiguity is reported";
  expect_agrees_with_fresh_analysis(r, three);

  const Layout two = direction_layout(planar({0.0, 60.0}));
  const AugmentResult r2 = augment_layout(two, greedy_only(1));
  EXPECT_NEAR(r2.steps[0].worst.pbar_min, pbar_ceiling(3), kCeilingReach);
}

TEST(Augment, GreedyNeverLowersAndMatchesFreshAnalysisOnRandomLayouts) {
  std::mt19937 rng(kSeed + 1);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::Matrix3Xd v(3, 4 + trial);
    for (Eigen::Index i = 0; i < v.cols(); ++i) v.col(i) = testing::random_unit_vector(rng);
    const Layout layout = direction_layout(v);
    AugmentOptions o = greedy_only(3);
    o.circle_samples = 24;
    const AugmentResult r = augment_layout(layout, o);
    EXPECT_EQ(r.status, AugmentResult::Status::kOk) << r.message;
    ASSERT_EQ(r.steps.size(), 3u);
    expect_never_lowers(r);
    expect_agrees_with_fresh_analysis(r, layout);
  }
}

TEST(Augment, DirectStartsFromGreedyAndNeverReportsLess) {
  VANTAGE_SKIP_WITHOUT_NLOPT();
  const Layout triad = direction_layout(Eigen::Matrix3d::Identity());
  AugmentOptions o;
  o.add = 2;
  o.circle_samples = 24;
  o.direct_starts = 2;
  o.direct_evaluations_per_start = 150;
  const AugmentResult r = augment_layout(triad, o);
  ASSERT_EQ(r.direct.status, DirectResult::Status::kOk) << r.direct.message;
  ASSERT_EQ(r.direct.added.size(), 2u);
  EXPECT_GE(r.direct.worst.pbar_min, r.final_pbar_min - kCertified);
  EXPECT_LE(r.direct.worst.pbar_min, pbar_ceiling(5) + kCertified);
  Eigen::Matrix3Xd v(3, 5);
  v << Eigen::Matrix3d::Identity(), r.direct.added[0], r.direct.added[1];
  EXPECT_NEAR(r.direct.worst.pbar_min, sdp::global_worst_viewpoint(v).pbar_min, kCertified);
}

Layout square_points() {
  Layout layout;
  layout.name = "tetrahedron";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 4);
  layout.entries << 0, 1, 0, 0,  //
      0, 0, 1, 0,                //
      0, 0, 0, 1;
  layout.weights = Eigen::VectorXd::Ones(4);
  layout.candidates.resize(3, 3);
  layout.candidates << 1, -1, 0.5,  //
      1, 0, 0.5,                    //
      1, 0, -0.5;
  return layout;
}

TEST(Augment, CandidatesOnlyChoosesAmongCandidates) {
  const Layout layout = square_points();
  AugmentOptions o;
  o.add = 2;
  o.candidates_only = true;
  const AugmentResult r = augment_layout(layout, o);
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_NE(r.steps[0].candidate_index, r.steps[1].candidate_index) << "each used once";
  for (const AugmentStep& st : r.steps) {
    ASSERT_GE(st.candidate_index, 0);
    EXPECT_EIGEN_NEAR(st.added, Eigen::Vector3d(layout.candidates.col(st.candidate_index)), kExact);
  }
  expect_never_lowers(r);
  expect_agrees_with_fresh_analysis(r, layout);
  // Exhaustive over the 3 pairs: at least as good as greedy.
  ASSERT_EQ(r.direct.status, DirectResult::Status::kOk) << r.direct.message;
  EXPECT_EQ(r.direct.method, "exhaustive_candidates");
  EXPECT_GE(r.direct.worst.pbar_min, r.final_pbar_min - kCertified);

  o.add = 4;
  o.run_direct = false;
  const AugmentResult out = augment_layout(layout, o);
  EXPECT_EQ(out.status, AugmentResult::Status::kNoCandidates);
  EXPECT_EQ(out.steps.size(), 3u);
}

TEST(Augment, PointModeSearchesTheGrownBox) {
  const Layout layout = square_points();
  AugmentOptions o = greedy_only(1);
  o.grid_samples = 4;
  o.refine_starts = 1;
  o.margin = 0.5;
  const AugmentResult r = augment_layout(layout, o);
  ASSERT_EQ(r.steps.size(), 1u);
  const Eigen::Vector3d p = r.steps[0].added;
  EXPECT_TRUE((p.array() >= -0.5 - 1e-12).all() && (p.array() <= 1.5 + 1e-12).all())
      << p.transpose();
  EXPECT_EQ(r.steps[0].vector_count, 10);
  expect_never_lowers(r);
  expect_agrees_with_fresh_analysis(r, layout);
}

TEST(Augment, CoplanarityAndCeiling) {
  EXPECT_NEAR(coplanarity(Eigen::Matrix3d::Identity()).smallest_singular_value,
              1.0 / std::sqrt(3.0), kRounding);
  const Coplanarity fan = coplanarity(planar({0.0, 60.0, 120.0}));
  EXPECT_TRUE(fan.nearly_coplanar);
  EXPECT_NEAR(std::abs(fan.normal.z()), 1.0, kRounding);
  EXPECT_NEAR(pbar_ceiling(3), std::sqrt(3.0) / 2.0, kCosRounding);
  EXPECT_NEAR(pbar_ceiling(4), 0.9238795325112867, kCosRounding);
  EXPECT_THROW(pbar_ceiling(0), InvalidArgument);
}

TEST(Augment, RejectsBadInput) {
  AugmentOptions o;
  o.circle_samples = 2;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("circle_samples"), std::string::npos);
  const Layout triad = direction_layout(Eigen::Matrix3d::Identity());
  EXPECT_THROW(augment_layout(triad, o), InvalidArgument);
  AugmentOptions c;
  c.candidates_only = true;
  EXPECT_THROW(augment_layout(triad, c), InvalidArgument) << "no candidates to choose from";
}

// The library owns the rules the `vantage design` command used to check alone (issue 34, item
// 4): a candidate on a marker or on another candidate, and the largest margin. Each error names
// the field and the entries, so that every front end can say it in its own words.
TEST(Augment, RefusesCandidatesThatCoincideAndMarginsPastTheLimit) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries = (Eigen::Matrix3Xd(3, 4) << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1).finished();
  layout.weights = Eigen::VectorXd::Ones(4);
  layout.candidates = (Eigen::Matrix3Xd(3, 3) << 1, 2, 1, 1, 2, 1, 1, 2, 1).finished();
  AugmentOptions options;
  options.add = 1;
  options.candidates_only = true;
  options.run_direct = false;
  try {
    augment_layout(layout, options);
    ADD_FAILURE() << "candidates[2] repeats candidates[0]";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "candidates");
    EXPECT_EQ(e.index(), 2);
    EXPECT_STREQ(e.what(), "candidates[2]: coincides with candidates[0]");
  }
  layout.candidates.col(2) = layout.entries.col(3);
  try {
    augment_layout(layout, options);
    ADD_FAILURE() << "candidates[2] sits on points[3]";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "candidates[2]: coincides with points[3]");
  }
  // Within the separation (1e-9 of the box's largest side, 1.5 here), not only equal.
  layout.candidates.col(2) = layout.entries.col(3) + Eigen::Vector3d(1e-10, 0, 0);
  EXPECT_THROW(augment_layout(layout, options), InvalidArgument);
  layout.candidates.col(2) = layout.entries.col(3) + Eigen::Vector3d(1e-6, 0, 0);
  EXPECT_NO_THROW(augment_layout(layout, options));

  options.margin = AugmentOptions::kMaxMargin * 1.5;
  try {
    augment_layout(layout, options);
    ADD_FAILURE() << "margin past the limit";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "options.margin");
    EXPECT_EQ(e.problem(), "must be in [0, 100]");
  }
}

}  // namespace
}  // namespace vantage::design
