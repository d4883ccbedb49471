#include "vantage/sdp/lmi.h"

#include <cmath>
#include <sstream>

#include "csdp_backend.h"
#include "vantage/analysis/common.h"

namespace vantage::sdp {

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
  if (num_variables < 1) {
    throw InvalidArgument("LmiProblem: num_variables must be >= 1, got " +
                          std::to_string(num_variables));
  }
  c_ = Eigen::VectorXd::Zero(num_variables);
}

int LmiProblem::add_dense_block(int size) {
  if (size < 1) throw InvalidArgument("LmiProblem::add_dense_block: size must be >= 1");
  blocks_.push_back({BlockKind::kDense, size});
  return num_blocks() - 1;
}

int LmiProblem::add_diagonal_block(int size) {
  if (size < 1) throw InvalidArgument("LmiProblem::add_diagonal_block: size must be >= 1");
  blocks_.push_back({BlockKind::kDiagonal, size});
  return num_blocks() - 1;
}

void LmiProblem::set_objective(int variable, double value) {
  if (variable < 0 || variable >= num_variables_) {
    throw InvalidArgument("LmiProblem::set_objective: variable out of range");
  }
  if (!std::isfinite(value)) throw InvalidArgument("LmiProblem::set_objective: value not finite");
  c_(variable) = value;
}

void LmiProblem::add_constant_entry(int block, int row, int col, double value) {
  add_entry(0, block, row, col, value);
}

void LmiProblem::add_variable_entry(int variable, int block, int row, int col, double value) {
  if (variable < 0 || variable >= num_variables_) {
    throw InvalidArgument("LmiProblem::add_variable_entry: variable out of range");
  }
  add_entry(variable + 1, block, row, col, value);
}

void LmiProblem::add_entry(int matrix, int block, int row, int col, double value) {
  if (block < 0 || block >= num_blocks()) {
    throw InvalidArgument("LmiProblem: block index " + std::to_string(block) + " out of range");
  }
  const Block& b = blocks_[block];
  if (row < 0 || col < 0 || row >= b.size || col >= b.size) {
    throw InvalidArgument("LmiProblem: entry (row, col) outside block " + std::to_string(block));
  }
  if (b.kind == BlockKind::kDiagonal && row != col) {
    throw InvalidArgument("LmiProblem: off-diagonal entry in diagonal block " +
                          std::to_string(block));
  }
  if (!std::isfinite(value)) throw InvalidArgument("LmiProblem: entry value not finite");
  if (row > col) std::swap(row, col);
  entries_.push_back({matrix, block, row, col, value});
}

Eigen::MatrixXd LmiProblem::lmi_matrix(const Eigen::VectorXd& y) const {
  if (y.size() != num_variables_) throw InvalidArgument("LmiProblem::lmi_matrix: y has wrong size");
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
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (!(tolerance > 0.0 && tolerance <= 1e-2)) {
    return fail("SdpOptions::tolerance must be in (0, 1e-2]");
  }
  if (max_iterations < 1) return fail("SdpOptions::max_iterations must be >= 1");
  return true;
}

SdpResult solve_lmi(const LmiProblem& problem, const SdpOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("solve_lmi: options: " + why);
  if (problem.num_blocks() == 0) throw InvalidArgument("solve_lmi: problem has no block");
  std::vector<bool> used(problem.num_variables(), false);
  for (const LmiProblem::Entry& e : problem.entries()) {
    if (e.matrix > 0 && e.value != 0.0) used[e.matrix - 1] = true;
  }
  for (int j = 0; j < problem.num_variables(); ++j) {
    if (!used[j]) {
      std::ostringstream out;
      out << "solve_lmi: problem: F_" << j + 1 << " (the matrix of y[" << j << "]) is zero";
      throw InvalidArgument(out.str());
    }
  }
  switch (options.backend) {
    case SdpBackend::kCsdp:
      return internal::solve_with_csdp(problem, options);
  }
  throw InvalidArgument("solve_lmi: options.backend unknown");
}

}  // namespace vantage::sdp
