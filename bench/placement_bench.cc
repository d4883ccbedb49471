// Marker placement (docs/math.md §21) against one certified search of its own answer in the same
// run: what choosing K of N sites costs, in searches. Sites on the ellipsoid of
// bench/ellipsoid_layout.h (seeded), 80-degree cones, whole sphere; with the ellipsoid's mesh
// for the greedy (its occlusion grid is cast once, outside the timing).

#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include "ellipsoid_layout.h"
#include "vantage/design/placement.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/visibility_model.h"

namespace {

using vantage_bench::ellipsoid_layout;
namespace design = vantage::design;
namespace visibility = vantage::visibility;

constexpr double kConeDeg = 80.0;
constexpr int kRandomTrials = 100;

struct Sites {
  vantage::Layout layout;
  visibility::VisibilityModel model;
  design::PlacementProblem problem;
};

Sites sites(int n, bool with_body, int markers) {
  vantage::Layout layout = ellipsoid_layout(n, with_body);
  layout.visibility->cone_half_angle_deg.setConstant(kConeDeg);
  Sites out{layout, visibility::VisibilityModel::of(layout), {}};
  out.problem.sites = out.model.problem();
  out.problem.markers = markers;
  return out;
}

design::PlaceOptions options() {
  design::PlaceOptions o;
  o.random_trials = kRandomTrials;
  return o;
}

// The baseline: one certified search of the answer of BM_Place_Greedy.
void BM_Place_OneSearch(benchmark::State& state) {
  const Sites s = sites(static_cast<int>(state.range(0)), true, static_cast<int>(state.range(1)));
  const design::PlacementResult answer = design::place_markers(s.problem, options());
  visibility::VisibilityProblem problem = s.problem.sites;
  const Eigen::Index k = static_cast<Eigen::Index>(answer.chosen.size());
  problem.points.resize(3, k);
  problem.normals.resize(3, k);
  problem.cos_cone.resize(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int site = answer.chosen[static_cast<std::size_t>(j)];
    problem.points.col(j) = s.problem.sites.points.col(site);
    problem.normals.col(j) = s.problem.sites.normals.col(site);
    problem.cos_cone(j) = s.problem.sites.cos_cone(site);
    problem.occlusion_markers.push_back(s.problem.sites.occlusion_marker(site));
  }
  for (auto _ : state) {
    const visibility::VisibilityWorstViewpoint w = visibility::visibility_worst_viewpoint(problem);
    benchmark::DoNotOptimize(w.t);
  }
}

// Greedy with swaps, the random baseline included.
void BM_Place_Greedy(benchmark::State& state) {
  const Sites s = sites(static_cast<int>(state.range(0)), true, static_cast<int>(state.range(1)));
  long evaluations = 0;
  double coverage = 0.0;
  for (auto _ : state) {
    const design::PlacementResult r = design::place_markers(s.problem, options());
    benchmark::DoNotOptimize(r.value.t_upper);
    evaluations = r.evaluations;
    coverage = r.value.coverage;
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["coverage"] = coverage;
}

// Every subset of 16 sites, K = 4 (1820 subsets), without a body.
void BM_Place_Exhaustive(benchmark::State& state) {
  const Sites s = sites(16, false, 4);
  long subsets = 0;
  for (auto _ : state) {
    const design::PlacementResult r = design::place_markers(s.problem, options());
    benchmark::DoNotOptimize(r.value.t_upper);
    subsets = r.subsets;
  }
  state.counters["subsets"] = static_cast<double>(subsets);
}

BENCHMARK(BM_Place_OneSearch)->Args({200, 12})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Greedy)->Args({200, 12})->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Place_Exhaustive)->Unit(benchmark::kMillisecond);

}  // namespace
