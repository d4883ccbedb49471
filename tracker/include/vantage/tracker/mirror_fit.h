#pragma once

/// The best rigid fit of a tool to its mirror image (docs/math.md §24, Eq. 24.2; NDI's rule that
/// a mirror image of another tool is not unique).
///
/// With M = diag(-1, 1, 1) (x -> -x), the mirror tool has the markers M p_i. The fit is
///   mu^2 = min over assignments pi, R in SO(3), t of (1/N) sum_i |R p_i + t - M p_pi(i)|^2,
/// rotation and translation, no scale; equivalently the best fit of the tool onto itself by an
/// improper orthogonal transform. mu = 0 iff the tool is its own mirror up to a rigid motion and
/// a relabelling (every planar layout is).

#include <Eigen/Core>
#include <string>
#include <vector>

namespace vantage::tracker {

/// A fit this close, relative to the tool's RMS radius about its centroid, is exact: rounding
/// in the fit is about 1e-15 of the radius.
inline constexpr double kOwnMirrorTolerance = 1e-9;

/// Options of mirror_fit().
struct MirrorFitOptions {
  /// Budget of the branch and bound over assignments, in distance comparisons (a partial
  /// assignment of k markers costs about k^2 / 2 + N of them, and each rigid fit counts as
  /// 200 + 4k), >= 1. The default is a fraction of a second of CPU (docs/math.md §24).
  long max_comparisons = 50'000'000;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// The result of mirror_fit().
struct MirrorFit {
  /// The RMS residual mu of the best fit found (Eq. 24.2): exact when certified, else an upper
  /// bound.
  double rms = 0.0;
  /// A lower bound on mu: equal to rms when certified, else the least bound (Eq. 24.3) of the
  /// partial assignments the budget left unexplored.
  double rms_lower = 0.0;
  /// The search ended within its budget, so rms is the minimum over every assignment.
  bool certified = false;
  /// rms <= kOwnMirrorTolerance times the tool's RMS radius: the tool is its own mirror image
  /// (planar or achiral), up to rounding.
  bool own_mirror = false;
  /// pi: marker i of the tool is fitted onto the mirror of marker assignment[i].
  std::vector<int> assignment;
  long comparisons = 0;  ///< distance comparisons spent
  long fits = 0;         ///< complete assignments fitted (Theorem 1 each)
};

/// Eq. (24.2) for the columns of `points` (3 x N, N >= 1, finite), by the depth-first branch and
/// bound of docs/math.md §24: the identity assignment first, then partial assignments dropped by
/// the bound of Eq. (24.3); deterministic. Throws InvalidArgument on non-finite points or bad
/// options.
MirrorFit mirror_fit(const Eigen::Matrix3Xd& points, const MirrorFitOptions& options = {});

}  // namespace vantage::tracker
