#include "designer.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "box_search.h"
#include "kill_level.h"
#include "text.h"
#include "vantage/analysis/common.h"
#include "vantage/tracker/identification.h"

namespace vantage::design::internal {
namespace {

// Compass search iteration cap (each iteration either moves or shrinks the step).
constexpr int kMaxCompassIterations = 400;
// Compass search: the step shrinks by this factor when no move improves.
constexpr double kStepShrink = 0.5;

}  // namespace

bool better(const Score& a, const Score& b, double tie) {
  if (a.t < b.t - tie) return true;
  if (a.t > b.t + tie) return false;
  if (a.n_worst != b.n_worst) return a.n_worst < b.n_worst;
  return a.kill_margin > b.kill_margin;
}

Designer::Designer(const Layout& layout, const AugmentOptions& options)
    : layout_(layout),
      options_(options),
      space_(make_addition_space(layout, options)),
      vectors_(data_vectors(layout).vectors),
      markers_(layout.entries),
      used_(layout.candidates.cols(), false) {}

sdp::WorstViewpointOptions Designer::solve_options(double stop_above) const {
  sdp::WorstViewpointOptions options;
  if (options_.prune_solves) {
    options.hints = hints_;
    options.stop_above = stop_above;
  }
  return options;
}

void Designer::remember(const WorstCase& w, bool stopped) {
  if (stopped) return;
  hints_.resize(current_hints_);
  hints_.insert(hints_.end(), w.viewpoints.begin(), w.viewpoints.end());
}

WorstCase Designer::evaluate(const Eigen::Matrix3Xd& vectors, double stop_above, bool* stopped) {
  ++solves_;
  bool was_stopped = false;
  WorstCase w = evaluate_worst_case(vectors, solve_options(stop_above), &was_stopped);
  if (stopped != nullptr) *stopped = was_stopped;
  remember(w, was_stopped);
  return w;
}

void Designer::prepare(const Eigen::Matrix3Xd& base, double expected_t) {
  prepared_base_ = base;
  prepared_.reset();
  const double level = kPreparedLevel * expected_t;
  if (options_.prune_solves && level >= kMinPreparedLevel && level <= 1.0) {
    prepared_ = std::make_unique<sdp::WorstViewpointWithAdditions>(base, level);
  }
}

WorstCase Designer::evaluate_added(const Eigen::Matrix3Xd& added, double stop_above,
                                   bool* stopped) {
  Eigen::Matrix3Xd all(3, prepared_base_.cols() + added.cols());
  all << prepared_base_, added;
  if (prepared_ == nullptr) return evaluate(all, stop_above, stopped);
  ++solves_;
  const long fallbacks = prepared_->fallbacks();
  bool was_stopped = false;
  WorstCase w =
      worst_case_of(prepared_->solve(added, solve_options(stop_above)), all, &was_stopped);
  if (stopped != nullptr) *stopped = was_stopped;
  remember(w, was_stopped);
  if (prepared_->fallbacks() > fallbacks) prepare(prepared_base_, w.t);
  return w;
}

bool Designer::keeps_distance_difference(const Eigen::Matrix3Xd& markers) const {
  const double gap = options_.min_distance_difference;
  return !(gap > 0.0) || tracker::min_distance_difference(markers).value >= gap;
}

bool Designer::feasible(const Eigen::Vector3d& x) const {
  if (!(options_.min_distance_difference > 0.0)) return true;
  Eigen::Matrix3Xd markers(3, markers_.cols() + 1);
  markers << markers_, x;
  return keeps_distance_difference(markers);
}

Score Designer::score(const Eigen::Vector3d& x, const WorstCase& current, long* screened,
                      double stop_above, std::vector<Eigen::Vector3d>* viewpoints) {
  Score s;
  Eigen::Matrix3Xd added;
  if (!space_->new_vectors(x, markers_, &added)) return s;
  if (!feasible(x)) {
    if (viewpoints != nullptr) *viewpoints = evaluate_added(added).viewpoints;
    return s;
  }
  int survivors = 0;
  double margin = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& a : current.viewpoints) {
    double proj = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < added.cols(); ++i) {
      proj = std::min(proj, std::abs(a.dot(added.col(i).normalized())));
    }
    if (proj < current.t - options_.tie_tolerance) {
      margin = std::min(margin, current.t - proj);
    } else {
      ++survivors;
      if (viewpoints != nullptr) viewpoints->push_back(a);
    }
  }
  s.kill_margin = std::isfinite(margin) ? margin : 0.0;
  if (survivors > 0) {
    ++*screened;
    s.t = current.t;
    s.n_worst = survivors;
    return s;
  }
  bool stopped = false;
  const WorstCase w = evaluate_added(added, stop_above, &stopped);
  if (viewpoints != nullptr) *viewpoints = w.viewpoints;
  s.t = w.t;
  s.n_worst = stopped ? std::numeric_limits<int>::max() : static_cast<int>(w.viewpoints.size());
  return s;
}

