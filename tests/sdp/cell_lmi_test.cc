// solve_cell_lmi() solves large cells by constraint generation: its answers must be those of the
// whole LMI, built here independently and solved in one CSDP call.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "support/eigen_testing.h"
#include "vantage/sdp/lmi.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {
namespace {

using testing::kSeed;

// Both are CSDP optima at relative accuracy 1e-8: t agrees to about 1e-7.
constexpr double kSdp = 1e-6;

// t is reported as this very minimum over the vectors: the rounding of one dot product.
constexpr double kRounding = 1e-15;

// Eq. (28) on every signed vector, written out from the paper: max t s.t. s_i a.n_i >= |t| as a
// 2x2 block per vector, ||a|| <= 1 as [[I, a], [a^T, 1]] >= 0.
double whole_lmi_t(const Eigen::Matrix3Xd& n, const Eigen::VectorXd& signs) {
  LmiProblem problem(4);
  problem.set_objective(3, -1.0);
  for (Eigen::Index i = 0; i < n.cols(); ++i) {
    const int b = problem.add_dense_block(2);
    for (int k = 0; k < 3; ++k) {
      problem.add_variable_entry(k, b, 0, 0, signs(i) * n(k, i));
      problem.add_variable_entry(k, b, 1, 1, signs(i) * n(k, i));
    }
    problem.add_variable_entry(3, b, 0, 1, 1.0);
  }
  const int ball = problem.add_dense_block(4);
  for (int k = 0; k < 3; ++k) problem.add_variable_entry(k, ball, k, 3, 1.0);
  for (int k = 0; k < 4; ++k) problem.add_constant_entry(ball, k, k, -1.0);
  const SdpResult result = solve_lmi(problem);
  EXPECT_TRUE(has_solution(result.status)) << result.message;
  return result.y(3);
}

Eigen::Matrix3Xd random_directions(std::mt19937& rng, int m) {
  Eigen::Matrix3Xd n(3, m);
  for (int i = 0; i < m; ++i) n.col(i) = testing::random_unit_vector(rng);
  return n;
}

// The signs of the cell that contains viewpoint a.
Eigen::VectorXd cell_of(const Eigen::Matrix3Xd& n, const Eigen::Vector3d& a) {
  return (n.transpose() * a).array().sign().matrix();
}

TEST(CellLmiGeneration, LargeCellsEqualTheWholeLmi) {
  std::mt19937 rng(kSeed);
  for (int m : {33, 100, 400, 1500}) {
    const Eigen::Matrix3Xd n = random_directions(rng, m);
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd signs = cell_of(n, testing::random_unit_vector(rng));
      const CellViewpoint cell = solve_cell_lmi(n, signs);
      const double whole = whole_lmi_t(n, signs);
      SCOPED_TRACE(::testing::Message() << "m = " << m << ", trial " << trial);
      ASSERT_EQ(cell.status, CellViewpoint::Status::kOk) << cell.message;
      EXPECT_NEAR(cell.t, whole, kSdp);
      // t is attained over all m vectors at the reported viewpoint.
      EXPECT_NEAR((signs.asDiagonal() * (n.transpose() * cell.viewpoint)).cwiseAbs().minCoeff(),
                  cell.t, kRounding);
      EXPECT_LT(cell.lmi_vectors, m) << "the answer came from a subset of the cell";
      EXPECT_GE(cell.lmi_solves, 1);
    }
  }
}

TEST(CellLmiGeneration, PaperSignsOfALargeLayoutEqualTheWholeLmi) {
  std::mt19937 rng(kSeed + 1);
  const Eigen::Matrix3Xd n = random_directions(rng, 800);
  const CellViewpoint paper = paper_worst_viewpoint(n);
  ASSERT_EQ(paper.status, CellViewpoint::Status::kOk) << paper.message;
  EXPECT_NEAR(paper.t, whole_lmi_t(n, paper_signs(n)), kSdp);
}

TEST(CellLmiGeneration, SmallCellsAreSolvedWhole) {
  std::mt19937 rng(kSeed + 2);
  const Eigen::Matrix3Xd n = random_directions(rng, 32);
  const CellViewpoint cell = solve_cell_lmi(n, cell_of(n, Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(cell.lmi_solves, 1);
  EXPECT_EQ(cell.lmi_vectors, 32);
}

TEST(CellLmiGeneration, EmptyLargeCellIsReportedEmpty) {
  // Random signs on 300 directions: the origin is in the hull of the signed vectors.
  std::mt19937 rng(kSeed + 3);
  const Eigen::Matrix3Xd n = random_directions(rng, 300);
  Eigen::VectorXd signs(300);
  for (int i = 0; i < 300; ++i) signs(i) = (rng() & 1) ? 1.0 : -1.0;
  const CellViewpoint cell = solve_cell_lmi(n, signs);
  EXPECT_EQ(cell.status, CellViewpoint::Status::kEmptyCell) << cell.message;
  EXPECT_LE(cell.t, CellViewpoint::kEmptyCellT);
  // The first 32 vectors alone leave a non-empty cell: the empty answer needed the check
  // against all 300 and a second round.
  EXPECT_GE(cell.lmi_solves, 2);
  EXPECT_NEAR(whole_lmi_t(n, signs), 0.0, kSdp);
}

}  // namespace
}  // namespace vantage::sdp
