#include "vantage/design/weights.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage::design {
namespace {

using testing::kSeed;

// Eq. (11) must hold to this (the requirement); the weights are O(1) and the LP solution
// is mapped back through an orthonormal null-space basis, so rounding is ~1e-15.
constexpr double kNullSpaceTolerance = 1e-9;
// The LP's optimum s* agrees with an exact vertex enumeration to CSDP's accuracy (~1e-8
// relative) on O(1) weights.
constexpr double kLpTolerance = 1e-6;
// Sum of weights equals n up to rounding.
constexpr double kSumTolerance = 1e-9;

// A suggested entry is the negated sum or partner of exact inputs: no rounding.
constexpr double kExact = 0.0;
// The reported residual is the same norm recomputed here: rounding of a norm of O(1e-15).
constexpr double kResidualRecomputed = 1e-15;
// The origin shift is a centroid of four exact points: rounding of a few sums.
constexpr double kShiftRounding = 1e-12;
// Sum of 100 000 weights equals n up to the rounding of the sum (~1e5 x eps x 1e5).
constexpr double kLargeSumTolerance = 1e-6;
// Eq. (11) on 100 000 entries: a few thousand ulps of the size of the terms summed.
constexpr double kRelativeResidual = 1e-12;

void expect_valid_weights(const Eigen::Matrix3Xd& z, const Weights& w) {
  ASSERT_TRUE(w.feasible) << w.message;
  ASSERT_EQ(w.weights.size(), z.cols());
  EXPECT_GE(w.weights.minCoeff(), 0.0);
  EXPECT_NEAR(w.weights.sum(), static_cast<double>(z.cols()), kSumTolerance);
  EXPECT_LE((z * w.weights).norm(), kNullSpaceTolerance);
  EXPECT_NEAR(w.residual, (z * w.weights).norm(), kResidualRecomputed);
  EXPECT_DOUBLE_EQ(w.min_weight, w.weights.minCoeff());
}

// max s s.t. Z w = 0, 1^T w = n, w_i >= s, by enumerating the vertices of the (pointed)
// polyhedron: every choice of n - 3 active constraints w_i = s that fixes (w, s) uniquely.
// Returns -infinity when [Z; 1^T] w = [0; n] has full row rank 4 and no vertex is feasible.
double brute_force_max_min(const Eigen::Matrix3Xd& z) {
  const int n = static_cast<int>(z.cols());
  double best = -std::numeric_limits<double>::infinity();
  const int active = n - 3;
  std::vector<bool> choose(n, false);
  std::fill(choose.begin(), choose.begin() + active, true);
  do {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 1, n + 1);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
    m.topLeftCorner(3, n) = z;
    m.block(3, 0, 1, n).setOnes();
    rhs(3) = n;
    int row = 4;
    for (int i = 0; i < n; ++i) {
      if (!choose[i]) continue;
      m(row, i) = 1.0;
      m(row, n) = -1.0;
      ++row;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
    if (lu.rank() < n + 1) continue;
    const Eigen::VectorXd x = lu.solve(rhs);
    const double s = x(n);
    if ((x.head(n).array() >= s - 1e-12).all()) best = std::max(best, s);
  } while (std::prev_permutation(choose.begin(), choose.end()));
  return best;
}

TEST(NullspaceWeights, SymmetricPairsGiveEqualWeights) {
  Eigen::Matrix3Xd z(3, 6);
  z << 1, -1, 0, 0, 0, 0,  //
      0, 0, 2, -2, 0, 0,   //
      0, 0, 0, 0, 3, -3;
  const Weights w = nullspace_weights(z);
  EXPECT_EQ(w.status, Weights::Status::kPositive);
  expect_valid_weights(z, w);
  EXPECT_NEAR(w.min_weight, 1.0, kLpTolerance);
  EXPECT_TRUE(w.suggestions.empty());
}

TEST(NullspaceWeights, MaxMinMatchesVertexEnumerationOnRandomLayouts) {
  std::mt19937 rng(kSeed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  int positive = 0, infeasible = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 4 + trial % 4;
    Eigen::Matrix3Xd z(3, n);
    for (int i = 0; i < n; ++i) {
      z.col(i) =
          Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)) + Eigen::Vector3d(0.4, 0.0, 0.0);
    }
    const Weights w = nullspace_weights(z);
    const double exact = brute_force_max_min(z);
    ASSERT_NE(w.status, Weights::Status::kSolverFailed) << w.message;
    if (exact > 1e-3) {
      ++positive;
      EXPECT_EQ(w.status, Weights::Status::kPositive) << "trial " << trial;
      expect_valid_weights(z, w);
      EXPECT_NEAR(w.min_weight, exact, kLpTolerance) << "trial " << trial;
    } else if (exact < -1e-3) {
      ++infeasible;
      EXPECT_EQ(w.status, Weights::Status::kInfeasible) << "trial " << trial;
      EXPECT_FALSE(w.feasible);
      EXPECT_NEAR(w.lp_optimum, exact, kLpTolerance) << "trial " << trial;
    }
  }
  EXPECT_GT(positive, 5) << "the random cases should exercise both outcomes";
  EXPECT_GT(infeasible, 5) << "the random cases should exercise both outcomes";
}

