// The least difference between two inter-marker distances (docs/math.md §24, Eq. 24.1: ART's
// identification rule), the closest two markers, and the identification margins of a tool.

#include <algorithm>
#include <limits>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/tracker/identification.h"

namespace vantage::tracker {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct DistancePair {
  double d;
  int i;
  int j;
};

// Every pair (i < j) in the order of pairs, then stably sorted by length: equal lengths keep
// the order of pairs.
std::vector<DistancePair> pairs_by_length(const Eigen::Matrix3Xd& points) {
  std::vector<DistancePair> pairs;
  const int n = static_cast<int>(points.cols());
  pairs.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(std::max(n - 1, 0)) / 2);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) pairs.push_back({(points.col(j) - points.col(i)).norm(), i, j});
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const DistancePair& a, const DistancePair& b) { return a.d < b.d; });
  return pairs;
}

bool before_in_order(const DistancePair& a, const DistancePair& b) {
  return a.i < b.i || (a.i == b.i && a.j < b.j);
}

// Eq. (24.1) over the sorted pairs that do not touch marker `lost` (-1: none): the least
// difference is between neighbours of the sorted list without those pairs.
DistanceDifference least_difference(const std::vector<DistancePair>& sorted, int lost) {
  DistanceDifference out;
  out.value = kInfinity;
  const DistancePair* previous = nullptr;
  for (const DistancePair& p : sorted) {
    if (p.i == lost || p.j == lost) continue;
    if (previous) {
      const double diff = p.d - previous->d;
      if (diff < out.value) {
        const bool ordered = before_in_order(*previous, p);
        const DistancePair& a = ordered ? *previous : p;
        const DistancePair& b = ordered ? p : *previous;
        out = {diff, {a.i, a.j}, {b.i, b.j}};
      }
    }
    previous = &p;
  }
  return out;
}

}  // namespace

DistanceDifference min_distance_difference(const Eigen::Matrix3Xd& points) {
  return least_difference(pairs_by_length(points), -1);
}

MarkerSeparation min_marker_separation(const Eigen::Matrix3Xd& points) {
  MarkerSeparation out;
  out.value = kInfinity;
  const int n = static_cast<int>(points.cols());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double d = (points.col(j) - points.col(i)).norm();
      if (d < out.value) out = {d, {i, j}};
    }
  }
  return out;
}

bool IdentificationOptions::is_valid(std::string* why) const {
  std::string inner;
  // inner is "<field>: <problem>": the field becomes "mirror.<field>".
  if (!mirror.is_valid(&inner)) {
    if (why != nullptr) *why = "mirror." + inner;
    return false;
  }
  return true;
}

IdentificationMargins identification_margins(const Eigen::Matrix3Xd& points,
                                             const IdentificationOptions& options) {
  internal::check_options("options", options);
  internal::check_min_count("points", points.cols(), 3, "points");
  internal::check_finite_columns("points", points);
  IdentificationMargins out;
  const std::vector<DistancePair> sorted = pairs_by_length(points);
  out.distance_difference = least_difference(sorted, -1);
  out.separation = min_marker_separation(points);
  out.mirror = mirror_fit(points, options.mirror);
  const int n = static_cast<int>(points.cols());
  for (int m = 0; m < n; ++m) {
    out.under_dropout.push_back({m, least_difference(sorted, m)});
    const double value = out.under_dropout.back().difference.value;
    if (out.worst_under_dropout < 0 ||
        value <
            out.under_dropout[static_cast<std::size_t>(out.worst_under_dropout)].difference.value) {
      out.worst_under_dropout = m;
    }
  }
  return out;
}

}  // namespace vantage::tracker
