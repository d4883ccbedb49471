#pragma once

// Private to vantage::design: one greedy step of the augmenter (augment_layout(), Sec. III.E
// done on the global worst viewpoints, docs/math.md §18). A step generates candidate additions,
// chooses the best (polishing the best few by a compass search), commits it to the layout and
// describes what happened; the mode-specific parts live in the AdditionSpace.

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <vector>

#include "addition_space.h"
#include "vantage/design/augment.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/sdp/worst_viewpoint_additions.h"

namespace vantage::design::internal {

/// Score of a candidate addition: lower t is better, then fewer surviving worst viewpoints, then
/// the larger kill margin.
struct Score {
  double t = std::numeric_limits<double>::infinity();
  int n_worst = std::numeric_limits<int>::max();
  double kill_margin = -std::numeric_limits<double>::infinity();
};

/// a ranks before b; t values within `tie` are equal.
bool better(const Score& a, const Score& b, double tie);

/// evaluate_worst_case() with the global solver's options. With a finite options.stop_above the
/// solve may stop early: then *stopped is set and only t (a value attained above stop_above, so
/// a lower bound on the true t) and one viewpoint are meaningful.
WorstCase evaluate_worst_case(const Eigen::Matrix3Xd& vectors,
                              const sdp::WorstViewpointOptions& options, bool* stopped);

/// The worst case a global solve `w` of `vectors` reports (*stopped as above, when not null).
WorstCase worst_case_of(const sdp::WorstViewpoint& w, const Eigen::Matrix3Xd& vectors,
                        bool* stopped);

/// Prepared solves (prepare()) start at this fraction of the t expected: candidates are rarely
/// that much better than the best known, and the frontier grows as (t / level)^2.
inline constexpr double kPreparedLevel = 0.7;
/// Below this level the solves are not prepared: the preparation refines crossing patches to
/// ~level / 2, as costly as many whole solves.
inline constexpr double kMinPreparedLevel = 1e-4;

/// One greedy step on one layout. Everything a step does is a function of that layout (its
/// entries, the canonical data_vectors() order, its remaining candidates, the search box of its
/// markers) and of the options: a step is the same whether it is the second of `--add 2` or
/// the first of `--add 1` on the layout the first step wrote. augment_layout() makes one
/// Designer per step (and one, on the final layout, for the direct optimiser).
class Designer {
 public:
  Designer(const Layout& layout, const AugmentOptions& options);

  /// The layout: as given, and after step() with the addition appended and the candidate it
  /// used (if any) removed.
  const Layout& layout() const { return layout_; }
  int vector_count() const { return static_cast<int>(vectors_.cols()); }
  const Eigen::Matrix3Xd& vectors() const { return vectors_; }
  const AdditionSpace& space() const { return *space_; }
  const AugmentOptions& options() const { return options_; }
  long solves() const { return solves_; }

  /// The global worst case of `vectors`, counted in solves(). The worst viewpoints of the
  /// current layout and of the last complete solve are passed to the solver as hints (they
  /// change its work, not its answer). With a finite stop_above the solve stops once t >
  /// stop_above is proven: *stopped is then set and only t (a lower bound) is meaningful.
  WorstCase evaluate(const Eigen::Matrix3Xd& vectors,
                     double stop_above = std::numeric_limits<double>::infinity(),
                     bool* stopped = nullptr);

  /// Prepares evaluate_added() for additions to `base` whose t is expected near `expected_t`
  /// (sdp::WorstViewpointWithAdditions at kPreparedLevel * expected_t; with prune_solves off,
  /// or a level below kMinPreparedLevel, evaluate_added() solves [base, added] whole).
  void prepare(const Eigen::Matrix3Xd& base, double expected_t);

  /// evaluate() of [base, added] for the prepared base: the same answer, from the prepared
  /// frontier. A solve whose t falls below the frontier's level re-prepares it lower.
  WorstCase evaluate_added(const Eigen::Matrix3Xd& added,
                           double stop_above = std::numeric_limits<double>::infinity(),
                           bool* stopped = nullptr);

