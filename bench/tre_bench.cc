// The target registration error (docs/math.md §23) of a 10-marker tool with normals: the certified
// worst and best over the tracked directions (the issue asks for at most 50 ms) and 10^5 Monte
// Carlo trials (at most 2 s). Baseline in the same run: one first-order evaluation at a direction.

#include <benchmark/benchmark.h>

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/tracker/tre_search.h"
#include "vantage/visibility/visibility.h"

namespace {

// Ten markers on a dome of radius 40 mm (golden-angle spiral over the upper 3/4 of the sphere),
// facing outward with 75-degree cones, at least 4 visible; the tip 150 mm below.
vantage::visibility::VisibilityProblem tre_bench_tool() {
  constexpr int kMarkers = 10;
  vantage::visibility::VisibilityProblem problem;
  problem.points.resize(3, kMarkers);
  problem.normals.resize(3, kMarkers);
  for (int i = 0; i < kMarkers; ++i) {
    const double z = 1.0 - 1.5 * (i + 0.5) / kMarkers;
    const double rho = std::sqrt(1.0 - z * z);
    const double phi = 2.399963229728653 * i;
    const Eigen::Vector3d n(rho * std::cos(phi), rho * std::sin(phi), z);
    problem.normals.col(i) = n;
    problem.points.col(i) = 40.0 * n;
  }
  problem.cos_cone = Eigen::VectorXd::Constant(kMarkers, std::cos(75.0 * vantage::kPi / 180.0));
  problem.min_visible = 4;
  return problem;
}

const Eigen::Vector3d kTip(0.0, 0.0, -150.0);
const vantage::tracker::FleModel kNdiFle{0.0995, 0.2985};

void BM_Tre_AtDirection(benchmark::State& state) {
  const vantage::visibility::VisibilityProblem problem = tre_bench_tool();
  const Eigen::Vector3d a = Eigen::Vector3d(0.2, 0.3, 0.9).normalized();
  for (auto _ : state) {
    const vantage::visibility::DirectionVisibility seen =
        vantage::visibility::direction_visibility(problem, a);
    benchmark::DoNotOptimize(
        vantage::tracker::tre_covariance(problem.points, seen.visible, kTip, kNdiFle, a));
  }
}
BENCHMARK(BM_Tre_AtDirection)->Unit(benchmark::kMicrosecond);

void BM_Tre_Worst(benchmark::State& state) {
  const vantage::visibility::VisibilityProblem problem = tre_bench_tool();
  long patches = 0;
  bool certified = true;
  for (auto _ : state) {
    const vantage::tracker::TreExtremes e = vantage::tracker::tre_extremes(problem, kTip, kNdiFle);
    patches = e.worst.patches + e.best.patches;
    certified = certified && e.worst.certified() && e.best.certified();
    benchmark::DoNotOptimize(e);
  }
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["certified"] = certified ? 1.0 : 0.0;
}
BENCHMARK(BM_Tre_Worst)->Unit(benchmark::kMillisecond);

void BM_Tre_MonteCarlo(benchmark::State& state) {
  const vantage::visibility::VisibilityProblem problem = tre_bench_tool();
  const Eigen::Vector3d a = Eigen::Vector3d(0.2, 0.3, 0.9).normalized();
  const vantage::visibility::DirectionVisibility seen =
      vantage::visibility::direction_visibility(problem, a);
  for (auto _ : state) {
    benchmark::DoNotOptimize(vantage::tracker::tre_monte_carlo(problem.points, seen.visible, kTip,
                                                               kNdiFle, a, 100000, 1, 1));
  }
}
BENCHMARK(BM_Tre_MonteCarlo)->Unit(benchmark::kMillisecond);

}  // namespace
