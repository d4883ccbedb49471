#include "vantage/sdp/lmi.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"

namespace vantage::sdp {
namespace {

using testing::kSeed;

// CSDP stops at relative gap / infeasibility 1e-8; objective values of O(1) problems agree with
// their closed forms to a few times that.
constexpr double kSdpTolerance = 1e-6;
// The LMI matrix at the returned y may have eigenvalues slightly below zero by the same order.
constexpr double kPsdSlack = 1e-7;

double min_eigenvalue(const Eigen::MatrixXd& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues().minCoeff();
}

TEST(SolveLmi, LinearProgram) {
  // min 2 y1 + 3 y2 s.t. y1 >= 1, y2 >= 1, y1 + y2 >= 3  ->  y = (2, 1), objective 7.
  LmiProblem lp(2);
  const int b = lp.add_diagonal_block(3);
  lp.set_objective(0, 2.0);
  lp.set_objective(1, 3.0);
  lp.add_variable_entry(0, b, 0, 0, 1.0);
  lp.add_variable_entry(1, b, 1, 1, 1.0);
  lp.add_variable_entry(0, b, 2, 2, 1.0);
  lp.add_variable_entry(1, b, 2, 2, 1.0);
  lp.add_constant_entry(b, 0, 0, 1.0);
  lp.add_constant_entry(b, 1, 1, 1.0);
  lp.add_constant_entry(b, 2, 2, 3.0);
  ::testing::internal::CaptureStdout();
  const SdpResult r = solve_lmi(lp);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "") << "the backend must be silent";
  ASSERT_EQ(r.status, SdpStatus::kOptimal) << r.message;
  EXPECT_EQ(r.backend, "csdp");
  EXPECT_EIGEN_NEAR(r.y, Eigen::Vector2d(2.0, 1.0), kSdpTolerance);
  EXPECT_NEAR(r.primal_objective, 7.0, kSdpTolerance);
  EXPECT_NEAR(r.dual_objective, 7.0, kSdpTolerance);
  EXPECT_NEAR(r.gap, 0.0, kSdpTolerance);
  EXPECT_GE(min_eigenvalue(lp.lmi_matrix(r.y)), -kPsdSlack);
}

TEST(SolveLmi, HyperbolicConstraint) {
  // min y1 + y2 s.t. [[y1, 1], [1, y2]] >= 0, i.e. y1 y2 >= 1, y >= 0  ->  y = (1, 1).
  LmiProblem p(2);
  const int b = p.add_dense_block(2);
  p.set_objective(0, 1.0);
  p.set_objective(1, 1.0);
  p.add_variable_entry(0, b, 0, 0, 1.0);
  p.add_variable_entry(1, b, 1, 1, 1.0);
  p.add_constant_entry(b, 0, 1, -1.0);
  const SdpResult r = solve_lmi(p);
  ASSERT_EQ(r.status, SdpStatus::kOptimal) << r.message;
  EXPECT_EIGEN_NEAR(r.y, Eigen::Vector2d(1.0, 1.0), kSdpTolerance);
  EXPECT_NEAR(r.primal_objective, 2.0, kSdpTolerance);
}

TEST(SolveLmi, LargestEigenvalueOfRandomMatrices) {
  // min y s.t. y I - A >= 0 is lambda_max(A); mixed with an LP block y >= -10 that is inactive.
  std::mt19937 rng(kSeed);
  for (int trial = 0; trial < 5; ++trial) {
    const int size = 2 + trial;
    Eigen::MatrixXd A = Eigen::MatrixXd::Random(size, size);
    A = (A + A.transpose()).eval();
    LmiProblem p(1);
    const int dense = p.add_dense_block(size);
    const int lp = p.add_diagonal_block(1);
    p.set_objective(0, 1.0);
    for (int i = 0; i < size; ++i) {
      p.add_variable_entry(0, dense, i, i, 1.0);
      for (int j = i; j < size; ++j) p.add_constant_entry(dense, i, j, A(i, j));
    }
    p.add_variable_entry(0, lp, 0, 0, 1.0);
    p.add_constant_entry(lp, 0, 0, -10.0);
    const SdpResult r = solve_lmi(p);
    ASSERT_EQ(r.status, SdpStatus::kOptimal) << r.message;
    const double lambda_max =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff();
    EXPECT_NEAR(r.y(0), lambda_max, kSdpTolerance);
    EXPECT_GE(min_eigenvalue(p.lmi_matrix(r.y)), -kPsdSlack);
  }
}

TEST(SolveLmi, InfeasibleProblem) {
  // y >= 1 and -y >= 0 cannot both hold.
  LmiProblem p(1);
  const int b = p.add_diagonal_block(2);
  p.set_objective(0, 1.0);
  p.add_variable_entry(0, b, 0, 0, 1.0);
  p.add_variable_entry(0, b, 1, 1, -1.0);
  p.add_constant_entry(b, 0, 0, 1.0);
  ::testing::internal::CaptureStdout();
  const SdpResult r = solve_lmi(p);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(r.status, SdpStatus::kInfeasible) << r.message;
  EXPECT_FALSE(has_solution(r.status));
}

TEST(SolveLmi, UnboundedProblem) {
  // min -y1 s.t. [[y1, y2], [y2, 1]] >= 0: y1 >= y2^2 has no upper limit on y1.
  LmiProblem p(2);
  const int b = p.add_dense_block(2);
  p.set_objective(0, -1.0);
  p.add_variable_entry(0, b, 0, 0, 1.0);
  p.add_variable_entry(1, b, 0, 1, 1.0);
  p.add_constant_entry(b, 1, 1, -1.0);
  const SdpResult r = solve_lmi(p);
  EXPECT_EQ(r.status, SdpStatus::kUnbounded) << r.message;
  // The certificate is an improving ray: c^T y < 0 with sum y_j F_j >= 0.
  EXPECT_LT(-r.y(0), 0.0);
}

TEST(SolveLmi, StatusNames) {
  EXPECT_STREQ(to_string(SdpStatus::kOptimal), "optimal");
  EXPECT_STREQ(to_string(SdpStatus::kInfeasible), "infeasible");
  EXPECT_STREQ(to_string(SdpStatus::kUnbounded), "unbounded");
  EXPECT_STREQ(to_string(SdpBackend::kCsdp), "csdp");
  EXPECT_TRUE(has_solution(SdpStatus::kOptimalReducedAccuracy));
}

TEST(SolveLmi, RejectsBadInput) {
  EXPECT_THROW(LmiProblem(0), InvalidArgument);
  LmiProblem p(2);
  const int b = p.add_diagonal_block(1);
  EXPECT_THROW(p.add_variable_entry(0, b, 0, 1, 1.0), InvalidArgument);
  EXPECT_THROW(p.add_variable_entry(2, b, 0, 0, 1.0), InvalidArgument);
  EXPECT_THROW(p.add_constant_entry(1, 0, 0, 1.0), InvalidArgument);
  p.add_variable_entry(0, b, 0, 0, 1.0);
  EXPECT_THROW(solve_lmi(p), InvalidArgument) << "F_2 is zero";
  p.add_variable_entry(1, b, 0, 0, 1.0);
  p.add_variable_entry(1, b, 0, 0, -1.0);
  EXPECT_THROW(solve_lmi(p), InvalidArgument) << "F_2 sums to zero";
  SdpOptions bad;
  bad.tolerance = 0.0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("tolerance"), std::string::npos);
}

}  // namespace
}  // namespace vantage::sdp
