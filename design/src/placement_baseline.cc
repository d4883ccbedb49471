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

}  // namespace

RandomBaseline PlacementSearch::baseline(std::optional<Scored>* best) {
  const std::vector<int> free = free_sites();
  const int k = problem_.markers - static_cast<int>(problem_.keep.size());
  const int trials = options_.random_trials;
  std::vector<std::optional<Scored>> drawn(static_cast<std::size_t>(trials));
  progress("random baseline, " + std::to_string(trials) + " subsets");
  // Each trial has its own engine and is scored on its own (no level, no witnesses), so the
  // baseline does not depend on the threads.
  parallel_blocks(trials, options_.threads, [&](long b, long e) {
    for (long trial = b; trial < e; ++trial) {
      PlacementRandom random = PlacementRandom::for_draw(options_.seed, static_cast<std::uint64_t>(trial));
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
        s.cover = coverage_.key(chosen);
        s.robust_cover = robust_cover(chosen);
        const FamilyValue v = evaluator_.family_t(family(chosen), 2.0, {});
        s.t = v.t_upper;
        s.status = v.status;
        if (options_.robust_dropout && v.worst_member >= 0) {
          s.worst_lost = chosen[static_cast<std::size_t>(v.worst_member)];
        }
        drawn[static_cast<std::size_t>(trial)] = std::move(s);
        break;
      }
    }
  });
  RandomBaseline out;
  std::vector<double> pbar;
  for (const std::optional<Scored>& s : drawn) {
    if (!s) continue;
    ++out.trials;
    if (s->cover.covered == coverage_.directions()) ++out.complete;
    pbar.push_back(std::sqrt(std::max(0.0, 1.0 - s->t * s->t)));
    if (!*best || better(*s, **best)) *best = *s;
  }
  if (*best) {
    out.best_coverage = coverage_.directions() == 0 ? 0.0
                                                    : static_cast<double>((*best)->cover.covered) /
                                                          coverage_.directions();
    out.best_pbar_min = std::sqrt(std::max(0.0, 1.0 - (*best)->t * (*best)->t));
    out.best = (*best)->chosen;
    std::sort(pbar.begin(), pbar.end());
    const std::size_t n = pbar.size();
    out.median_pbar_min = n % 2 == 1 ? pbar[n / 2] : 0.5 * (pbar[n / 2 - 1] + pbar[n / 2]);
  }
  return out;
}

std::optional<int> PlacementSearch::covering_markers() {
  std::vector<int> chosen = problem_.keep;
  std::sort(chosen.begin(), chosen.end());
  const std::vector<int> free = free_sites();
  while (true) {
    const CoverageCounts counts(coverage_, chosen);
    if (counts.key().covered == coverage_.directions()) return static_cast<int>(chosen.size());
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
