// Theorem 6 worst viewpoint: the certified global answer (branch and bound over sign cells) against
// one CSDP solve of the paper's single LMI (Eq. 28), on m random unit vectors from a seeded engine.

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <random>

#include "vantage/sdp/worst_viewpoint.h"

namespace {

Eigen::Matrix3Xd random_unit_vectors(int m) {
  std::mt19937 rng(20061122u + static_cast<unsigned>(m));
  std::normal_distribution<double> normal;
  Eigen::Matrix3Xd z(3, m);
  for (int i = 0; i < m; ++i) {
    z.col(i) = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
  }
  return z;
}

void BM_WorstViewpoint_Global(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  long cells = 0;
  long patches = 0;
  for (auto _ : state) {
    const vantage::sdp::WorstViewpoint w = vantage::sdp::global_worst_viewpoint(z);
    benchmark::DoNotOptimize(w.t);
    cells = w.cells_solved;
    patches = w.patches;
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["patches"] = static_cast<double>(patches);
}

void BM_WorstViewpoint_PaperLmi(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const vantage::sdp::CellViewpoint paper = vantage::sdp::paper_worst_viewpoint(z);
    benchmark::DoNotOptimize(paper.t);
  }
}

// The global answer plus its confirming CSDP solve of the optimal cell (what analyze reports).
void BM_WorstViewpoint_GlobalConfirmed(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  vantage::sdp::WorstViewpointOptions options;
  options.confirm_with_sdp = true;
  for (auto _ : state) {
    const vantage::sdp::WorstViewpoint w = vantage::sdp::global_worst_viewpoint(z, options);
    benchmark::DoNotOptimize(w.t);
  }
}

// The NLopt cross-check as analyze runs it: bounded samples plus the polish of the certified
// viewpoints' cells (CrossCheckOptions defaults).
void BM_WorstViewpoint_CrossCheck(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  const vantage::sdp::WorstViewpoint w = vantage::sdp::global_worst_viewpoint(z);
  int samples = 0;
  for (auto _ : state) {
    const vantage::sdp::CrossCheck check =
        vantage::sdp::crosscheck_worst_viewpoint(z, w.t, {}, w.viewpoints);
    benchmark::DoNotOptimize(check.t);
    samples = check.samples;
  }
  state.counters["samples"] = static_cast<double>(samples);
}

}  // namespace

BENCHMARK(BM_WorstViewpoint_Global)
    ->Arg(3)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(20000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_PaperLmi)
    ->Arg(3)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(20000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_GlobalConfirmed)
    ->Arg(3)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_CrossCheck)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);
