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

class Designer {
 public:
  Designer(const Layout& layout, const AugmentOptions& options);

  int vector_count() const { return static_cast<int>(vectors_.cols()); }
  const Eigen::Matrix3Xd& vectors() const { return vectors_; }
  const AdditionSpace& space() const { return *space_; }
  long solves() const { return solves_; }

  /// The global worst case of `vectors`, counted in solves().
  WorstCase evaluate(const Eigen::Matrix3Xd& vectors);

  /// One greedy step from the current worst case; *out_of_candidates is set (and the step is
  /// empty) when there is nothing left to add.
  AugmentStep step(const WorstCase& current, bool* out_of_candidates);

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
  // Commit: mark the candidate used and append the new data vectors (and marker).
  void commit(const Option& chosen);
  // Description: the new worst case and the step's note in plain words.
  void describe(const WorstCase& current, const Option& chosen, AugmentStep* st);

  // Score of adding x; solves only when x kills every current worst viewpoint.
  Score score(const Eigen::Vector3d& x, const WorstCase& current, long* screened);
  // Compass search from x, starting with `step`.
  Eigen::Vector3d polish(Eigen::Vector3d x, Score* s, double step, const WorstCase& current,
                         long* screened);

  const Layout& layout_;
  const AugmentOptions& options_;
  std::unique_ptr<AdditionSpace> space_;
  Eigen::Matrix3Xd vectors_;
  Eigen::Matrix3Xd markers_;
  std::vector<bool> used_;
  long solves_ = 0;
};

}  // namespace vantage::design::internal
