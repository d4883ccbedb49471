// The anchors of a placement (docs/math.md §21, "How far from optimal"): random feasible
// subsets, and greedy by coverage alone past K.

#include <algorithm>
#include <cmath>

#include "placement_random.h"
#include "placement_search.h"
#include "vantage/analysis/parallel.h"

namespace vantage::design::internal {
namespace {

// Draws of one random subset before it counts as infeasible.
constexpr int kDrawAttempts = 100;
// The baseline's trials are certified to this in t (or the search's tolerance, if coarser): an
// anchor reported to four digits, and its t_upper only errs on the baseline's side.
constexpr double kBaselineTolerance = 1e-5;

}  // namespace

std::vector<std::optional<Scored>> PlacementSearch::draw_baseline() {
  const std::vector<int> free = free_sites();
  const int k = problem_.markers - static_cast<int>(problem_.keep.size());
  const int trials = options_.random_trials;
  std::vector<std::optional<Scored>> drawn(static_cast<std::size_t>(trials));
  // Each trial has its own engine, so the draws do not depend on the threads. Coverage first:
  // it is counted, not searched.
  parallel_blocks(trials, options_.threads, [&](long b, long e) {
    for (long trial = b; trial < e; ++trial) {
      PlacementRandom random =
          PlacementRandom::for_draw(options_.seed, static_cast<std::uint64_t>(trial));
      for (int attempt = 0; attempt < kDrawAttempts; ++attempt) {
        std::vector<int> pool = free;
        std::vector<int> chosen = problem_.keep;
        for (int i = 0; i < k; ++i) {
          const std::size_t j =
              static_cast<std::size_t>(i) + random.index(pool.size() - static_cast<std::size_t>(i));
          std::swap(pool[static_cast<std::size_t>(i)], pool[j]);
          chosen.push_back(pool[static_cast<std::size_t>(i)]);
        }
        std::sort(chosen.begin(), chosen.end());
        if (!evaluator_.feasible(chosen)) continue;
        Scored s;
        s.chosen = chosen;
        s.covered = coverage_.key(chosen).covered;
        s.cover = ranked(coverage_.key(chosen), false);
        s.robust_cover = robust_cover(chosen);
        drawn[static_cast<std::size_t>(trial)] = std::move(s);
        break;
      }
    }
  });
  return drawn;
}

void PlacementSearch::search_baseline(std::vector<std::optional<Scored>>* drawn_subsets) {
  std::vector<std::optional<Scored>>& drawn = *drawn_subsets;
  // t is searched only where it counts: the complete trials (a trial that leaves a lattice
  // direction untrackable has p-bar_min 0 in the median) and those tying the best coverage.
  const Scored* top = nullptr;
  for (const std::optional<Scored>& s : drawn) {
    if (s && (top == nullptr || better_cover(*s, *top))) top = &*s;
  }
  std::vector<Scored*> searched;
  for (std::optional<Scored>& s : drawn) {
    if (!s) continue;
    const bool complete = s->covered >= required_;
    const bool ties_top = !better_cover(*top, *s);
    if (complete || ties_top) searched.push_back(&*s);
  }
  parallel_blocks(static_cast<long>(searched.size()), options_.threads, [&](long b, long e) {
    for (long i = b; i < e; ++i) {
      Scored& s = *searched[static_cast<std::size_t>(i)];
      const FamilyValue v =
          evaluator_.family_t(family(s.chosen), no_level(), {},
                              std::max(kBaselineTolerance, options_.search.certificate_tolerance));
      s.t = v.t_upper;
      s.status = v.status;
      if (options_.robust_dropout && v.worst_member >= 0) {
        s.worst_lost = s.chosen[static_cast<std::size_t>(v.worst_member)];
      }
    }
  });
  evaluations_ += static_cast<long>(searched.size());
}

RandomBaseline PlacementSearch::baseline(std::optional<Scored>* best) {
  progress("random baseline, " + std::to_string(options_.random_trials) + " subsets");
  std::vector<std::optional<Scored>> drawn = draw_baseline();
  search_baseline(&drawn);
  const Scored* top = nullptr;
  for (const std::optional<Scored>& s : drawn) {
    if (s && (top == nullptr || better_cover(*s, *top))) top = &*s;
  }
  RandomBaseline out;
  std::vector<double> pbar;
  std::vector<double> values;
  for (const std::optional<Scored>& s : drawn) {
    if (!s) continue;
    ++out.trials;
    const bool complete = s->covered >= required_;
    if (complete) ++out.complete;
    pbar.push_back(complete && affine() ? std::sqrt(std::max(0.0, 1.0 - s->t * s->t)) : 0.0);
    values.push_back(complete ? s->t : no_level());
    if (!better_cover(*top, *s) && (!*best || better(*s, **best))) *best = *s;
  }
  if (*best) {
    out.best_coverage = coverage_.directions() == 0
                            ? 0.0
                            : static_cast<double>((*best)->covered) / coverage_.directions();
    out.best_pbar_min = affine() ? std::sqrt(std::max(0.0, 1.0 - (*best)->t * (*best)->t)) : 0.0;
    out.best_objective = (*best)->t;
    out.best = (*best)->chosen;
    std::sort(pbar.begin(), pbar.end());
    std::sort(values.begin(), values.end());
    const std::size_t n = pbar.size();
    out.median_pbar_min = n % 2 == 1 ? pbar[n / 2] : 0.5 * (pbar[n / 2 - 1] + pbar[n / 2]);
    out.median_objective = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  }
  return out;
}

std::optional<int> PlacementSearch::covering_markers() {
  std::vector<int> chosen = problem_.keep;
  std::sort(chosen.begin(), chosen.end());
  const std::vector<int> free = free_sites();
  while (true) {
    const CoverageCounts counts(coverage_, chosen);
    if (counts.key().covered >= required_) return static_cast<int>(chosen.size());
    int pick = -1;
    CoverageKey top = counts.key();
    for (int c : free) {
      if (std::binary_search(chosen.begin(), chosen.end(), c)) continue;
      if (!evaluator_.feasible_with(chosen, c)) continue;
      const CoverageKey key = counts.with_added(c);
      if (top < key) {
        top = key;
        pick = c;
      }
    }
    if (pick < 0) return std::nullopt;
    chosen.insert(std::upper_bound(chosen.begin(), chosen.end(), pick), pick);
  }
}

}  // namespace vantage::design::internal
