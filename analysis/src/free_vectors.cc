#include "vantage/analysis/free_vectors.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace vantage {

const char* to_string(PairWeighting weighting) {
  switch (weighting) {
    case PairWeighting::kGeometricMean:
      return "geometric_mean";
    case PairWeighting::kArithmeticMean:
      return "arithmetic_mean";
  }
  return "unknown";
}

std::optional<PairWeighting> parse_pair_weighting(std::string_view name) {
  if (name == "geometric") return PairWeighting::kGeometricMean;
  if (name == "arithmetic") return PairWeighting::kArithmeticMean;
  return std::nullopt;
}

const char* to_string(FreeVectorSet set) {
  switch (set) {
    case FreeVectorSet::kAuto:
      return "auto";
    case FreeVectorSet::kAllPairs:
      return "all_pairs";
    case FreeVectorSet::kMaxSpanningTree:
      return "max_spanning_tree";
  }
  return "unknown";
}

double pair_weight(double w_i, double w_j, PairWeighting weighting) {
  // sqrt(w_i) sqrt(w_j), not sqrt(w_i w_j): the product of two large weights may overflow.
  return weighting == PairWeighting::kGeometricMean ? std::sqrt(w_i) * std::sqrt(w_j)
                                                    : 0.5 * (w_i + w_j);
}

namespace {

bool auto_uses_all_pairs(Eigen::Index n) { return n * (n - 1) / 2 <= kAutoAllPairsLimit; }

/// All pairs (i, j), i < j, in lexicographic order.
Eigen::Matrix2Xi all_pairs(Eigen::Index n) {
  Eigen::Matrix2Xi pairs(2, n * (n - 1) / 2);
  int k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) pairs.col(k++) << i, j;
  return pairs;
}

/// The column of (i, j), i < j, in all_pairs(n).
Eigen::Index pair_index(Eigen::Index n, Eigen::Index i, Eigen::Index j) {
  return i * n - i * (i + 1) / 2 + (j - i - 1);
}

/// Prim's algorithm for the maximum spanning tree of the distances |z_j - z_i|; the edges in
/// order of addition, each with its length.
Eigen::Matrix2Xi max_spanning_tree(const Eigen::Matrix3Xd& points, std::vector<double>* lengths) {
  const int n = static_cast<int>(points.cols());
  Eigen::Matrix2Xi pairs(2, n - 1);
  std::vector<bool> in_tree(n, false);
  std::vector<double> best(n, -1.0);
  std::vector<int> parent(n, 0);
  in_tree[0] = true;
  for (int j = 1; j < n; ++j) best[j] = (points.col(j) - points.col(0)).norm();
  for (int k = 0; k < n - 1; ++k) {
    int next = -1;
    for (int j = 0; j < n; ++j)
      if (!in_tree[j] && (next < 0 || best[j] > best[next])) next = j;
    in_tree[next] = true;
    pairs.col(k) << std::min(parent[next], next), std::max(parent[next], next);
    lengths->push_back(best[next]);
    for (int j = 0; j < n; ++j) {
      const double distance = (points.col(j) - points.col(next)).norm();
      if (!in_tree[j] && distance > best[j]) {
        best[j] = distance;
        parent[j] = next;
      }
    }
  }
  return pairs;
}

}  // namespace

Eigen::Index free_vector_count(Eigen::Index n, FreeVectorSet set) {
  switch (set) {
    case FreeVectorSet::kAllPairs:
      return n * (n - 1) / 2;
    case FreeVectorSet::kMaxSpanningTree:
      return n - 1;
    case FreeVectorSet::kAuto:
      break;
  }
  return auto_uses_all_pairs(n) ? n * (n - 1) / 2 : kAutoBudget;
}

