#include "vantage/analysis/swap_sensitivity.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage {

std::vector<SwapError> swap_sensitivity(const Eigen::Matrix3Xd& z, const Eigen::VectorXd& weights,
                                        int count) {
  const Eigen::Index m = z.cols();
  internal::check_min_count("z", m, 2, "columns");
  if (count < 1) internal::fail("count", "must be >= 1, got " + std::to_string(count));
  internal::check_finite_columns("z", z);
  internal::check_weights("weights", weights, m, "z");
  auto w = [&weights](Eigen::Index k) { return weights.size() == 0 ? 1.0 : weights(k); };
  const Eigen::Matrix4d D = orientation_matrix_d(z, z, weights);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // The worst `count` pairs in a bounded heap: O(count) memory instead of all m (m - 1) / 2
  // pairs. ranks_before is a strict total order, so the selection is the same as sorting all.
  const auto ranks_before = [](const SwapError& a, const SwapError& b) {
    if (a.error_deg != b.error_deg) return a.error_deg > b.error_deg;
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  };
  const size_t pairs = static_cast<size_t>(m) * static_cast<size_t>(m - 1) / 2;
  const size_t keep = std::min(pairs, static_cast<size_t>(count));
  std::vector<SwapError> worst;  // a heap whose front ranks last
  worst.reserve(keep);
  auto offer = [&](const SwapError& e) {
    if (worst.size() < keep) {
      worst.push_back(e);
      std::push_heap(worst.begin(), worst.end(), ranks_before);
    } else if (ranks_before(e, worst.front())) {
      std::pop_heap(worst.begin(), worst.end(), ranks_before);
      worst.back() = e;
      std::push_heap(worst.begin(), worst.end(), ranks_before);
    }
  };
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = i + 1; j < m; ++j) {
      const Eigen::Matrix4d swapped =
          D + swap_delta_d(z.col(i), z.col(j), z.col(i), z.col(j), w(i), w(j));
      const TopEigenpair top = top_eigenpair(swapped);
      if (!(top.gap > kSwapAmbiguousGap * swapped.norm())) {
        // A repeated top eigenvalue: the optima form a subspace of dimension >= 2 of unit
        // quaternions, which always holds one with eps4 = 0, a half turn.
        offer({static_cast<int>(i), static_cast<int>(j), 180.0, true});
        continue;
      }
      const double angle = rotation_angle_between(rotation_from_quaternion(top.vector), identity);
      offer({static_cast<int>(i), static_cast<int>(j), angle * kDegreesPerRadian, false});
    }
  }
  std::sort_heap(worst.begin(), worst.end(), ranks_before);
  return worst;
}

}  // namespace vantage