Eigen::Vector3d Designer::polish(Eigen::Vector3d x, Score* s, double step, const WorstCase& current,
                                 long* screened) {
  for (int it = 0; it < kMaxCompassIterations && step > options_.refine_tolerance; ++it) {
    Eigen::Vector3d dirs[AdditionSpace::kMaxCompassMoves];
    const int count = space_->compass_moves(x, dirs);
    Eigen::Vector3d best_x = x;
    Score best_s = *s;
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector3d y = space_->move(x, step, dirs[k]);
      // Only a move that can beat best_s needs its exact score.
      const Score sy = score(y, current, screened, best_s.t + options_.tie_tolerance);
      if (better(sy, best_s, options_.tie_tolerance)) {
        best_s = sy;
        best_x = y;
      }
    }
    if (best_x == x) {
      step *= kStepShrink;
    } else {
      x = best_x;
      *s = best_s;
    }
  }
  return x;
}

std::vector<Designer::Option> Designer::generate(const WorstCase& current, AugmentStep* st) {
  std::vector<Option> options;
  // choose() uses the first `ranked` options after sorting: a candidate whose t exceeds the
  // ranked-th best exact t so far by more than the tie tolerance ranks behind them, so its
  // solve may stop there.
  const std::size_t ranked = options_.candidates_only ? 1 : options_.refine_starts;
  std::vector<double> best_t;  // the `ranked` smallest exact t so far, ascending
  auto add = [&](const Eigen::Vector3d& x, int index) {
    const double stop_above = best_t.size() < ranked ? std::numeric_limits<double>::infinity()
                                                     : best_t.back() + options_.tie_tolerance;
    const Score s = score(x, current, &st->screened, stop_above);
    options.push_back({x, index, s});
    if (s.t > stop_above) return;     // the solve stopped above: not exact
    if (!std::isfinite(s.t)) return;  // infeasible: ranks last
    best_t.insert(std::upper_bound(best_t.begin(), best_t.end(), s.t), s.t);
    if (best_t.size() > ranked) best_t.pop_back();
  };
  for (Eigen::Index c = 0; c < layout_.candidates.cols(); ++c) {
    if (!used_[c]) add(space_->addition(layout_.candidates.col(c)), static_cast<int>(c));
  }
  Eigen::Vector3d kill_point = Eigen::Vector3d::UnitX();
  std::vector<Eigen::Vector3d> kill_points;
  st->best_kill_level = best_kill_level(current.viewpoints, &kill_point, &kill_points);
  st->single_vector_can_improve =
      space_->single_addition_can_improve(st->best_kill_level, current.t, options_.tie_tolerance);
  if (!options_.candidates_only) {
    std::vector<Eigen::Vector3d> samples;
    space_->coarse_samples(current, kill_points, &samples);
    for (const Eigen::Vector3d& x : samples) add(x, -1);
  }
  return options;
}

Designer::Option Designer::choose(std::vector<Option>* options, const WorstCase& current,
                                  AugmentStep* st) {
  std::stable_sort(options->begin(), options->end(), [this](const Option& a, const Option& b) {
    return better(a.score, b.score, options_.tie_tolerance);
  });
  Option chosen = options->front();
  if (options_.candidates_only) return chosen;
  const int starts = std::min<int>(options_.refine_starts, static_cast<int>(options->size()));
  for (int r = 0; r < starts; ++r) {
    Option o = (*options)[r];
    o.x = polish(o.x, &o.score, space_->initial_compass_step(), current, &st->screened);
    if (o.x != (*options)[r].x) o.candidate_index = -1;
    if (better(o.score, chosen.score, options_.tie_tolerance)) chosen = o;
  }
  search_box(&chosen, current, st);
  return chosen;
}

