#pragma once

// A plain simulated annealing over K-subsets of N sites: the baseline that place_markers()'s
// search must match at equal wall time (docs/math.md §21, "Search"). Written apart from the
// library: it sees the objective only through a function of the chosen sites.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace vantage_bench {

struct AnnealResult {
  double energy = std::numeric_limits<double>::infinity();
  std::vector<int> chosen;  ///< increasing
  long evaluations = 0;
};

struct AnnealSchedule {
  double seconds = 1.0;    ///< wall time of the run
  double start = 0.05;     ///< temperature at the start, in units of the energy
  double end = 0.0005;     ///< temperature at the end; geometric in elapsed time between
  std::uint64_t seed = 1;  ///< the engine of the first subset, the moves and the acceptance
};

// Starts from a uniformly random K-subset; a move replaces one chosen site by one unchosen site,
// both uniform; Metropolis acceptance at a temperature falling geometrically with the elapsed
// wall time. `energy(chosen)` (chosen increasing) is smaller for better subsets; +inf allowed.
template <class Energy>
AnnealResult anneal(int sites, int markers, const AnnealSchedule& schedule, Energy energy) {
  std::mt19937_64 engine(schedule.seed);
  std::vector<int> order(static_cast<std::size_t>(sites));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), engine);
  std::vector<int> in(order.begin(), order.begin() + markers);
  std::vector<int> out(order.begin() + markers, order.end());
  auto sorted = [](std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  AnnealResult best;
  double current = energy(sorted(in));
  best = {current, sorted(in), 1};
  if (out.empty()) return best;
  std::uniform_int_distribution<std::size_t> pick_in(0, in.size() - 1);
  std::uniform_int_distribution<std::size_t> pick_out(0, out.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed >= schedule.seconds) break;
    const double temperature =
        schedule.start * std::pow(schedule.end / schedule.start, elapsed / schedule.seconds);
    const std::size_t i = pick_in(engine);
    const std::size_t j = pick_out(engine);
    std::swap(in[i], out[j]);
    const double candidate = energy(sorted(in));
    ++best.evaluations;
    const double rise = candidate - current;
    const bool accept = candidate <= current ||
                        (std::isfinite(rise) && unit(engine) < std::exp(-rise / temperature));
    if (accept) {
      current = candidate;
      if (current < best.energy) {
        best.energy = current;
        best.chosen = sorted(in);
      }
    } else {
      std::swap(in[i], out[j]);
    }
  }
  return best;
}

}  // namespace vantage_bench
