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
  /// An attained value exceeded options.stop_above at stop_point (a hint or a cell optimum);
  /// the search stopped there and optima, upper and lower are incomplete.
  bool stopped = false;
  Eigen::Vector3d stop_point = Eigen::Vector3d::UnitZ();
  /// search_frontier() only: no attained value reached the frontier's level, so the patches
  /// pruned when the frontier was collected are not proven below t*: search the whole sphere.
  bool below_level = false;
};

/// The leaves of the branch and bound over unit columns `n` at a fixed level L (nothing is
/// solved): every patch is pruned whose bound is below L - tie_tolerance, so max_a min_i |a.n_i|
/// < L - tie_tolerance outside the frontier, for n and for n plus any further columns. Each leaf
/// keeps the circles that can still bound it at level L.
struct Frontier {
  struct Patch {
    int face;
    double u, v, h;  // centre and half-width on the cube face
    int depth;
    int first, count;  // its circles: [first, first + count) of x, y, z
  };
  double level = 0.0;
  std::vector<Patch> patches;
  std::vector<double> x, y, z;
  long patches_visited = 0;  ///< patches the collection visited
};

Frontier collect_frontier(const Eigen::Matrix3Xd& n, double level,
                          const WorstViewpointOptions& options);

/// The branch and bound of search_worst_viewpoint() over the frontier's patches only, for unit
/// columns n whose first base_count columns are the ones the frontier was collected on. Exact
/// (the same optima, upper and lower) when lower >= frontier.level; otherwise below_level is set.
SearchOutcome search_frontier(const Frontier& frontier, const Eigen::Matrix3Xd& n, int base_count,
                              const WorstViewpointOptions& options);

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

/// The public result of a search over the unit columns n (all of them, repeats included): the
/// reported viewpoint, ties, t evaluated on every column, the certificate and, when asked, the
/// SDP confirmation.
WorstViewpoint worst_viewpoint_result(const Eigen::Matrix3Xd& n, const SearchOutcome& search,
                                      const WorstViewpointOptions& options);

}  // namespace vantage::sdp::internal
