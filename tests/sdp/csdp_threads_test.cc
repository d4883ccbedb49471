#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <atomic>
#include <random>
#include <thread>
#include <vector>

#include "support/eigen_testing.h"
#include "vantage/sdp/lmi.h"

namespace vantage::sdp {
namespace {

using testing::kSeed;

// As in lmi_test.cc: CSDP's 1e-8 relative gap gives O(1) objectives to a few times that.
constexpr double kSdpTolerance = 1e-6;
constexpr int kThreads = 4;
constexpr int kSolvesPerThread = 200;

// min y s.t. y I - A >= 0: lambda_max(A). One dense block, so CSDP's op_o() takes the path that
// uses its (process-wide) work matrices.
LmiProblem largest_eigenvalue_problem(const Eigen::MatrixXd& A) {
  LmiProblem p(1);
  const int dense = p.add_dense_block(static_cast<int>(A.rows()));
  p.set_objective(0, 1.0);
  for (int i = 0; i < A.rows(); ++i) {
    p.add_variable_entry(0, dense, i, i, 1.0);
    for (int j = i; j < A.cols(); ++j) p.add_constant_entry(dense, i, j, A(i, j));
  }
  return p;
}

// CSDP keeps op_o()'s work matrices in a static pointer: two solves at once used (and freed) each
// other's buffers and aborted the process. solve_lmi() must be safe to call from many threads,
// each solve returning the answer it returns alone.
TEST(SolveLmiThreads, ConcurrentSolvesOfDifferentSizesAgreeWithEigen) {
  std::vector<std::vector<Eigen::MatrixXd>> matrices(kThreads);
  std::mt19937 rng(kSeed);
  std::normal_distribution<double> normal;
  for (int t = 0; t < kThreads; ++t) {
    const int size = 2 + 3 * t;  // different block sizes: a foreign buffer would be too small
    for (int s = 0; s < kSolvesPerThread; ++s) {
      Eigen::MatrixXd A(size, size);
      for (int i = 0; i < size * size; ++i) A.data()[i] = normal(rng);
      matrices[t].push_back((A + A.transpose()) / 2.0);
    }
  }
  std::atomic<int> not_optimal{0};
  std::vector<std::vector<double>> answers(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (const Eigen::MatrixXd& A : matrices[t]) {
        const SdpResult r = solve_lmi(largest_eigenvalue_problem(A));
        if (r.status != SdpStatus::kOptimal) ++not_optimal;
        answers[t].push_back(r.y(0));
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(not_optimal.load(), 0);
  for (int t = 0; t < kThreads; ++t) {
    for (int s = 0; s < kSolvesPerThread; ++s) {
      const double lambda_max =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(matrices[t][s]).eigenvalues().maxCoeff();
      EXPECT_NEAR(answers[t][s], lambda_max, kSdpTolerance) << "thread " << t << " solve " << s;
    }
  }
}

}  // namespace
}  // namespace vantage::sdp
