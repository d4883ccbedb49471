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
  return auto_uses_all_pairs(n) ? n * (n - 1) / 2
                                : std::min<Eigen::Index>(n - 1, kAutoSpanningLimit);
}

Eigen::Matrix2Xi free_vector_pairs(const Eigen::Matrix3Xd& points, FreeVectorSet set) {
  const Eigen::Index n = points.cols();
  if (set == FreeVectorSet::kAllPairs || (set == FreeVectorSet::kAuto && auto_uses_all_pairs(n))) {
    Eigen::Matrix2Xi pairs(2, n * (n - 1) / 2);
    int k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) pairs.col(k++) << i, j;
    return pairs;
  }
  std::vector<double> lengths;
  const Eigen::Matrix2Xi tree = max_spanning_tree(points, &lengths);
  if (set == FreeVectorSet::kMaxSpanningTree || tree.cols() <= kAutoSpanningLimit) return tree;
  // The longest kAutoSpanningLimit edges (stable: ties keep the order of addition).
  std::vector<int> order(tree.cols());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return lengths[a] > lengths[b]; });
  Eigen::Matrix2Xi kept(2, kAutoSpanningLimit);
  for (int k = 0; k < kAutoSpanningLimit; ++k) kept.col(k) = tree.col(order[k]);
  return kept;
}

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
