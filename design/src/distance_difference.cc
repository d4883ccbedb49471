// The least difference between two inter-marker distances (ART's identification rule).

#include <algorithm>
#include <limits>
#include <vector>

#include "vantage/design/placement.h"

namespace vantage::design {

DistanceDifference min_distance_difference(const Eigen::Matrix3Xd& points) {
  struct Pair {
    double d;
    int i;
    int j;
  };
  std::vector<Pair> pairs;
  const int n = static_cast<int>(points.cols());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) pairs.push_back({(points.col(j) - points.col(i)).norm(), i, j});
  }
  DistanceDifference out;
  out.value = std::numeric_limits<double>::infinity();
  if (pairs.size() < 2) return out;
  // Sorted by length, the least difference is between neighbours; stable, so that equal
  // lengths keep the pair order.
  std::vector<std::size_t> order(pairs.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return pairs[a].d < pairs[b].d; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Pair& a = pairs[std::min(order[k - 1], order[k])];
    const Pair& b = pairs[std::max(order[k - 1], order[k])];
    const double diff = std::abs(a.d - b.d);
    if (diff < out.value) out = {diff, {a.i, a.j}, {b.i, b.j}};
  }
  return out;
}

}  // namespace vantage::design
