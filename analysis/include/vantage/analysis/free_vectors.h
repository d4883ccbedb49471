#pragma once

/// Free vectors of Prop. 8: from n marker positions z_i (object frame) and their measurements
/// q_i (image or 3-D), the differences
///   z_j - z_i  and  q_j - q_i,   i < j  (the one sign convention of vantage),
/// which do not depend on the translation. Each pair gets the weight of PairWeighting. Used by
/// layout analysis (data_vectors in layout.h) and by the affine pose estimators.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

namespace vantage {

/// How a free vector z_j - z_i is weighted from its markers' weights (Prop. 8's proof).
enum class PairWeighting {
  kGeometricMean,   ///< sqrt(w_i) sqrt(w_j), the default
  kArithmeticMean,  ///< (w_i + w_j) / 2
};

/// "geometric_mean" or "arithmetic_mean".
const char* to_string(PairWeighting weighting);

/// The weighting named as the front ends' option spells it (--pair-weighting, pair_weighting=):
/// "geometric" or "arithmetic"; nullopt for any other name.
std::optional<PairWeighting> parse_pair_weighting(std::string_view name);

/// The weight of the pair (i, j) under `weighting`.
double pair_weight(double w_i, double w_j, PairWeighting weighting);

/// Which free vectors to build from n points.
enum class FreeVectorSet {
  /// All pairs while n (n - 1) / 2 <= kAutoAllPairsLimit (n <= 5: at most 2^10 sign patterns
  /// in Prop. 4). Beyond, a budget of kAutoBudget vectors (2^12 patterns at most): the edges of
  /// the maximum spanning tree (the longest kAutoBudget of them beyond kAutoBudget + 1 points),
  /// then the longest other pairs until the budget is full. With an image, affine_pose() also
  /// makes sure of the pair with the largest image-to-object length ratio: the pair that sets
  /// Lemma 7's LUB scale, so the scale is the one all pairs would give (exact whenever some
  /// pair lies in the image plane, as the paper's all-pairs estimator is). Never throws for the
  /// number of points.
  kAuto,
  kAllPairs,  ///< all n (n - 1) / 2 pairs i < j, as in the paper
  /// n - 1 pairs forming the maximum spanning tree of the object distances |z_j - z_i| (Prim):
  /// connects every point with the longest, least noise-sensitive vectors; 2^(n-1) patterns.
  kMaxSpanningTree,
};

/// Largest all-pairs set kAuto uses (10 vectors: 5 points).
inline constexpr int kAutoAllPairsLimit = 10;
/// Free vectors kAuto uses beyond the all-pairs limit (12 vectors: 4096 sign patterns).
inline constexpr int kAutoBudget = 12;

/// "auto", "all_pairs" or "max_spanning_tree".
const char* to_string(FreeVectorSet set);

/// Number of free vectors `set` gives for n >= 2 points.
Eigen::Index free_vector_count(Eigen::Index n, FreeVectorSet set);

/// The pairs (i, j), i < j, of `set` for these points, one per column. all_pairs in
/// lexicographic order of (i, j); the spanning tree in order of addition to it; kAuto beyond
/// all pairs: its tree edges, then the further pairs by decreasing length (ties by (i, j)).
/// points: 3 x n, n >= 2 (not validated here: callers validate their own input).
Eigen::Matrix2Xi free_vector_pairs(const Eigen::Matrix3Xd& points, FreeVectorSet set);

/// free_vector_pairs(points, set) for points with a measurement each (image points, 2 x n, or
/// 3-D measurements): for kAuto beyond all pairs, the pair of largest |q_j - q_i| / |z_j - z_i|
/// replaces the last (shortest further) pair when the set does not hold it already, so that
/// the LUB scale of Eq. (23) over the set is the one over all pairs. Other sets are as above.
template <int MeasuredRows>
Eigen::Matrix2Xi free_vector_pairs(
    const Eigen::Matrix3Xd& points,
    const Eigen::Matrix<double, MeasuredRows, Eigen::Dynamic>& measured, FreeVectorSet set);

extern template Eigen::Matrix2Xi free_vector_pairs<2>(const Eigen::Matrix3Xd&,
                                                      const Eigen::Matrix2Xd&, FreeVectorSet);
extern template Eigen::Matrix2Xi free_vector_pairs<3>(const Eigen::Matrix3Xd&,
                                                      const Eigen::Matrix3Xd&, FreeVectorSet);

/// Free vectors with their measurements and weights.
template <int MeasuredRows>
struct FreeVectorsOf {
  Eigen::Matrix3Xd z_object;                              ///< z_j - z_i per pair
  Eigen::Matrix<double, MeasuredRows, Eigen::Dynamic> d;  ///< q_j - q_i per pair
  Eigen::VectorXd weights;                                ///< pair_weight per pair
  Eigen::Matrix2Xi pairs;                                 ///< (i, j) per column
};

/// Builds the free vectors of `pairs`. weights: n entries or empty (all 1). measured: MeasuredRows
/// x n. Not validated (callers validate their own input).
template <int MeasuredRows>
FreeVectorsOf<MeasuredRows> build_free_vectors(
    const Eigen::Matrix3Xd& points,
    const Eigen::Matrix<double, MeasuredRows, Eigen::Dynamic>& measured,
    const Eigen::VectorXd& weights, const Eigen::Matrix2Xi& pairs, PairWeighting weighting);

extern template FreeVectorsOf<2> build_free_vectors<2>(const Eigen::Matrix3Xd&,
                                                       const Eigen::Matrix2Xd&,
                                                       const Eigen::VectorXd&,
                                                       const Eigen::Matrix2Xi&, PairWeighting);
extern template FreeVectorsOf<3> build_free_vectors<3>(const Eigen::Matrix3Xd&,
                                                       const Eigen::Matrix3Xd&,
                                                       const Eigen::VectorXd&,
                                                       const Eigen::Matrix2Xi&, PairWeighting);

}  // namespace vantage
