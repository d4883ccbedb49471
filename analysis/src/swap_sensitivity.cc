#include "vantage/analysis/swap_sensitivity.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage {
namespace {

// The swapped D's top eigenvector is then the unit quaternion (0, 0, 0, 1) by a relative gap of
// at least this, well above top_eigenpair's fallback gap (1e-3 of the traceless part's norm, at
// most 3 ||D + Delta D||_F) and kSwapAmbiguousGap: top_eigenpair returns it exactly (its
// adjugate column has exact zeros), so the error is exactly 0.
constexpr double kUnmovedRelativeGap = 1e-2;
// Relative rounding allowance on the bound of ||Delta D||_F over all pairs.
constexpr double kBoundRounding = 1e-12;

// Proves, without an eigensolver, that a swap leaves R = I the unique optimum. Noise-free (and
// with equal weights for the pair), the last row and column of D and of Delta D are exactly
// (0, 0, 0, d44): D + Delta D is block diagonal, (0, 0, 0, 1) is an eigenvector with eigenvalue
// d44 + delta44, and every other eigenvalue is at most lambda_max(D_3x3) + ||Delta D_3x3||_F
// (Weyl). Pairs it cannot decide go to the eigensolver.
class UnmovedScreen {
 public:
  explicit UnmovedScreen(const Eigen::Matrix4d& D)
      : D_(D), d_norm_(D.norm()), block_(last_column_is_zero(D)) {
    if (block_) {
      top3_ = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(D.topLeftCorner<3, 3>(),
                                                             Eigen::EigenvaluesOnly)
                  .eigenvalues()(2);
    }
  }

  // With unit weights, Delta D = K(a, -a) for a = z_j - z_i: its last column is exactly zero
  // (a x -a) and ||Delta D||_F <= (2 + 2 sqrt 3) |a|^2 <= (2 + 2 sqrt 3) (2 max_k |z_k|)^2. When
  // that bound passes proves_unmoved()'s test, every pair does.
  bool proves_every_pair_unmoved(const Eigen::Matrix3Xd& z, const Eigen::VectorXd& weights) const {
    if (!block_ || !(weights.size() == 0 || (weights.array() == 1.0).all())) return false;
    const double longest = z.colwise().norm().maxCoeff();
    const double delta_bound =
        (2.0 + 2.0 * std::sqrt(3.0)) * 4.0 * longest * longest * (1.0 + kBoundRounding);
    const double gap = D_(3, 3) - top3_ - delta_bound;
    return gap > kUnmovedRelativeGap * (d_norm_ + delta_bound);
  }

  bool proves_unmoved(const Eigen::Matrix4d& delta) const {
    if (!block_ || !last_column_is_zero(delta)) return false;
    const double delta_norm = delta.norm();
    const double gap = D_(3, 3) + delta(3, 3) - top3_ - delta.topLeftCorner<3, 3>().norm();
    return gap > kUnmovedRelativeGap * (d_norm_ + delta_norm);
  }

 private:
  static bool last_column_is_zero(const Eigen::Matrix4d& a) {
    return a(0, 3) == 0.0 && a(1, 3) == 0.0 && a(2, 3) == 0.0 && a(3, 0) == 0.0 && a(3, 1) == 0.0 &&
           a(3, 2) == 0.0;
  }

  Eigen::Matrix4d D_;
  double d_norm_;
  bool block_;
  double top3_ = 0.0;
};

}  // namespace

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
  const UnmovedScreen screen(D);
  if (screen.proves_every_pair_unmoved(z, weights)) {
    // Every error is exactly 0: the ranking is (i, j) order, O(count) instead of O(m^2).
    std::vector<SwapError> first;
    for (Eigen::Index i = 0; i < m && first.size() < keep; ++i) {
      for (Eigen::Index j = i + 1; j < m && first.size() < keep; ++j) {
        first.push_back({static_cast<int>(i), static_cast<int>(j), 0.0, false});
      }
    }
    return first;
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = i + 1; j < m; ++j) {
      const Eigen::Matrix4d delta =
          swap_delta_d(z.col(i), z.col(j), z.col(i), z.col(j), w(i), w(j));
      if (screen.proves_unmoved(delta)) {
        offer({static_cast<int>(i), static_cast<int>(j), 0.0, false});
        continue;
      }
      const Eigen::Matrix4d swapped = D + delta;
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
