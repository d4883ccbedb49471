// Theorem 6 worst viewpoint: the certified global answer (branch and bound over sign cells) against
// one CSDP solve of the paper's single LMI (Eq. 28), on m random unit vectors from a seeded engine.

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <random>

#include "vantage/sdp/layout_analysis.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/sdp/worst_viewpoint_additions.h"

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

// The certified global search with default options (two threads from m = 2000 on: timed in wall
// time, see UseRealTime below), and on one thread (the same result and patches).
void global_search(benchmark::State& state, int threads) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  vantage::sdp::WorstViewpointOptions options;
  options.threads = threads;
  long cells = 0;
  long patches = 0;
  for (auto _ : state) {
    const vantage::sdp::WorstViewpoint w = vantage::sdp::global_worst_viewpoint(z, options);
    benchmark::DoNotOptimize(w.t);
    cells = w.cells_solved;
    patches = w.patches;
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["patches"] = static_cast<double>(patches);
}

void BM_WorstViewpoint_Global(benchmark::State& state) { global_search(state, 2); }
void BM_WorstViewpoint_GlobalOneThread(benchmark::State& state) { global_search(state, 1); }

// The baseline of the global search: one CSDP solve of the paper's single LMI on all m vectors.
void BM_WorstViewpoint_PaperLmi(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  const Eigen::Matrix3Xd p = z * vantage::sdp::paper_signs(z).asDiagonal();
  for (auto _ : state) {
    const vantage::sdp::SdpResult whole =
        vantage::sdp::solve_lmi(vantage::sdp::cell_lmi_problem(p));
    benchmark::DoNotOptimize(whole.y);
  }
}

// The same LMI as paper_worst_viewpoint() solves it: constraint generation from the cell's
// minimum-norm direction, each answer checked against all m vectors.
void BM_WorstViewpoint_PaperLmiGenerated(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  int solves = 0;
  int vectors = 0;
  for (auto _ : state) {
    const vantage::sdp::CellViewpoint paper = vantage::sdp::paper_worst_viewpoint(z);
    benchmark::DoNotOptimize(paper.t);
    solves = paper.lmi_solves;
    vectors = paper.lmi_vectors;
  }
  state.counters["lmi_solves"] = solves;
  state.counters["lmi_vectors"] = vectors;
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

// What `vantage analyze` computes (analyze_vectors with default options): the global search with
// its confirming cell LMI, the paper's single LMI, the NLopt cross-check and the swap analysis.
void BM_WorstViewpoint_Analyze(benchmark::State& state) {
  const Eigen::Matrix3Xd z = random_unit_vectors(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const vantage::sdp::LayoutAnalysis report = vantage::sdp::analyze_vectors(z);
    benchmark::DoNotOptimize(report.t);
  }
}

// The augmenter's inner solve: m random directions plus 50 more (another seed), solved whole
// (AddedWhole) or from the base's frontier prepared once at 0.7 t*_base (AddedPrepared, the
// design module's level; the preparation is reported as a counter, not timed per solve).
Eigen::Matrix3Xd fifty_added() { return 2.0 * random_unit_vectors(50); }

void BM_WorstViewpoint_AddedWhole(benchmark::State& state) {
  const Eigen::Matrix3Xd base = random_unit_vectors(static_cast<int>(state.range(0)));
  Eigen::Matrix3Xd all(3, base.cols() + 50);
  all << base, fifty_added();
  for (auto _ : state) benchmark::DoNotOptimize(vantage::sdp::global_worst_viewpoint(all).t);
}

void BM_WorstViewpoint_AddedPrepared(benchmark::State& state) {
  const Eigen::Matrix3Xd base = random_unit_vectors(static_cast<int>(state.range(0)));
  const Eigen::Matrix3Xd added = fifty_added();
  const double t_base = vantage::sdp::global_worst_viewpoint(base).t;
  vantage::sdp::WorstViewpointWithAdditions prepared(base, 0.7 * t_base);
  for (auto _ : state) benchmark::DoNotOptimize(prepared.solve(added).t);
  state.counters["frontier"] = static_cast<double>(prepared.frontier_patches());
  state.counters["fallbacks"] = static_cast<double>(prepared.fallbacks());
}

}  // namespace

BENCHMARK(BM_WorstViewpoint_AddedWhole)->Arg(1000)->Arg(5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_AddedPrepared)->Arg(1000)->Arg(5000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_Global)
    ->Arg(3)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(20000)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(BM_WorstViewpoint_GlobalOneThread)
    ->Arg(5000)
    ->Arg(20000)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();
BENCHMARK(BM_WorstViewpoint_PaperLmi)
    ->Arg(3)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(20000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_PaperLmiGenerated)
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
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_CrossCheck)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_WorstViewpoint_Analyze)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Arg(20000)
    ->Unit(benchmark::kMillisecond);
