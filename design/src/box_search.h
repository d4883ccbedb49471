#pragma once

// Private to vantage::design: the point-mode search for the best new marker in the search box,
// a branch and bound over the box (docs/math.md §18).
//
// Adding the marker p adds the free vectors u_i(p) = (p - z_i) / |p - z_i| to the data vectors
// n_j; the new t is T(p) = max_a F(a, p), F(a, p) = min(g(a), min_i |a.u_i(p)|) with
// g(a) = min_j |a.n_j|. For any viewpoint a and any box C of positions,
//   T(p) >= F(a, p) >= min(g(a), min_i inf_{p in C} |a.u_i(p)|)   for every p in C,
// and inf_{p in C} |a.u_i(p)| is exact from the box's 8 vertices: 0 when the plane through z_i
// perpendicular to a cuts C; otherwise |a.u| is the cosine of the angle between a and the
// direction p - z_i, which is quasi-convex over C, so its minimum sits at a vertex. Each cell
// keeps the viewpoints that bound it best (the worst viewpoints of the global solves at its
// centre and at its ancestors'), so the bound tends to T(centre) as cells shrink. Cells are
// taken lowest bound first; a cell whose bound is within the tolerance of the best t found
// (U) holds no better position and is dropped; others are probed at their centre (one global
// solve, a new U is polished by the compass search) and halved along their longest side.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "designer.h"

namespace vantage::design::internal {

/// Cells narrower than this fraction of the box's largest side are not halved further: they
/// are counted as unresolved (a ridge of t the bound cannot separate from the best t).
inline constexpr double kMinCellFraction = 1e-3;
/// Cells that touch a marker (closer to it than their own width) stop at this fraction: next
/// to a marker z_i the directions p - z_i take every value, so the bound there stays 0 at any
/// width, and a new marker that close to an old one is of no use.
inline constexpr double kMinMarkerCellFraction = 1e-2;
/// Viewpoints a cell keeps for its bound (those that bound it best).
inline constexpr int kCellViewpoints = 6;

/// What the search found and what it proved.
struct BoxSearchResult {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< the best position found
  Score score;                                  ///< its score
  /// No position of the box outside the unresolved cells has t below this (U - tolerance once
  /// closed).
  double t_lower = 0.0;
  long unresolved = 0;  ///< cells left at the minimum width with a bound below U - tolerance
  bool closed = false;  ///< every other cell was dropped before the solve budget ran out
  long solves = 0;      ///< global solves spent (probes and polish)
};

/// The functions of the Designer the search uses.
struct BoxSearchCalls {
  /// Score of position x and the viewpoints at which its t is attained (the surviving worst
  /// viewpoints when x kills not all of them; none for a degenerate x).
  std::function<Score(const Eigen::Vector3d& x, std::vector<Eigen::Vector3d>* viewpoints)> probe;
  /// Compass search from x (score *s) with a first step of `step` (fraction of the box side).
  std::function<Eigen::Vector3d(const Eigen::Vector3d& x, Score* s, double step)> polish;
  /// Global solves spent so far.
  std::function<long()> solves;
};

/// Branch and bound over [lo, hi] for the markers (3 x n) and the unit data vectors (3 x m),
/// starting from the best position known (x, score) and the current worst viewpoints. Stops
/// when the cells are exhausted or after `max_solves` more global solves. `tolerance` is in t.
BoxSearchResult search_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                           const Eigen::Matrix3Xd& markers, const Eigen::Matrix3Xd& unit_vectors,
                           const std::vector<Eigen::Vector3d>& worst_viewpoints,
                           const Eigen::Vector3d& x, const Score& score, double tolerance,
                           double tie_tolerance, long max_solves, const BoxSearchCalls& calls);

}  // namespace vantage::design::internal
