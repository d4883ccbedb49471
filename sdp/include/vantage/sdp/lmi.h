#pragma once

/// A small, backend-neutral semidefinite program in LMI (dual) form and its solver front end.
///
///   minimise    c^T y            over y in R^k
///   subject to  F(y) = sum_{j=1..k} y_j F_j - F_0  is positive semidefinite,
///
/// where every F_j is block diagonal with the same block structure: diagonal blocks (each one a
/// set of linear inequalities, an LP part) and dense symmetric blocks. This is the form of the
/// paper's Theorem 6 (Eq. 28). Its Lagrange dual is
///
///   maximise    tr(F_0 X)   subject to  tr(F_j X) = c_j (j = 1..k),  X positive semidefinite.
///
/// Backends: CSDP (libsdp). CSDP's primal is max tr(C X) s.t. tr(A_j X) = a_j and its dual is
/// min a^T y s.t. sum y_j A_j - C >= 0, so the LMI problem is CSDP's dual with A_j = F_j,
/// C = F_0 and a = c. No backend type appears in this header.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace vantage::sdp {

/// Which SDP solver runs the problem.
enum class SdpBackend {
  kCsdp,  ///< CSDP 6 (Borchers), primal-dual interior point; silent, no file input
};

/// "csdp".
const char* to_string(SdpBackend backend);

/// Outcome of an SDP solve, in terms of the LMI problem (minimise c^T y s.t. F(y) >= 0).
/// CSDP return codes 0..10 map one to one onto the values below, in order.
enum class SdpStatus {
  kOptimal,                 ///< CSDP 0: solved to the requested relative accuracy
  kUnbounded,               ///< CSDP 1: certificate that the dual (max tr F_0 X) is infeasible:
                            ///< c^T y is unbounded below on a feasible LMI
  kInfeasible,              ///< CSDP 2: certificate that no y makes F(y) >= 0
  kOptimalReducedAccuracy,  ///< CSDP 3: a solution, but full accuracy was not reached
  kMaxIterations,           ///< CSDP 4: iteration limit (SdpOptions::max_iterations) reached
  kStuckPrimal,             ///< CSDP 5: stuck at the edge of the (CSDP-)primal feasible set
  kStuckDual,               ///< CSDP 6: stuck at the edge of the (CSDP-)dual feasible set
  kNoProgress,              ///< CSDP 7: lack of progress
  kSingular,                ///< CSDP 8: X, Z or the Schur complement O became singular
  kNumericalError,          ///< CSDP 9: NaN or Inf values detected
  kBackendError,            ///< CSDP 10 or any other code: the backend reported an error
};

/// "optimal", "unbounded", "infeasible", "optimal_reduced_accuracy", "max_iterations",
/// "stuck_primal", "stuck_dual", "no_progress", "singular", "numerical_error", "backend_error".
const char* to_string(SdpStatus status);

/// kOptimal or kOptimalReducedAccuracy: y is a usable (near-)optimal point.
bool has_solution(SdpStatus status);

/// Kind of one diagonal block of the F_j.
enum class BlockKind {
  kDiagonal,  ///< only diagonal entries: each one a scalar linear inequality (LP part)
  kDense,     ///< a dense symmetric block
};

/// The LMI problem above. Build it with add_*_block() then add_*_entry(); entries at the same
/// position add up. Off-diagonal entries are mirrored (the matrices are symmetric), so give each
/// (row, col) pair once. Indices are 0-based.
class LmiProblem {
 public:
  /// num_variables = k >= 1. Throws InvalidArgument otherwise.
  explicit LmiProblem(int num_variables);

  /// Adds a dense symmetric block of the given size >= 1; returns its index.
  int add_dense_block(int size);
  /// Adds a diagonal (LP) block of the given size >= 1; returns its index.
  int add_diagonal_block(int size);

  /// c_j (default 0).
  void set_objective(int variable, double value);
  /// Adds value to (row, col) and (col, row) of block `block` of F_0.
  void add_constant_entry(int block, int row, int col, double value);
  /// Adds value to (row, col) and (col, row) of block `block` of F_{variable+1}, the matrix
  /// multiplying y[variable].
  void add_variable_entry(int variable, int block, int row, int col, double value);

  int num_variables() const { return num_variables_; }
  int num_blocks() const { return static_cast<int>(blocks_.size()); }
  BlockKind block_kind(int block) const { return blocks_.at(block).kind; }
  int block_size(int block) const { return blocks_.at(block).size; }
  const Eigen::VectorXd& objective() const { return c_; }

  /// One stored upper-triangle entry (row <= col) of F_matrix (matrix 0 is F_0).
  struct Entry {
    int matrix;
    int block;
    int row;
    int col;
    double value;
  };
  const std::vector<Entry>& entries() const { return entries_; }

  /// F(y) = sum y_j F_j - F_0 as a dense matrix (blocks along the diagonal). For tests and
  /// diagnostics; allocates.
  Eigen::MatrixXd lmi_matrix(const Eigen::VectorXd& y) const;

 private:
  struct Block {
    BlockKind kind;
    int size;
  };
  void add_entry(int matrix, int block, int row, int col, double value);

  int num_variables_;
  Eigen::VectorXd c_;
  std::vector<Block> blocks_;
  std::vector<Entry> entries_;
};

/// Options of solve_lmi().
struct SdpOptions {
  SdpBackend backend = SdpBackend::kCsdp;
  /// Relative primal/dual feasibility and relative gap tolerance (CSDP axtol, atytol, objtol).
  /// Dimensionless, in (0, 1e-2].
  double tolerance = 1e-8;
  /// Iteration limit of the interior-point method, >= 1.
  int max_iterations = 100;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Result of solve_lmi().
struct SdpResult {
  SdpStatus status = SdpStatus::kBackendError;
  /// The LMI variable y (size k). For kUnbounded it is CSDP's certificate direction.
  Eigen::VectorXd y;
  /// c^T y: the objective of the LMI problem (CSDP's "dual objective").
  double primal_objective = 0.0;
  /// tr(F_0 X): the objective of its dual (CSDP's "primal objective").
  double dual_objective = 0.0;
  /// primal_objective - dual_objective, >= 0 up to the tolerance at an optimum.
  double gap = 0.0;
  /// Interior-point iterations, or -1 when the backend does not report them (CSDP's sdp()
  /// returns only a status code).
  int iterations = -1;
  std::string backend;  ///< to_string(SdpOptions::backend)
  std::string message;  ///< what the backend said, in words
};

/// Solves the LMI problem. Silent (no output, no parameter file is read) and leak-free.
/// Throws InvalidArgument when the options are invalid, the problem has no block, or some F_j
/// (j >= 1) is entirely zero (CSDP rejects empty constraints).
/// Safe to call from several threads at once: CSDP is not reentrant, so its solver loops run one
/// at a time under a process-wide lock (threads wait; answers are as if solved alone).
SdpResult solve_lmi(const LmiProblem& problem, const SdpOptions& options = {});

}  // namespace vantage::sdp
