#pragma once

// Bound 2' of docs/math.md §20: on a patch where too few markers are certainly visible, the best
// that any possible choice of mixed markers allows. Mixed markers come in units, seen whole or
// not at all (markers of one normal and one cone at that cone's edge); where two units' hidden
// sides do not meet, every direction sees one of them.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "vantage/visibility/internal/cone_classes.h"

namespace vantage::visibility::internal {

/// A marker on a patch: certainly visible, certainly hidden, mixed, or mixed only at the edge
/// of its cone (clear of the body on the whole patch).
enum class Seen : std::uint8_t { kVisible, kHidden, kMixed, kConeEdge };

inline bool is_mixed(Seen s) { return s == Seen::kMixed || s == Seen::kConeEdge; }

/// sin(min(pi/2, asin s + r)) for s = |c.u| at a patch's centre and its radius r (cos r, sin r):
/// the largest |a.u| on the patch (§14).
double sin_plus(double s, double cos_r, double sin_r);

/// Whether markers (increasing) lie on one line by §20's test of trackability (fewer than three:
/// true): then no direction that sees exactly them is trackable.
using CollinearTest = std::function<bool(const std::vector<int>& markers)>;

/// What bound 2' reads on one patch.
struct PatchMarkers {
  const std::vector<Seen>& seen;                    ///< per marker
  const std::vector<std::pair<int, int>>& pair_of;  ///< markers (i, j) of each pair index
  const Eigen::Matrix3Xd& u;                        ///< unit free vector of each pair index
  const std::vector<int>& pairs;  ///< pairs of markers not hidden (others count as 1)
  Eigen::Vector3d centre;
  double cos_r = 1.0;
  double sin_r = 0.0;
  /// When given, a choice of units whose markers (with the certain ones) are collinear is not
  /// trackable and does not count.
  const CollinearTest* collinear = nullptr;
};

/// Bound 2' on t over the trackable directions of the patch (1 when it does not apply).
double needed_mixed_bound(const ConeClasses& classes, int min_visible, const PatchMarkers& patch);

}  // namespace vantage::visibility::internal
