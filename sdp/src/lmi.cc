#include "vantage/sdp/lmi.h"

#include <cmath>
#include <sstream>

#include "csdp_backend.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage::sdp {

using vantage::internal::fail;

namespace {

void check_index(const char* arg, int index, int size) {
  if (index < 0 || index >= size) {
    fail(arg, "must be in [0, " + std::to_string(size) + "), got " + std::to_string(index));
  }
}

}  // namespace

const char* to_string(SdpBackend backend) {
  switch (backend) {
    case SdpBackend::kCsdp:
      return "csdp";
  }
  return "unknown";
}

const char* to_string(SdpStatus status) {
  switch (status) {
    case SdpStatus::kOptimal:
      return "optimal";
    case SdpStatus::kUnbounded:
      return "unbounded";
    case SdpStatus::kInfeasible:
      return "infeasible";
    case SdpStatus::kOptimalReducedAccuracy:
      return "optimal_reduced_accuracy";
    case SdpStatus::kMaxIterations:
      return "max_iterations";
    case SdpStatus::kStuckPrimal:
      return "stuck_primal";
    case SdpStatus::kStuckDual:
      return "stuck_dual";
    case SdpStatus::kNoProgress:
      return "no_progress";
    case SdpStatus::kSingular:
      return "singular";
    case SdpStatus::kNumericalError:
      return "numerical_error";
    case SdpStatus::kBackendError:
      return "backend_error";
  }
  return "unknown";
}

bool has_solution(SdpStatus status) {
  return status == SdpStatus::kOptimal || status == SdpStatus::kOptimalReducedAccuracy;
}

LmiProblem::LmiProblem(int num_variables) : num_variables_(num_variables) {
  if (num_variables < 1)
    fail("num_variables", "must be >= 1, got " + std::to_string(num_variables));
  c_ = Eigen::VectorXd::Zero(num_variables);
}

int LmiProblem::add_dense_block(int size) {
  if (size < 1) fail("size", "must be >= 1, got " + std::to_string(size));
  blocks_.push_back({BlockKind::kDense, size});
  return num_blocks() - 1;
}

int LmiProblem::add_diagonal_block(int size) {
  if (size < 1) fail("size", "must be >= 1, got " + std::to_string(size));
  blocks_.push_back({BlockKind::kDiagonal, size});
  return num_blocks() - 1;
}

void LmiProblem::set_objective(int variable, double value) {
  check_index("variable", variable, num_variables_);
  if (!std::isfinite(value)) fail("value", "not finite");
  c_(variable) = value;
}

void LmiProblem::add_constant_entry(int block, int row, int col, double value) {
  add_entry(0, block, row, col, value);
}

void LmiProblem::add_variable_entry(int variable, int block, int row, int col, double value) {
  check_index("variable", variable, num_variables_);
  add_entry(variable + 1, block, row, col, value);
}

void LmiProblem::add_entry(int matrix, int block, int row, int col, double value) {
  check_index("block", block, num_blocks());
  const Block& b = blocks_[block];
  if (row < 0 || col < 0 || row >= b.size || col >= b.size) {
    fail("row, col",
         "outside block " + std::to_string(block) + " of size " + std::to_string(b.size));
  }
  if (b.kind == BlockKind::kDiagonal && row != col) {
    fail("row, col", "off-diagonal entry in diagonal block " + std::to_string(block));
  }
  if (!std::isfinite(value)) fail("value", "not finite");
  if (row > col) std::swap(row, col);
  entries_.push_back({matrix, block, row, col, value});
}

Eigen::MatrixXd LmiProblem::lmi_matrix(const Eigen::VectorXd& y) const {
  if (y.size() != num_variables_) {
    fail("y", "has " + std::to_string(y.size()) +
                  " entries, expected num_variables = " + std::to_string(num_variables_));
  }
  std::vector<int> offset(blocks_.size() + 1, 0);
  for (size_t b = 0; b < blocks_.size(); ++b) offset[b + 1] = offset[b] + blocks_[b].size;
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(offset.back(), offset.back());
  for (const Entry& e : entries_) {
    const double scale = e.matrix == 0 ? -1.0 : y(e.matrix - 1);
    const int r = offset[e.block] + e.row;
    const int c = offset[e.block] + e.col;
    F(r, c) += scale * e.value;
    if (r != c) F(c, r) += scale * e.value;
  }
  return F;
}

bool SdpOptions::is_valid(std::string* why) const {
  using vantage::internal::invalid_option;
  if (!(tolerance > 0.0 && tolerance <= 1e-2)) {
    return invalid_option(why, "tolerance", "must be in (0, 1e-2]");
  }
  if (max_iterations < 1) return invalid_option(why, "max_iterations", "must be >= 1");
  return true;
}

SdpResult solve_lmi(const LmiProblem& problem, const SdpOptions& options) {
  vantage::internal::check_options("options", options);
  if (problem.num_blocks() == 0) fail("problem", "has no block");
  std::vector<bool> used(problem.num_variables(), false);
  for (const LmiProblem::Entry& e : problem.entries()) {
    if (e.matrix > 0 && e.value != 0.0) used[e.matrix - 1] = true;
  }
  for (int j = 0; j < problem.num_variables(); ++j) {
    if (!used[j]) {
      std::ostringstream out;
      out << "F_" << j + 1 << " (the matrix of y[" << j << "]) is zero";
      fail("problem", out.str());
    }
  }
  switch (options.backend) {
    case SdpBackend::kCsdp:
      return internal::solve_with_csdp(problem, options);
  }
  fail("options.backend", "unknown");
}

}  // namespace vantage::sdp
