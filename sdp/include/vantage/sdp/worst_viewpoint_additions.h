#pragma once

/// The global worst viewpoint (Theorem 6, Eq. 31) of one fixed set of data vectors plus a few
/// more, for many different additions: the augmenter's inner loop, which scores thousands of
/// candidate markers or directions against the same layout.
///
/// Adding vectors never raises t* = max_a min_i |a.n_i|. So once the base layout's branch and
/// bound has proven its objective below a level L outside a small set of patches (the frontier),
/// the objective of every augmented layout is below L there too, and a search of the frontier
/// alone (with the base circles that can still bound each patch plus all the added ones) decides
/// every augmented layout whose t* >= L. Layouts whose t* < L fall back to a whole-sphere search.
/// Either way the answer is global_worst_viewpoint()'s: the same optima, certificate and ties.

#include <Eigen/Core>
#include <memory>

#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {

namespace internal {
struct Frontier;
}

class WorstViewpointWithAdditions {
 public:
  /// Prepares `base` (3 x m, m >= 1, non-zero finite columns) at the level `level` in (0, 1]
  /// (a t* that the augmented layouts of interest are expected to reach, e.g. a fraction of the
  /// base layout's t*). The preparation costs about (base t* / level)^2 whole-sphere searches
  /// of the base: patches crossed by a circle are refined until their bound is below level.
  /// options: tie_tolerance and max_patches are used here and must be those of every solve().
  /// Throws InvalidArgument on bad input.
  WorstViewpointWithAdditions(const Eigen::Matrix3Xd& base, double level,
                              const WorstViewpointOptions& options = {});
  ~WorstViewpointWithAdditions();
  WorstViewpointWithAdditions(WorstViewpointWithAdditions&&) noexcept;
  WorstViewpointWithAdditions& operator=(WorstViewpointWithAdditions&&) noexcept;

  /// global_worst_viewpoint([base, added], options) (added: 3 x k, k >= 1, non-zero finite
  /// columns): the same result, from the frontier when its t* >= level(), else from a search of
  /// the whole sphere (counted in fallbacks()). Columns of the result refer to [base, added].
  /// Throws InvalidArgument on bad input, or when options.tie_tolerance differs from the one
  /// the frontier was collected with.
  WorstViewpoint solve(const Eigen::Matrix3Xd& added, const WorstViewpointOptions& options = {});

  double level() const;
  long frontier_patches() const;                 ///< patches of the frontier
  long fallbacks() const { return fallbacks_; }  ///< solves that searched the whole sphere

 private:
  Eigen::Matrix3Xd base_;           // unit columns
  Eigen::Matrix3Xd distinct_base_;  // unit, repeats removed: the frontier's circles
  double tie_tolerance_ = 0.0;
  std::unique_ptr<internal::Frontier> frontier_;
  long fallbacks_ = 0;
};

}  // namespace vantage::sdp
