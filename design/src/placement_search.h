#pragma once

// Private to vantage::design: the searches of marker placement (docs/math.md §21) over one
// objective: exhaustive, greedy, swaps, the random baseline, and greedy by coverage alone.

#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "camera_objective.h"

#include "placement_coverage.h"
#include "placement_evaluator.h"
#include "vantage/design/placement.h"

namespace vantage::design::internal {

/// A choice scored by the objective: coverage first (with robust_dropout, then the least
/// coverage after one loss), ranked by PlacementSearch::ranked(), then t (the largest objective
/// value over the family: the choice itself, or each choice left after one loss), smaller better.
struct Scored {
  std::vector<int> chosen;   ///< increasing
  int covered = 0;           ///< lattice directions covered, as counted
  CoverageKey cover;         ///< ranked
  CoverageKey robust_cover;  ///< robust_dropout only
  double t = 1.0;
  int worst_lost = -1;  ///< robust_dropout: the site whose loss gives t
  visibility::VisibilityWorstViewpoint::Status status =
      visibility::VisibilityWorstViewpoint::Status::kUntrackable;
};

class PlacementSearch {
 public:
  PlacementSearch(const PlacementProblem& problem, const PlaceOptions& options);

  const SiteCoverage& coverage() const { return coverage_; }
  /// Lattice directions a complete choice covers at least.
  int required() const { return required_; }
  /// The camera objective's model, or null (affine, tracker).
  const CameraSiteObjective* camera() const { return camera_.get(); }
  /// The objective is the paper's bound (t, p-bar_min), not camera or tracker.
  bool affine() const { return !camera_ && !options_.tracker; }
  const PlacementEvaluator& evaluator() const { return evaluator_; }
  long evaluations() const { return evaluations_; }

  /// a is better than b by coverage alone (with robust_dropout, then the least coverage after
  /// one loss).
  bool better_cover(const Scored& a, const Scored& b) const;
  /// a is better than b by the objective.
  bool better(const Scored& a, const Scored& b) const;
  /// The full score of a choice (no level).
  Scored score(std::vector<int> chosen);

  /// K-subsets of the free sites, or limit + 1 when there are more than `limit`.
  long subset_count(long limit) const;
  /// Every feasible subset; nullopt when none is feasible. `*subsets` counts them.
  std::optional<Scored> exhaustive(long* subsets);
  /// The greedy construction; `steps` gets the value after each addition.
  std::optional<Scored> greedy(std::vector<PlacementStep>* steps);
  /// Improving swaps from `start` until none improves; `*swaps` counts them.
  Scored swaps(Scored start, int* swaps);
  /// A random neighbour of `from` for the iterated local search (docs/math.md §21, "Search"):
  /// min(f, max(2, f/3)) of its f free markers, uniform, replaced one by one by uniform free sites
  /// that keep the constraints; scored. nullopt when a replacement finds no feasible site.
  std::optional<Scored> perturbed(const Scored& from, std::mt19937_64* engine);
  /// The random baseline.
  RandomBaseline baseline(std::optional<Scored>* best);
  /// Markers at which greedy by coverage alone covers every lattice direction, if it does.
  std::optional<int> covering_markers();

 private:
  /// The baseline's random feasible subsets, one per trial (none where 100 draws were not
  /// feasible), with their coverage.
  std::vector<std::optional<Scored>> draw_baseline();
  /// The objective of the drawn subsets where it counts: the complete ones and those that tie
  /// the best coverage.
  void search_baseline(std::vector<std::optional<Scored>>* drawn);
  std::vector<std::vector<int>> family(const std::vector<int>& chosen) const;
  // The key as placements are ranked: every key covering required() directions is the same
  // (coverage no longer ranks), below it the count, then (`potential`: the greedy's guide only)
  // the potential.
  CoverageKey ranked(CoverageKey key, bool potential) const;
  // A level above every objective value: 2 for t, +inf for degrees.
  double no_level() const;
  CoverageKey robust_cover(const std::vector<int>& chosen) const;
  // Among `subsets` (tying on coverage), the first of least t below `level`, by chunks of fixed
  // size so that the answer does not depend on the threads; -1 when none is below.
  int least_t(const std::vector<std::vector<int>>& subsets, double level, Scored* best);
  void remember(const std::vector<Eigen::Vector3d>& found);
  std::vector<int> free_sites() const;
  // A swap or a new incumbent must lower t by more than the certificate tolerance: two t_upper
  // closer than that are not told apart, and the earlier choice stays.
  // The camera's and the tracker's values are exact (a lattice statistic, a certified bound
  // computed the same way every time): any decrease counts.
  double min_gain() const { return affine() ? options_.search.certificate_tolerance : 0.0; }
  void progress(const std::string& stage) const;

  const PlacementProblem& problem_;
  const PlaceOptions& options_;
  std::unique_ptr<CameraSiteObjective> camera_;
  SiteCoverage coverage_;
  int required_ = 0;
  PlacementEvaluator evaluator_;
  std::vector<char> kept_;
  std::vector<Eigen::Vector3d> witnesses_;
  long evaluations_ = 0;
};

}  // namespace vantage::design::internal