TEST(NullspaceWeights, OriginOutsideHullIsInfeasibleAndPartnerFixVerified) {
  Eigen::Matrix3Xd z(3, 4);
  z << 1, 2, 1.5, 1,  //
      0, 1, -1, 0.5,  //
      0, 0.5, 0.2, -1;
  const Weights w = nullspace_weights(z);
  EXPECT_EQ(w.status, Weights::Status::kInfeasible);
  EXPECT_FALSE(w.feasible);
  EXPECT_LT(w.lp_optimum, 0.0);
  EXPECT_EQ(w.weights.size(), 0);
  ASSERT_FALSE(w.suggestions.empty());
  const WeightsSuggestion* partner = nullptr;
  for (const WeightsSuggestion& candidate : w.suggestions) {
    if (candidate.kind == WeightsSuggestion::Kind::kSymmetricPartner) partner = &candidate;
  }
  ASSERT_NE(partner, nullptr);
  const WeightsSuggestion& s = *partner;
  ASSERT_GE(s.index, 0);
  EXPECT_EIGEN_NEAR(s.added, Eigen::Vector3d(-z.col(s.index)), kExact);
  Eigen::Matrix3Xd fixed(3, 5);
  fixed << z, s.added;
  const Weights again = nullspace_weights(fixed);
  expect_valid_weights(fixed, again);
  EXPECT_NEAR(again.min_weight, s.min_weight, kLpTolerance);
  // The suggestion is the best single partner.
  for (int i = 0; i < 4; ++i) {
    Eigen::Matrix3Xd other(3, 5);
    other << z, -z.col(i);
    const Weights o = nullspace_weights(other);
    EXPECT_LE(o.min_weight, s.min_weight + kLpTolerance) << "partner of " << i;
  }
}

TEST(NullspaceWeights, PointsOnAPlaneMissingTheOriginAreInfeasibleAndShiftFixes) {
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, 4);
  layout.entries << 0, 1, 1, 0,  //
      0, 0, 1, 1,                //
      2, 2, 2, 2;
  layout.weights = Eigen::VectorXd::Ones(4);
  const Weights w = layout_weights(layout);
  EXPECT_EQ(w.status, Weights::Status::kInfeasible);
  bool have_shift = false;
  for (const WeightsSuggestion& s : w.suggestions) {
    if (s.kind != WeightsSuggestion::Kind::kShiftOrigin) continue;
    have_shift = true;
    EXPECT_EIGEN_NEAR(s.shift, Eigen::Vector3d(0.5, 0.5, 2.0), kShiftRounding);
    const Eigen::Matrix3Xd shifted = layout.entries.colwise() - s.shift;
    const Weights again = nullspace_weights(shifted);
    EXPECT_EQ(again.status, Weights::Status::kPositive);
    expect_valid_weights(shifted, again);
    EXPECT_NEAR(again.min_weight, 1.0, kLpTolerance);
  }
  EXPECT_TRUE(have_shift);
}

