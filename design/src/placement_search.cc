// The searches of marker placement (docs/math.md §21): the objective, the exhaustive search,
// greedy construction and swaps.

#include "placement_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vantage/analysis/parallel.h"

namespace vantage::design::internal {
namespace {

// Subsets whose t is compared per chunk: fixed, so that the level each chunk is searched against
// (the best of the chunks before) does not depend on the threads.
constexpr std::size_t kChunk = 8;
// Witnesses kept (the most recent first).
constexpr std::size_t kMaxWitnesses = 64;
// Swap passes at most (each pass tries every chosen site against every free one).
constexpr int kMaxPasses = 50;

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

std::unique_ptr<CameraSiteObjective> camera_objective(const PlaceOptions& options) {
  if (!options.camera) return nullptr;
  return std::make_unique<CameraSiteObjective>(*options.camera, options.threads);
}

SiteCoverage site_coverage(const PlacementProblem& problem, const PlaceOptions& options,
                           const CameraSiteObjective* camera) {
  if (camera == nullptr) return SiteCoverage(problem.sites, options.coverage_samples);
  return SiteCoverage(static_cast<int>(problem.sites.points.cols()), camera->directions(),
                      camera->min_seen(), [camera](int s, int d) { return camera->sees(s, d); });
}

// Directions a complete placement covers: ceil(min_coverage * D), or D - 1 by default (every
// lattice direction but one), at least 1.
int required_directions(const PlaceOptions& options, int directions) {
  if (directions == 0) return 0;
  if (!options.min_coverage) return std::max(1, directions - 1);
  const double wanted = std::ceil(*options.min_coverage * directions - 1e-9);
  return std::clamp(static_cast<int>(wanted), 1, directions);
}

}  // namespace

PlacementSearch::PlacementSearch(const PlacementProblem& problem, const PlaceOptions& options)
    : problem_(problem),
      options_(options),
      camera_(camera_objective(options)),
      coverage_(site_coverage(problem, options, camera_.get())),
      required_(required_directions(options, coverage_.directions())),
      evaluator_(problem, options, camera_.get()),
      kept_(static_cast<std::size_t>(problem.sites.points.cols()), 0) {
  for (int s : problem.keep) kept_[static_cast<std::size_t>(s)] = 1;
}

CoverageKey PlacementSearch::ranked(CoverageKey key, bool potential) const {
  if (key.covered >= required_) return {required_, 0};
  if (!potential) key.potential = 0;
  return key;
}

double PlacementSearch::no_level() const {
  return affine() ? 2.0 : std::numeric_limits<double>::infinity();
}

void PlacementSearch::progress(const std::string& stage) const {
  if (options_.progress) options_.progress(stage);
}

bool PlacementSearch::better_cover(const Scored& a, const Scored& b) const {
  if (!(a.cover == b.cover)) return b.cover < a.cover;
  return options_.robust_dropout && b.robust_cover < a.robust_cover;
}

bool PlacementSearch::better(const Scored& a, const Scored& b) const {
  if (better_cover(a, b)) return true;
  if (better_cover(b, a)) return false;
  return a.t < b.t - min_gain();
}

std::vector<std::vector<int>> PlacementSearch::family(const std::vector<int>& chosen) const {
  if (!options_.robust_dropout) return {chosen};
  std::vector<std::vector<int>> out;
  for (std::size_t m = 0; m < chosen.size(); ++m) out.push_back(without_position(chosen, m));
  return out;
}

CoverageKey PlacementSearch::robust_cover(const std::vector<int>& chosen) const {
  if (!options_.robust_dropout) return {};
  const std::vector<std::uint16_t> counts = coverage_.counts(chosen);
  CoverageKey least;
  bool first = true;
  for (int m : chosen) {
    std::vector<std::uint16_t> without = counts;
    for (int d = 0; d < coverage_.directions(); ++d) {
      if (coverage_.sees(m, d)) --without[static_cast<std::size_t>(d)];
    }
    const CoverageKey key = ranked(coverage_.key(without), false);
    if (first || key < least) least = key;
    first = false;
  }
  return least;
}

Scored PlacementSearch::score(std::vector<int> chosen) {
  Scored out;
  out.chosen = sorted(std::move(chosen));
  out.covered = coverage_.key(out.chosen).covered;
  out.cover = ranked(coverage_.key(out.chosen), false);
  out.robust_cover = robust_cover(out.chosen);
  const FamilyValue v = evaluator_.family_t(family(out.chosen), no_level(), {});
  evaluations_ += v.searches;
  out.t = v.t_upper;
  out.status = v.status;
  if (options_.robust_dropout && v.worst_member >= 0) {
    out.worst_lost = out.chosen[static_cast<std::size_t>(v.worst_member)];
  }
  remember(v.witnesses);
  return out;
}

void PlacementSearch::remember(const std::vector<Eigen::Vector3d>& found) {
  witnesses_.insert(witnesses_.begin(), found.begin(), found.end());
  if (witnesses_.size() > kMaxWitnesses) witnesses_.resize(kMaxWitnesses);
}

int PlacementSearch::least_t(const std::vector<std::vector<int>>& subsets, double level,
                             Scored* best) {
  int found = -1;
  for (std::size_t begin = 0; begin < subsets.size(); begin += kChunk) {
    const std::size_t end = std::min(subsets.size(), begin + kChunk);
    std::vector<FamilyValue> values(end - begin);
    const std::vector<Eigen::Vector3d> witnesses = witnesses_;
    parallel_blocks(static_cast<long>(end - begin), options_.threads, [&](long b, long e) {
      for (long k = b; k < e; ++k) {
        values[static_cast<std::size_t>(k)] = evaluator_.family_t(
            family(subsets[begin + static_cast<std::size_t>(k)]), level, witnesses);
      }
    });
    for (std::size_t k = 0; k < values.size(); ++k) {
      const FamilyValue& v = values[k];
      evaluations_ += v.searches;
      remember(v.witnesses);
      if (!v.below || !(v.t_upper < level)) continue;
      found = static_cast<int>(begin + k);
      level = v.t_upper - min_gain();
      best->t = v.t_upper;
      best->status = v.status;
      best->worst_lost = -1;
      if (options_.robust_dropout && v.worst_member >= 0) {
        best->worst_lost = subsets[begin + k][static_cast<std::size_t>(v.worst_member)];
      }
    }
  }
  return found;
}

std::vector<int> PlacementSearch::free_sites() const {
  std::vector<int> out;
  for (std::size_t s = 0; s < kept_.size(); ++s) {
    if (!kept_[s]) out.push_back(static_cast<int>(s));
  }
  return out;
}

long PlacementSearch::subset_count(long limit) const {
  const long n = static_cast<long>(free_sites().size());
  const long k = problem_.markers - static_cast<long>(problem_.keep.size());
  long c = 1;
  for (long i = 1; i <= k; ++i) {
    c = c * (n - k + i) / i;  // exact: C(n-k+i, i) at every step
    if (c > limit) return limit + 1;
  }
  return c;
}

std::optional<Scored> PlacementSearch::exhaustive(long* subsets) {
  const std::vector<int> free = free_sites();
  const int k = problem_.markers - static_cast<int>(problem_.keep.size());
  std::vector<std::vector<int>> all;
  std::vector<int> index(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) index[static_cast<std::size_t>(i)] = i;
  const int n = static_cast<int>(free.size());
  while (true) {
    std::vector<int> chosen = problem_.keep;
    for (int i : index) chosen.push_back(free[static_cast<std::size_t>(i)]);
    chosen = sorted(std::move(chosen));
    if (evaluator_.feasible(chosen)) all.push_back(std::move(chosen));
    int i = k - 1;
    while (i >= 0 && index[static_cast<std::size_t>(i)] == n - k + i) --i;
    if (i < 0) break;
    ++index[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < k; ++j) {
      index[static_cast<std::size_t>(j)] = index[static_cast<std::size_t>(j - 1)] + 1;
    }
  }
  *subsets = static_cast<long>(all.size());
  if (all.empty()) return std::nullopt;
  progress("exhaustive, " + std::to_string(all.size()) + " subsets");
  std::vector<CoverageKey> covers(all.size());
  std::vector<CoverageKey> robust(all.size());
  parallel_blocks(static_cast<long>(all.size()), options_.threads, [&](long b, long e) {
    for (long s = b; s < e; ++s) {
      covers[static_cast<std::size_t>(s)] = ranked(coverage_.key(all[s]), false);
    }
  });
  const CoverageKey top = *std::max_element(covers.begin(), covers.end());
  std::vector<std::vector<int>> ties;
  for (std::size_t s = 0; s < all.size(); ++s) {
    if (covers[s] == top) ties.push_back(all[s]);
  }
  if (options_.robust_dropout) {
    std::vector<CoverageKey> r(ties.size());
    parallel_blocks(static_cast<long>(ties.size()), options_.threads, [&](long b, long e) {
      for (long s = b; s < e; ++s) r[static_cast<std::size_t>(s)] = robust_cover(ties[s]);
    });
    const CoverageKey best = *std::max_element(r.begin(), r.end());
    std::vector<std::vector<int>> kept;
    for (std::size_t s = 0; s < ties.size(); ++s) {
      if (r[s] == best) kept.push_back(ties[s]);
    }
    ties = std::move(kept);
  }
  Scored best;
  const int winner = least_t(ties, no_level(), &best);
  best.chosen = ties[static_cast<std::size_t>(std::max(winner, 0))];
  best.covered = coverage_.key(best.chosen).covered;
  best.cover = top;
  best.robust_cover = robust_cover(best.chosen);
  return best;
}

std::optional<Scored> PlacementSearch::greedy(std::vector<PlacementStep>* steps) {
  std::vector<int> chosen = sorted(problem_.keep);
  const int k = problem_.sites.min_visible;
  auto record = [&](int added) {
    Scored s = chosen.size() >= static_cast<std::size_t>(k) ? score(chosen) : Scored{};
    // Too few markers track nothing: t = 1 (affine), no value (camera, tracker).
    if (chosen.size() < static_cast<std::size_t>(k) && !affine()) {
      s.t = std::numeric_limits<double>::infinity();
    }
    PlacementStep step;
    step.k = static_cast<int>(chosen.size());
    step.added = added;
    step.value.coverage =
        coverage_.directions() == 0
            ? 0.0
            : static_cast<double>(coverage_.key(chosen).covered) / coverage_.directions();
    step.value.objective = s.t;
    if (affine()) {
      step.value.t_upper = s.t;
      step.value.pbar_min = std::sqrt(std::max(0.0, 1.0 - s.t * s.t));
    }
    step.value.status = s.status;
    steps->push_back(step);
  };
  if (!chosen.empty()) record(-1);
  const std::vector<int> free = free_sites();
  while (static_cast<int>(chosen.size()) < problem_.markers) {
    progress("greedy " + std::to_string(chosen.size() + 1) + "/" +
             std::to_string(problem_.markers));
    const CoverageCounts counts(coverage_, chosen);
    std::vector<int> candidates;
    for (int c : free) {
      if (std::binary_search(chosen.begin(), chosen.end(), c)) continue;
      if (evaluator_.feasible_with(chosen, c)) candidates.push_back(c);
    }
    if (candidates.empty()) return std::nullopt;
    std::vector<CoverageKey> keys(candidates.size());
    parallel_blocks(static_cast<long>(candidates.size()), options_.threads, [&](long b, long e) {
      for (long i = b; i < e; ++i) {
        keys[static_cast<std::size_t>(i)] =
            ranked(counts.with_added(candidates[static_cast<std::size_t>(i)]), true);
      }
    });
    const CoverageKey top = *std::max_element(keys.begin(), keys.end());
    std::vector<std::vector<int>> ties;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (!(keys[i] == top)) continue;
      std::vector<int> next = chosen;
      next.push_back(candidates[i]);
      ties.push_back(sorted(std::move(next)));
    }
    if (options_.robust_dropout && static_cast<int>(chosen.size()) + 1 > k) {
      std::vector<CoverageKey> r(ties.size());
      for (std::size_t i = 0; i < ties.size(); ++i) r[i] = robust_cover(ties[i]);
      const CoverageKey best = *std::max_element(r.begin(), r.end());
      std::vector<std::vector<int>> kept;
      for (std::size_t i = 0; i < ties.size(); ++i) {
        if (r[i] == best) kept.push_back(ties[i]);
      }
      ties = std::move(kept);
    }
    int pick = 0;
    if (ties.size() > 1 && static_cast<int>(chosen.size()) + 1 >= k) {
      Scored best;
      pick = std::max(0, least_t(ties, no_level(), &best));
    }
    std::vector<int> next = ties[static_cast<std::size_t>(pick)];
    int added = -1;
    for (int s : next) {
      if (!std::binary_search(chosen.begin(), chosen.end(), s)) added = s;
    }
    chosen = std::move(next);
    record(added);
  }
  return score(chosen);
}

