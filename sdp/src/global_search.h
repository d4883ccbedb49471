#pragma once

// Private: the branch and bound behind global_worst_viewpoint() (Theorem 6 over all sign cells).

#include <Eigen/Core>
#include <vector>

#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp::internal {

/// An attained viewpoint a (unit, either sign) with its value min_i |a.n_i|.
struct AttainedViewpoint {
  Eigen::Vector3d a;
  double value;
};

/// What the branch and bound proved and found.
struct SearchOutcome {
  /// Attained viewpoints within tie_tolerance of the best attained value, one per optimum (a and
  /// -a, and points closer than 1e-9 in 1 - |a.b|, are one optimum; the best value of each kept).
  std::vector<AttainedViewpoint> optima;
  double lower = 0.0;  ///< best attained min_i |a.n_i|
  double upper = 0.0;  ///< proven upper bound on min_i |a.n_i| over the sphere (>= lower)
  long cells_solved = 0;
  long patches = 0;
  bool exhausted = false;  ///< the patch budget ran out before every patch was decided
};

/// The columns of unit vectors `n` with parallel and antiparallel repeats removed: a column is
/// dropped when an earlier kept column equals it or its negative within 1e-15 in every
/// component (repeats change min_i |a.n_i| by at most that). The first occurrence is kept, in
/// the original order, so a layout without repeats is returned unchanged.
Eigen::Matrix3Xd distinct_directions(const Eigen::Matrix3Xd& n);

/// Branch and bound over the cube-face patches of the hemisphere for unit columns `n` (at least
/// one), see global_worst_viewpoint(). Depth-first: memory is O(m + depth * (circles near a
/// patch)), time about (number of patches at the optimum's scale) x (circles near a patch).
SearchOutcome search_worst_viewpoint(const Eigen::Matrix3Xd& n,
                                     const WorstViewpointOptions& options);

}  // namespace vantage::sdp::internal