TEST(NullspaceWeights, DirectionModeNeverSuggestsAShift) {
  Layout layout;
  layout.entries = Eigen::Matrix3d::Identity();
  layout.weights = Eigen::VectorXd::Ones(3);
  const Weights w = layout_weights(layout);
  EXPECT_EQ(w.status, Weights::Status::kInfeasible);
  ASSERT_FALSE(w.suggestions.empty());
  for (const WeightsSuggestion& s : w.suggestions) {
    EXPECT_NE(s.kind, WeightsSuggestion::Kind::kShiftOrigin);
  }
}

TEST(NullspaceWeights, BalancingEntryAlwaysGivesStrictlyPositiveWeights) {
  // Z = I: the best single symmetric partner only reaches a smallest weight of 0, while one
  // entry at -(1, 1, 1) lets all four weights be equal (1 after normalising to sum 4).
  const Weights w = nullspace_weights(Eigen::Matrix3d::Identity());
  ASSERT_FALSE(w.suggestions.empty());
  const WeightsSuggestion& best = w.suggestions.front();
  EXPECT_EQ(best.kind, WeightsSuggestion::Kind::kBalancingEntry);
  EXPECT_EIGEN_NEAR(best.added, Eigen::Vector3d(-1, -1, -1), kExact);
  EXPECT_NEAR(best.min_weight, 1.0, kLpTolerance);
  Eigen::Matrix3Xd fixed(3, 4);
  fixed << Eigen::Matrix3d::Identity(), best.added;
  expect_valid_weights(fixed, nullspace_weights(fixed));
  // Random infeasible layouts: the balancing entry's weights are strictly positive.
  std::mt19937 rng(testing::kSeed + 77);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Matrix3Xd z = testing::random_points(rng, 5).array() + 2.0;
    const Weights r = nullspace_weights(z);
    ASSERT_EQ(r.status, Weights::Status::kInfeasible);
    bool found = false;
    for (const WeightsSuggestion& s : r.suggestions) {
      if (s.kind != WeightsSuggestion::Kind::kBalancingEntry) continue;
      found = true;
      EXPECT_GT(s.min_weight, kLpTolerance);
    }
    EXPECT_TRUE(found);
  }
}

TEST(NullspaceWeights, OriginOnHullBoundaryForcesZeros) {
  // x and -x balance; y cannot be balanced by anything: its weight must be 0.
  Eigen::Matrix3Xd z(3, 4);
  z << 1, -1, 0, 0.5,  //
      0, 0, 1, 0,      //
      0, 0, 0, 0;
  const Weights w = nullspace_weights(z);
  EXPECT_EQ(w.status, Weights::Status::kBoundary);
  expect_valid_weights(z, w);
  EXPECT_EQ(w.zero_forced, std::vector<int>{2});
  EXPECT_EQ(w.weights(2), 0.0);
  // The others: w1 = w0 + 0.5 w3 and w0 + w1 + w3 = 4; the max-min has w0 = w3 = a,
  // w1 = 1.5 a, 3.5 a = 4.
  EXPECT_NEAR(w.weights(0), 4.0 / 3.5, kLpTolerance);
  EXPECT_NEAR(w.weights(3), 4.0 / 3.5, kLpTolerance);
  EXPECT_FALSE(w.suggestions.empty()) << "a boundary layout still gets the paper's fixes";
}

// The dual active-set solver and the CSDP primal are independent implementations of one LP: they
// must agree on s* and on the classification, with valid weights from both.
TEST(NullspaceWeights, ActiveSetAgreesWithCsdp) {
  std::mt19937 rng(kSeed + 5);
  std::normal_distribution<double> gauss(0.0, 1.0);
  WeightsOptions csdp;
  csdp.solver = WeightsOptions::Solver::kCsdp;
  csdp.suggest = false;
  WeightsOptions active;
  active.suggest = false;
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 4 + trial % 40;
    const double shift = 0.05 * (trial % 12);  // from balanced to far outside
    Eigen::Matrix3Xd z(3, n);
    for (int i = 0; i < n; ++i) {
      z.col(i) = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)) + Eigen::Vector3d(shift, 0, 0);
    }
    const Weights a = nullspace_weights(z, active);
    const Weights c = nullspace_weights(z, csdp);
    ASSERT_NE(c.status, Weights::Status::kSolverFailed) << c.message;
    EXPECT_EQ(a.status, c.status) << "trial " << trial;
    EXPECT_NEAR(a.lp_optimum, c.lp_optimum, kLpTolerance) << "trial " << trial;
    if (a.feasible) expect_valid_weights(z, a);
    ++compared;
  }
  EXPECT_EQ(compared, 60);
}