std::optional<Scored> PlacementSearch::perturbed(const Scored& from, std::mt19937_64* engine) {
  std::vector<int> movable;
  for (int s : from.chosen) {
    if (!kept_[static_cast<std::size_t>(s)]) movable.push_back(s);
  }
  if (movable.empty()) return std::nullopt;
  std::shuffle(movable.begin(), movable.end(), *engine);
  const std::size_t moves = std::min(movable.size(), std::max<std::size_t>(2, movable.size() / 3));
  std::vector<int> chosen = from.chosen;
  const std::vector<int> free = free_sites();
  for (std::size_t m = 0; m < moves; ++m) {
    chosen.erase(std::find(chosen.begin(), chosen.end(), movable[m]));
    std::vector<int> candidates;
    for (int c : free) {
      const bool taken = std::find(chosen.begin(), chosen.end(), c) != chosen.end();
      const bool removed = std::find(movable.begin(), movable.begin() + static_cast<long>(m) + 1,
                                     c) != movable.begin() + static_cast<long>(m) + 1;
      if (!taken && !removed && evaluator_.feasible_with(sorted(chosen), c)) {
        candidates.push_back(c);
      }
    }
    if (candidates.empty()) return std::nullopt;
    std::uniform_int_distribution<std::size_t> pick(0, candidates.size() - 1);
    chosen.push_back(candidates[pick(*engine)]);
  }
  return score(std::move(chosen));
}

