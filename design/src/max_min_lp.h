#pragma once

// The max-min weight LP of nullspace_weights() (Eq. 11, Prop. 3):
//
//   maximise s  over (w, s)  subject to  Z w = 0,  1^T w = n,  w_i >= s,
//
// solved through its dual, which has three variables. With c = (1/n) sum_i z_i (the centroid)
// and g_i = z_i - c, the dual is
//
//   minimise c.u  over u in R^3  subject to  g_i.u <= 1  (i = 1..n),   s* = 1 + min c.u,
//
// and its multipliers alpha_i >= 0 (c + sum_i alpha_i g_i = 0) give the primal weights
// w_i = s* + n alpha_i, s* = 1 - sum_i alpha_i. u = 0 is strictly feasible, so an active-set
// (simplex) method started there needs no phase 1; each step costs O(n) and at most three
// constraints are active, so memory is O(n). The dual is unbounded exactly when 0 is not in the
// affine hull of the z_i (Z w = 0, 1^T w = n has no solution).

#include <Eigen/Core>

#include "vantage/sdp/lmi.h"

namespace vantage::design::internal {

/// Result of one max-min LP.
struct MaxMinSolution {
  enum class Kind {
    kSolved,            ///< w, s and slack are set
    kAffineInfeasible,  ///< Z w = 0, 1^T w = n has no solution at all
    kSolverFailed,      ///< the iteration limit or the CSDP backend gave no solution
  } kind = Kind::kSolverFailed;
  Eigen::VectorXd w;  ///< sum n, min_i w_i = s (kSolved)
  double s = 0.0;     ///< the optimum s*
  /// Dual slacks 1 - g_i.u* >= 0 (mean 1) of the active-set method; empty for CSDP. On the
  /// boundary (s* = 0) they are s* - u*.z_i: a clearly positive slack marks a z_i strictly on
  /// the far side of the supporting plane u*.z = 0, whose weight every solution sets to 0.
  Eigen::VectorXd slack;
  sdp::SdpStatus sdp_status = sdp::SdpStatus::kOptimal;
  int lp_solves = 0;
  int iterations = 0;  ///< active-set steps (0 for CSDP)
};

/// The dual active-set method above: O(n) memory, O(n) per step.
MaxMinSolution solve_max_min_dual(const Eigen::Matrix3Xd& z);

/// The same LP on the SDP layer (one diagonal block of n entries, CSDP): O(n^2) memory, kept as
/// an independent cross-check for small n. Throws InvalidArgument when n > kMaxCsdpEntries.
MaxMinSolution solve_max_min_csdp(const Eigen::Matrix3Xd& z, const sdp::SdpOptions& options);

/// Largest n solve_max_min_csdp() accepts (its null-space basis is n x n).
constexpr int kMaxCsdpEntries = 2000;

}  // namespace vantage::design::internal
