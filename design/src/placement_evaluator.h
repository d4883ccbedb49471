#pragma once

// Private to vantage::design: the certified worst case of a choice of sites, or of the choices
// left after the loss of one marker, needed only when it beats a level (docs/math.md §21).

#include <Eigen/Core>
#include <atomic>
#include <vector>

#include "camera_objective.h"

#include "vantage/design/placement.h"

namespace vantage::design::internal {

/// An attained viewpoint beyond which a subset is rejected without a search, and the value
/// t_upper of a subset family when it beat the level.
struct FamilyValue {
  bool below = false;    ///< every member's t_upper is below the level (then the fields hold)
  double t_upper = 1.0;  ///< the largest t_upper of the members (1 for an untrackable member)
  int worst_member = -1;
  visibility::VisibilityWorstViewpoint::Status status =
      visibility::VisibilityWorstViewpoint::Status::kUntrackable;  ///< of the worst member
  std::vector<Eigen::Vector3d> witnesses;  ///< worst viewpoints the searches found
  int searches = 0;                        ///< certified searches run
};

class PlacementEvaluator {
 public:
  /// `camera` (or null for the affine objective) outlives the evaluator.
  PlacementEvaluator(const PlacementProblem& problem, const PlaceOptions& options,
                     const CameraSiteObjective* camera);

  /// The visibility problem of the chosen sites (their grid markers remapped).
  visibility::VisibilityProblem subproblem(const std::vector<int>& chosen) const;

  /// The separation and distance-difference constraints hold for `chosen`.
  bool feasible(const std::vector<int>& chosen) const;
  /// The constraints hold for `chosen` plus site c, given that they hold for `chosen`.
  bool feasible_with(const std::vector<int>& chosen, int c) const;

  /// The largest objective value over `family` (subsets of sites), when below `level`. Affine:
  /// t_upper, attained values at the witnesses first, then a search per member that stops once
  /// it attains the level; `tolerance` > 0 replaces the search's certificate tolerance (the
  /// random baseline's). Camera: the statistic of the CRB; tracker: the largest certified worst
  /// RMS TRE bound over the targets, the witnesses' attained values first (docs/math.md §21,
  /// "Objectives").
  FamilyValue family_t(const std::vector<std::vector<int>>& family, double level,
                       const std::vector<Eigen::Vector3d>& witnesses, double tolerance = 0.0) const;

 private:
  std::vector<visibility::VisibilityProblem> subproblems(
      const std::vector<std::vector<int>>& family) const;
  FamilyValue camera_family(const std::vector<std::vector<int>>& family, double level) const;
  FamilyValue tracker_family(const std::vector<std::vector<int>>& family, double level,
                             const std::vector<Eigen::Vector3d>& witnesses) const;

  const PlacementProblem& problem_;
  const PlaceOptions& options_;
  const CameraSiteObjective* camera_;
  const double separation_;  // PlacementProblem::least_separation()
  // The camera's worst direction last found: tried first (it only speeds the rejections up).
  mutable std::atomic<int> camera_hint_{0};
};

/// `chosen` without its entry m (by position).
std::vector<int> without_position(const std::vector<int>& chosen, std::size_t m);

}  // namespace vantage::design::internal