  /// One greedy step from `current`, the worst case of layout() (evaluate_worst_case of its
  /// data vectors, as the step reports its own); *out_of_candidates is set (and the step is
  /// empty) when there is nothing left to add, *no_feasible (and the step is empty, the layout
  /// unchanged) when the best option breaks AugmentOptions::min_distance_difference (then every
  /// option does). The step's candidate_index is into layout()'s candidates before the step.
  /// Call once.
  AugmentStep step(const WorstCase& current, bool* out_of_candidates, bool* no_feasible);

  /// AugmentOptions::min_distance_difference: true when it is 0 or the columns of `markers`
  /// keep it (vantage::tracker::min_distance_difference, docs/math.md §24).
  bool keeps_distance_difference(const Eigen::Matrix3Xd& markers) const;
  /// Point mode: keeps_distance_difference() of layout()'s markers with x added.
  bool feasible(const Eigen::Vector3d& x) const;

 private:
  struct Option {
    Eigen::Vector3d x;
    int candidate_index;  // into Layout::candidates, or -1
    Score score;
  };

  // Candidate generation: the unused layout candidates, then (unless candidates_only) the
  // space's coarse samples; each scored on the way. Also fills the step's kill-level facts.
  std::vector<Option> generate(const WorstCase& current, AugmentStep* st);
  // Choice: the best option after polishing the best few (unless candidates_only).
  Option choose(std::vector<Option>* options, const WorstCase& current, AugmentStep* st);
  // Commit: append the addition to the layout (removing the candidate it used) and recompute
  // the data vectors and markers from it.
  void commit(const Option& chosen);
  // Description: the new worst case (a hint-free solve of the new layout's data vectors, so
  // that it equals a fresh run's initial one) and the step's note in plain words.
  void describe(const WorstCase& current, const Option& chosen, AugmentStep* st);

  // The global solver's options of one solve: hints and stop_above when prune_solves.
  sdp::WorstViewpointOptions solve_options(double stop_above) const;
  // Keeps the viewpoints of a complete solve as hints for the next.
  void remember(const WorstCase& w, bool stopped);

  // Score of adding x; solves only when x kills every current worst viewpoint. A score whose t
  // would exceed stop_above need not be exact: the solve may stop with t a value above it (and
  // n_worst = max), which ranks it behind every score with t <= stop_above - tie. With
  // `viewpoints`, the viewpoints where x's t is attained are stored there (the surviving worst
  // viewpoints when x does not kill them all). An x that is not feasible() has the worst Score
  // (t = +infinity); with `viewpoints` it is still solved for them (they bound the box search's
  // cells around x) and the solve counts.
  Score score(const Eigen::Vector3d& x, const WorstCase& current, long* screened,
              double stop_above = std::numeric_limits<double>::infinity(),
              std::vector<Eigen::Vector3d>* viewpoints = nullptr);
  // Point mode: the branch and bound over the search box (box_search.h) from `chosen`.
  void search_box(Option* chosen, const WorstCase& current, AugmentStep* st);
  // Compass search from x, starting with `step`.
  Eigen::Vector3d polish(Eigen::Vector3d x, Score* s, double step, const WorstCase& current,
                         long* screened);

  Layout layout_;
  const AugmentOptions& options_;
  std::unique_ptr<AdditionSpace> space_;
  Eigen::Matrix3Xd vectors_;
  Eigen::Matrix3Xd markers_;
  std::vector<bool> used_;
  std::vector<Eigen::Vector3d> hints_;  // worst viewpoints of the current layout and last solve
  int current_hints_ = 0;               // how many of hints_ are the current layout's
  long solves_ = 0;
  Eigen::Matrix3Xd prepared_base_;
  std::unique_ptr<sdp::WorstViewpointWithAdditions> prepared_;
};

}  // namespace vantage::design::internal