Scored PlacementSearch::swaps(Scored current, int* swaps) {
  const std::vector<int> free = free_sites();
  for (int pass = 1; pass <= kMaxPasses; ++pass) {
    progress("swaps, pass " + std::to_string(pass));
    bool improved = false;
    const std::vector<int> removable = current.chosen;
    for (int out : removable) {
      if (kept_[static_cast<std::size_t>(out)]) continue;
      if (!std::binary_search(current.chosen.begin(), current.chosen.end(), out)) continue;
      CoverageCounts counts(coverage_, current.chosen);
      counts.prepare_removal(out);
      std::vector<int> rest;
      for (int s : current.chosen) {
        if (s != out) rest.push_back(s);
      }
      std::vector<int> candidates;
      for (int c : free) {
        if (std::binary_search(current.chosen.begin(), current.chosen.end(), c)) continue;
        if (evaluator_.feasible_with(rest, c)) candidates.push_back(c);
      }
      if (candidates.empty()) continue;
      std::vector<CoverageKey> keys(candidates.size());
      parallel_blocks(static_cast<long>(candidates.size()), options_.threads, [&](long b, long e) {
        for (long i = b; i < e; ++i) {
          keys[static_cast<std::size_t>(i)] =
              ranked(counts.with_swapped(candidates[static_cast<std::size_t>(i)]), false);
        }
      });
      const CoverageKey top = *std::max_element(keys.begin(), keys.end());
      if (top < current.cover) continue;
      std::vector<std::vector<int>> ties;
      for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (!(keys[i] == top)) continue;
        std::vector<int> next = rest;
        next.push_back(candidates[i]);
        ties.push_back(sorted(std::move(next)));
      }
      CoverageKey robust_top;
      if (options_.robust_dropout) {
        std::vector<CoverageKey> r(ties.size());
        parallel_blocks(static_cast<long>(ties.size()), options_.threads, [&](long b, long e) {
          for (long i = b; i < e; ++i) r[static_cast<std::size_t>(i)] = robust_cover(ties[i]);
        });
        robust_top = *std::max_element(r.begin(), r.end());
        if (top == current.cover && robust_top < current.robust_cover) continue;
        std::vector<std::vector<int>> kept;
        for (std::size_t i = 0; i < ties.size(); ++i) {
          if (r[i] == robust_top) kept.push_back(ties[i]);
        }
        ties = std::move(kept);
      }
      const bool cover_gain =
          current.cover < top || (options_.robust_dropout && current.robust_cover < robust_top);
      Scored best;
      const int pick = least_t(ties, cover_gain ? no_level() : current.t - min_gain(), &best);
      if (pick < 0) continue;
      best.chosen = ties[static_cast<std::size_t>(pick)];
      best.covered = coverage_.key(best.chosen).covered;
      best.cover = top;
      best.robust_cover = robust_top;
      if (!better(best, current)) continue;
      current = best;
      ++*swaps;
      improved = true;
    }
    if (!improved) break;
  }
  return current;
}

}  // namespace vantage::design::internal
