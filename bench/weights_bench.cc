// Max-min weights of Eq. (11) (design/weights.h): the dual active-set LP against the CSDP primal
// it replaced as the default, on the same seeded layouts (n Gaussian vectors shifted by 0.2 along
// x, so strictly positive weights exist and the LP is not trivial).

#include <benchmark/benchmark.h>

#include <random>

#include "vantage/design/weights.h"

namespace {

Eigen::Matrix3Xd shifted_gaussian(int n) {
  std::mt19937 rng(20261126);
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::Matrix3Xd z(3, n);
  for (int i = 0; i < n; ++i) z.col(i) << gauss(rng) + 0.2, gauss(rng), gauss(rng);
  return z;
}

void run(benchmark::State& state, vantage::design::WeightsOptions::Solver solver) {
  const Eigen::Matrix3Xd z = shifted_gaussian(static_cast<int>(state.range(0)));
  vantage::design::WeightsOptions options;
  options.solver = solver;
  options.suggest = false;
  for (auto _ : state) {
    const vantage::design::Weights w = vantage::design::nullspace_weights(z, options);
    benchmark::DoNotOptimize(w.min_weight);
  }
  state.SetComplexityN(state.range(0));
}

void BM_Weights_DualActiveSet(benchmark::State& state) {
  run(state, vantage::design::WeightsOptions::Solver::kDualActiveSet);
}
void BM_Weights_Csdp(benchmark::State& state) {
  run(state, vantage::design::WeightsOptions::Solver::kCsdp);
}

BENCHMARK(BM_Weights_DualActiveSet)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Weights_Csdp)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
