#pragma once

/// Identification margins of one tool (docs/math.md §24): how well a tracker that sees unlabelled
/// markers can tell the tool's markers apart by their distances (ART's rule, Eq. 24.1), with any
/// one marker lost, and how far the tool is from its own mirror image (NDI's rule, Eq. 24.2).
///
/// Points are the columns of a 3 x N matrix (the tool frame); every number is in their units.
/// Pairs are (i, j) with i < j; "the order of pairs" is (0,1), (0,2), ..., (0,N-1), (1,2), ...

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "vantage/tracker/mirror_fit.h"

namespace vantage::tracker {

/// The least difference between two inter-marker distances.
struct DistanceDifference {
  /// min |d_ij - d_kl| over distinct unordered pairs {i, j} != {k, l} (Eq. 24.1); +infinity
  /// with fewer than two pairs.
  double value = 0.0;
  std::pair<int, int> pair_a{-1, -1};  ///< the earlier of the two pairs in the order of pairs
  std::pair<int, int> pair_b{-1, -1};  ///< the later one; both (-1, -1) when value is infinite
};

/// Eq. (24.1) for the columns of `points` (any count, finite): one sort of the N(N-1)/2
/// distances; among equal least differences, the first of the length-sorted neighbours (equal
/// lengths keep the order of pairs). The one check of `place` and `design`
/// --min-distance-difference D: a layout is admissible iff value >= D.
DistanceDifference min_distance_difference(const Eigen::Matrix3Xd& points);

/// The closest two markers: min d_ij and its pair (the first in the order of pairs).
struct MarkerSeparation {
  double value = 0.0;  ///< +infinity with fewer than two points
  std::pair<int, int> pair{-1, -1};
};

/// min d_ij over the pairs of columns of `points`.
MarkerSeparation min_marker_separation(const Eigen::Matrix3Xd& points);

/// Eq. (24.1) with one marker lost.
struct DropoutDifference {
  int lost = -1;  ///< the marker removed (a column of the full layout)
  /// Over the pairs without `lost`; the pairs name columns of the full layout.
  DistanceDifference difference;
};

/// Options of identification_margins().
struct IdentificationOptions {
  MirrorFitOptions mirror;  ///< the branch and bound of mirror_rms

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Every identification margin of a tool (docs/math.md §24).
struct IdentificationMargins {
  DistanceDifference distance_difference;  ///< Eq. (24.1)
  MarkerSeparation separation;             ///< min d_ij
  MirrorFit mirror;                        ///< Eq. (24.2)
  /// Eq. (24.1) without marker m, for m = 0, ..., N-1 (each >= distance_difference.value).
  std::vector<DropoutDifference> under_dropout;
  /// Index into under_dropout of the smallest margin (the first such m).
  int worst_under_dropout = -1;
};

/// The margins of the columns of `points` (3 x N, N >= 3, finite). Throws InvalidArgument
/// ("points") on fewer than 3 points or a non-finite coordinate, and on bad options. The cost is
/// O(N^3) for the dropout plus the mirror search (bounded by options.mirror).
IdentificationMargins identification_margins(const Eigen::Matrix3Xd& points,
                                             const IdentificationOptions& options = {});

}  // namespace vantage::tracker