Eigen::Matrix2Xi free_vector_pairs(const Eigen::Matrix3Xd& points, FreeVectorSet set) {
  const Eigen::Index n = points.cols();
  if (set == FreeVectorSet::kAllPairs || (set == FreeVectorSet::kAuto && auto_uses_all_pairs(n))) {
    return all_pairs(n);
  }
  std::vector<double> lengths;
  const Eigen::Matrix2Xi tree = max_spanning_tree(points, &lengths);
  if (set == FreeVectorSet::kMaxSpanningTree) return tree;
  if (tree.cols() >= kAutoBudget) {
    // The longest kAutoBudget edges (stable: ties keep the order of addition).
    std::vector<int> order(tree.cols());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return lengths[a] > lengths[b]; });
    Eigen::Matrix2Xi kept(2, kAutoBudget);
    for (int k = 0; k < kAutoBudget; ++k) kept.col(k) = tree.col(order[k]);
    return kept;
  }
  // The tree, then the longest pairs it does not hold (ties by (i, j)).
  const Eigen::Matrix2Xi every = all_pairs(n);
  std::vector<bool> in_tree(static_cast<std::size_t>(every.cols()), false);
  for (Eigen::Index k = 0; k < tree.cols(); ++k) {
    in_tree[static_cast<std::size_t>(pair_index(n, tree(0, k), tree(1, k)))] = true;
  }
  std::vector<int> further;
  for (int k = 0; k < every.cols(); ++k) {
    if (!in_tree[static_cast<std::size_t>(k)]) further.push_back(k);
  }
  auto length = [&](int k) { return (points.col(every(1, k)) - points.col(every(0, k))).norm(); };
  std::stable_sort(further.begin(), further.end(),
                   [&](int a, int b) { return length(a) > length(b); });
  Eigen::Matrix2Xi kept(2, kAutoBudget);
  kept.leftCols(tree.cols()) = tree;
  for (Eigen::Index k = tree.cols(); k < kAutoBudget; ++k) {
    kept.col(k) = every.col(further[static_cast<std::size_t>(k - tree.cols())]);
  }
  return kept;
}

template <int MeasuredRows>
Eigen::Matrix2Xi free_vector_pairs(
    const Eigen::Matrix3Xd& points,
    const Eigen::Matrix<double, MeasuredRows, Eigen::Dynamic>& measured, FreeVectorSet set) {
  Eigen::Matrix2Xi pairs = free_vector_pairs(points, set);
  const Eigen::Index n = points.cols();
  if (set != FreeVectorSet::kAuto || auto_uses_all_pairs(n)) return pairs;
  // The pair of largest |q_j - q_i| / |z_j - z_i| over all pairs (ratios compared as
  // cross-multiplied squares: no division by a short object vector).
  int best_i = 0;
  int best_j = 1;
  double best_q = -1.0;
  double best_z = 1.0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double q = (measured.col(j) - measured.col(i)).squaredNorm();
      const double z = (points.col(j) - points.col(i)).squaredNorm();
      if (q * best_z > best_q * z) {
        best_q = q;
        best_z = z;
        best_i = i;
        best_j = j;
      }
    }
  }
  if (!(best_q > 0.0)) return pairs;  // no measured differences: no scale to protect
  for (Eigen::Index k = 0; k < pairs.cols(); ++k) {
    if (pairs(0, k) == best_i && pairs(1, k) == best_j) return pairs;
  }
  pairs.col(pairs.cols() - 1) << best_i, best_j;
  return pairs;
}

template Eigen::Matrix2Xi free_vector_pairs<2>(const Eigen::Matrix3Xd&, const Eigen::Matrix2Xd&,
                                               FreeVectorSet);
template Eigen::Matrix2Xi free_vector_pairs<3>(const Eigen::Matrix3Xd&, const Eigen::Matrix3Xd&,
                                               FreeVectorSet);

template <int MeasuredRows>
FreeVectorsOf<MeasuredRows> build_free_vectors(
    const Eigen::Matrix3Xd& points,
    const Eigen::Matrix<double, MeasuredRows, Eigen::Dynamic>& measured,
    const Eigen::VectorXd& weights, const Eigen::Matrix2Xi& pairs, PairWeighting weighting) {
  const Eigen::Index m = pairs.cols();
  FreeVectorsOf<MeasuredRows> out;
  out.pairs = pairs;
  out.z_object.resize(3, m);
  out.d.resize(MeasuredRows, m);
  out.weights.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const int i = pairs(0, k);
    const int j = pairs(1, k);
    out.z_object.col(k) = points.col(j) - points.col(i);
    out.d.col(k) = measured.col(j) - measured.col(i);
    const double wi = weights.size() == 0 ? 1.0 : weights(i);
    const double wj = weights.size() == 0 ? 1.0 : weights(j);
    out.weights(k) = pair_weight(wi, wj, weighting);
  }
  return out;
}

template FreeVectorsOf<2> build_free_vectors<2>(const Eigen::Matrix3Xd&, const Eigen::Matrix2Xd&,
                                                const Eigen::VectorXd&, const Eigen::Matrix2Xi&,
                                                PairWeighting);
template FreeVectorsOf<3> build_free_vectors<3>(const Eigen::Matrix3Xd&, const Eigen::Matrix3Xd&,
                                                const Eigen::VectorXd&, const Eigen::Matrix2Xi&,
                                                PairWeighting);

}  // namespace vantage