TEST(NullspaceWeights, PlanarAndCollinearLayoutsOnBothSolvers) {
  // z in the plane z = 0 (the dual is unbounded along e_z with a zero objective there), and on
  // one line through the origin.
  Eigen::Matrix3Xd planar(3, 5);
  planar << 1, -1, 0, 0, 0.5,  //
      0, 0, 1, -2, 0.5,        //
      0, 0, 0, 0, 0;
  Eigen::Matrix3Xd line(3, 3);
  line << 1, -2, 3,  //
      2, -4, 6,      //
      0, 0, 0;
  WeightsOptions csdp;
  csdp.solver = WeightsOptions::Solver::kCsdp;
  for (const Eigen::Matrix3Xd& z : {planar, line}) {
    const Weights a = nullspace_weights(z);
    const Weights c = nullspace_weights(z, csdp);
    EXPECT_EQ(a.status, Weights::Status::kPositive);
    EXPECT_NEAR(a.lp_optimum, c.lp_optimum, kLpTolerance);
    expect_valid_weights(z, a);
  }
}

TEST(NullspaceWeights, HundredThousandEntriesInLinearMemory) {
  // The old CSDP path built an n x n null-space basis (80 GB here); the dual needs O(n).
  constexpr int kEntries = 100000;
  std::mt19937 rng(kSeed + 9);
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::Matrix3Xd z(3, kEntries);
  for (int i = 0; i < kEntries; ++i) {
    z.col(i) = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)) + Eigen::Vector3d(0.2, 0, 0);
  }
  const Weights w = nullspace_weights(z);
  ASSERT_EQ(w.status, Weights::Status::kPositive) << w.message;
  ASSERT_EQ(w.weights.size(), kEntries);
  EXPECT_GE(w.weights.minCoeff(), 0.0);
  EXPECT_NEAR(w.weights.sum(), kEntries, kLargeSumTolerance);
  // Eq. (11) relative to the size of the terms summed.
  const double terms = (z.colwise().norm().transpose().array() * w.weights.array()).sum();
  EXPECT_LE((z * w.weights).norm(), kRelativeResidual * terms);
  // Optimality is checked independently where CSDP is quick: on the first 200 entries.
  const Eigen::Matrix3Xd head = z.leftCols(200);
  WeightsOptions csdp;
  csdp.solver = WeightsOptions::Solver::kCsdp;
  csdp.suggest = false;
  EXPECT_NEAR(nullspace_weights(head).lp_optimum, nullspace_weights(head, csdp).lp_optimum,
              kLpTolerance);
  // Infeasible at this size: the fixes stay O(n) (partners of the 32 farthest entries only).
  const Eigen::Matrix3Xd outside = z.array() + 3.0;
  const Weights far = nullspace_weights(outside);
  EXPECT_EQ(far.status, Weights::Status::kInfeasible);
  ASSERT_FALSE(far.suggestions.empty());
  EXPECT_GT(far.suggestions.front().min_weight, 0.0);
  EXPECT_LE(far.lp_solves, 40);
}

TEST(NullspaceWeights, CsdpRefusesLargeLayouts) {
  WeightsOptions csdp;
  csdp.solver = WeightsOptions::Solver::kCsdp;
  EXPECT_THROW(nullspace_weights(Eigen::Matrix3Xd::Ones(3, 2001), csdp), InvalidArgument);
}

TEST(NullspaceWeights, RejectsBadInput) {
  Eigen::Matrix3Xd z = Eigen::Matrix3Xd::Identity(3, 3);
  z(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(nullspace_weights(z), InvalidArgument);
  WeightsOptions bad;
  bad.zero_tolerance = 0.0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("zero_tolerance"), std::string::npos);
  EXPECT_THROW(nullspace_weights(Eigen::Matrix3Xd::Identity(3, 3), bad), InvalidArgument);
}

}  // namespace
}  // namespace vantage::design