void Designer::search_box(Option* chosen, const WorstCase& current, AugmentStep* st) {
  Eigen::Vector3d lo, hi;
  if (!space_->search_box(&lo, &hi) || options_.search_budget == 0) return;
  const long max_solves =
      std::max<long>(1, options_.search_budget / std::max<Eigen::Index>(1, vectors_.cols()));
  Eigen::Matrix3Xd unit_vectors = vectors_;
  for (Eigen::Index j = 0; j < unit_vectors.cols(); ++j) unit_vectors.col(j).normalize();
  BoxSearchCalls calls;
  calls.probe = [&](const Eigen::Vector3d& x, std::vector<Eigen::Vector3d>* viewpoints) {
    return score(x, current, &st->screened, std::numeric_limits<double>::infinity(), viewpoints);
  };
  calls.polish = [&](const Eigen::Vector3d& x, Score* s, double step) {
    return polish(x, s, step, current, &st->screened);
  };
  calls.solves = [this] { return solves_; };
  const BoxSearchResult r = internal::search_box(
      lo, hi, markers_, unit_vectors, current.viewpoints, chosen->x, chosen->score,
      options_.search_tolerance, options_.tie_tolerance, max_solves, calls);
  st->search_t_lower = r.t_lower;
  st->search_closed = r.closed;
  st->search_unresolved = r.unresolved;
  st->search_solves = r.solves;
  if (r.x != chosen->x) *chosen = {r.x, -1, r.score};
}

void Designer::commit(const Option& chosen) {
  Eigen::Matrix3Xd added;
  VANTAGE_CHECK(space_->new_vectors(chosen.x, markers_, &added), "chosen addition is degenerate");
  if (chosen.candidate_index >= 0) {
    const Eigen::Index c = chosen.candidate_index;
    const Eigen::Index n = layout_.candidates.cols();
    Eigen::Matrix3Xd kept(3, n - 1);
    kept << layout_.candidates.leftCols(c), layout_.candidates.rightCols(n - 1 - c);
    layout_.candidates = kept;
    used_.erase(used_.begin() + c);
  }
  append_entry(&layout_, chosen.x, "added");
  vectors_ = data_vectors(layout_).vectors;
  markers_ = layout_.entries;
}

void Designer::describe(const WorstCase& current, const Option& chosen, AugmentStep* st) {
  st->added = chosen.x;
  st->candidate_index = chosen.candidate_index;
  ++solves_;
  st->worst = evaluate_worst_case(vectors_, sdp::WorstViewpointOptions{}, nullptr);
  st->vector_count = vector_count();
  st->ceiling = pbar_ceiling(st->vector_count);
  st->improved = st->worst.t < current.t - options_.tie_tolerance;
  st->angle_from_worst_plane_deg =
      space_->angle_from_worst_planes_deg(chosen.x, current.viewpoints);
  std::ostringstream note;
  const int k = static_cast<int>(current.viewpoints.size());
  if (st->improved) {
    note << "p-bar_min rose from " << fmt(current.pbar_min) << " to " << fmt(st->worst.pbar_min);
  } else if (!st->single_vector_can_improve) {
    note << "no single vector can raise p-bar_min = " << fmt(current.pbar_min) << ": the " << k
         << " worst viewpoint(s) cannot all be killed at once (min over unit c of max_k |a_k.c| "
         << "= " << fmt(st->best_kill_level) << " >= t = " << fmt(current.t)
         << "); added the vector leaving the fewest worst viewpoints ("
         << st->worst.viewpoints.size() << ")";
  } else if (options_.candidates_only) {
    note << "p-bar_min unchanged at " << fmt(current.pbar_min)
         << ": no remaining candidate kills all " << k << " worst viewpoint(s)";
  } else {
    note << "p-bar_min unchanged at " << fmt(current.pbar_min) << ": no addition found in the "
         << space_->search_name() << " kills all " << k
         << " worst viewpoint(s); added the one leaving the fewest (" << st->worst.viewpoints.size()
         << ")";
  }
  st->note = note.str();
}

AugmentStep Designer::step(const WorstCase& current, bool* out_of_candidates, bool* no_feasible) {
  AugmentStep st;
  hints_ = current.viewpoints;
  current_hints_ = static_cast<int>(hints_.size());
  prepare(vectors_, current.t);
  const long solves_before = solves_;
  std::vector<Option> options = generate(current, &st);
  if (options.empty()) {
    *out_of_candidates = true;
    return st;
  }
  const Option chosen = choose(&options, current, &st);
  if (!feasible(chosen.x)) {
    // Infeasible options rank last: the best one is infeasible only when all are.
    *no_feasible = true;
    return st;
  }
  commit(chosen);
  describe(current, chosen, &st);
  st.global_solves = solves_ - solves_before;
  return st;
}

}  // namespace vantage::design::internal
