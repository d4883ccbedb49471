#pragma once

/// Non-negative weights for the decoupled pose solution of Prop. 3 (McInroy et al., Sec. II).
///
/// Prop. 3 decouples rotation from translation when the data points satisfy Eq. (11),
///
///   sum_i w_i z_i = 0,   i.e.  Z w = 0,  w_i >= 0,
///
/// ("w must be chosen in the null space of Z ... with all non-negative elements", text after
/// Prop. 3). vantage picks, among all such w normalised to sum_i w_i = n, the one whose smallest
/// weight is largest (as far from dropping a marker as possible). That is the linear program
///
///   maximise s   over (w, s)   subject to   Z w = 0,  1^T w = n,  w_i >= s  (i = 1..n),
///
/// solved through its dual, which has three variables (c the centroid of the z_i):
///
///   minimise c.u  over u in R^3  subject to  (z_i - c).u <= 1,   s* = 1 + min c.u,
///
/// by an active-set (simplex) method started at the strictly feasible u = 0: O(n) memory and
/// O(n) per step, so 100 000 entries take well under a second. The returned w is the basic
/// optimum the dual's multipliers give: w_i = s* for all but at most three entries. s is free,
/// so the LP is feasible exactly when 0 is in the affine hull of the z_i, and bounded (s <= 1);
/// its optimum s* classifies the layout: s* > 0 strictly positive weights exist, s* = 0 weights
/// exist only with some w_i = 0 (the origin is on the boundary of conv{z_i}), s* < 0 no weights
/// exist (the origin is outside conv{z_i}).
///
/// Which z_i: in point mode the marker positions themselves (Eq. 11 is a condition on positions
/// in the object frame). In direction mode the data vectors themselves, read as the z_i of
/// Prop. 3 (each one a point relative to the object origin).
///
/// When no strictly positive weights exist, the paper's fixes are computed and verified (the LP
/// is re-solved on the fixed layout): add the symmetric partner -z_i of one z_i ("choose the z's
/// in symmetrical pairs", remark after Prop. 3), choosing the i whose fix gives the largest
/// smallest weight; and, in point mode only, move the object origin to the centroid of the
/// markers (then equal weights satisfy Eq. 11).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/sdp/lmi.h"

namespace vantage::design {

/// Options of nullspace_weights().
struct WeightsOptions {
  /// |s*| at or below this counts as s* = 0 (boundary), in weight units (the weights sum to n).
  /// The active-set solver is exact up to rounding, CSDP to relative accuracy ~1e-8. In (0, 1e-2].
  double zero_tolerance = 1e-6;
  /// Compute and verify the paper's fixes when weights are not strictly positive. Up to 64
  /// entries every symmetric partner is tried, beyond that the 32 entries farthest beyond the
  /// plane separating the z_i from the origin (largest dual slack).
  bool suggest = true;
  /// How the LP is solved.
  enum class Solver {
    kDualActiveSet,  ///< the three-variable dual (default; any n)
    kCsdp,  ///< the primal on the SDP layer: O(n^2) memory, n <= 2000; an independent check
  };
  Solver solver = Solver::kDualActiveSet;
  sdp::SdpOptions sdp;  ///< backend options of the LP (Solver::kCsdp)

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// One of the paper's fixes, already verified by re-solving the LP on the fixed layout.
struct WeightsSuggestion {
  enum class Kind {
    kSymmetricPartner,  ///< add -z_index (with its own weight) to the layout
    kShiftOrigin,       ///< subtract `shift` from every point (move the origin to `shift`)
    /// add one entry at -sum_i z_i: then equal weights satisfy Eq. (11), so strictly positive
    /// weights always exist (the paper's symmetric pairs need one partner per entry)
    kBalancingEntry,
  };
  Kind kind = Kind::kSymmetricPartner;
  int index = -1;                                   ///< kSymmetricPartner: the mirrored entry
  Eigen::Vector3d added = Eigen::Vector3d::Zero();  ///< the new entry (partner or balancing)
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  ///< kShiftOrigin: the new origin
  /// Smallest weight of the max-min weights of the fixed layout (normalised to sum = its
  /// entry count); > zero_tolerance means the fix gives strictly positive weights.
  double min_weight = 0.0;
  Eigen::VectorXd weights;  ///< those weights (n + 1 entries for a partner, n for a shift)
  std::string text;         ///< one sentence for the user
};

/// "symmetric_partner", "shift_origin" or "balancing_entry".
const char* to_string(WeightsSuggestion::Kind kind);

/// Result of nullspace_weights().
struct Weights {
  enum class Status {
    kPositive,     ///< s* > zero_tolerance: all weights strictly positive
    kBoundary,     ///< |s*| <= zero_tolerance: weights exist, but some must be 0 (the origin is
                   ///< on the boundary of conv{z_i}); `weights` has the forced zeros set to 0
                   ///< and maximises the smallest of the others
    kInfeasible,   ///< s* < -zero_tolerance, or Z w = 0, 1^T w = n has no solution at all (all
                   ///< z_i on a plane that misses the origin): no non-negative weights exist
    kSolverFailed  ///< the LP backend returned no solution (see `sdp_status`)
  };
  Status status = Status::kSolverFailed;
  /// kPositive or kBoundary: weights exist.
  bool feasible = false;
  /// n weights, >= 0, sum n, with Z w = 0 (kPositive, kBoundary); empty otherwise.
  Eigen::VectorXd weights;
  /// ||sum_i w_i z_i|| of `weights` (0 when empty).
  double residual = 0.0;
  /// min_i w_i of `weights` (0 when empty).
  double min_weight = 0.0;
  /// s* of the LP: the largest smallest weight (negative when infeasible: how far from it).
  double lp_optimum = 0.0;
  /// Indices forced to weight 0 (kBoundary).
  std::vector<int> zero_forced;
  /// The paper's fixes, best first (when options.suggest and status is not kPositive).
  std::vector<WeightsSuggestion> suggestions;
  sdp::SdpStatus sdp_status = sdp::SdpStatus::kBackendError;
  int lp_solves = 0;  ///< LPs solved, including those verifying suggestions
  std::string message;
};

/// "positive", "boundary", "infeasible" or "solver_failed".
const char* to_string(Weights::Status status);

/// Max-min non-negative weights with sum_i w_i z_i = 0 (Eq. 11) for the columns of z (3 x n,
/// n >= 1, finite). allow_shift enables the kShiftOrigin suggestion (point mode).
/// Throws InvalidArgument on non-finite z, invalid options, or n > 2000 with Solver::kCsdp.
Weights nullspace_weights(const Eigen::Matrix3Xd& z, const WeightsOptions& options = {},
                          bool allow_shift = false);

/// The same for a layout: its points (point mode, origin shift suggested) or its vectors
/// (direction mode). Validates the layout.
Weights layout_weights(const Layout& layout, const WeightsOptions& options = {});

}  // namespace vantage::design
