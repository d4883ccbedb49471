// A tool fleet's identification (docs/math.md §24; issue 37 asks for 54 tools in under a second):
// every pair and each tool relabelled, with verdicts, for 54 four- to six-marker tools in a
// 100 mm cube, each seen in views of its own minimum (3 or 4). Baseline in the same run: the
// same fleet with one k = 3 for every tool (the former default, whose views are the cheapest).

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "vantage/tracker/tool_match.h"

namespace {

constexpr int kFleet = 54;

std::vector<Eigen::Matrix3Xd> fleet(std::vector<int>* own) {
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  std::vector<Eigen::Matrix3Xd> tools;
  for (int t = 0; t < kFleet; ++t) {
    const int markers = 4 + t % 3;
    Eigen::Matrix3Xd p(3, markers);
    for (Eigen::Index i = 0; i < p.size(); ++i) p.data()[i] = coordinate(rng);
    tools.push_back(p);
    own->push_back(3 + t % 2);
  }
  return tools;
}

void BM_IdentFleet_OwnMinimum(benchmark::State& state) {
  std::vector<int> own;
  const std::vector<Eigen::Matrix3Xd> tools = fleet(&own);
  for (auto _ : state) {
    benchmark::DoNotOptimize(vantage::tracker::match_tool_library(tools, {}, own));
  }
}
BENCHMARK(BM_IdentFleet_OwnMinimum)->Unit(benchmark::kMillisecond);

void BM_IdentFleet_Baseline_K3(benchmark::State& state) {
  std::vector<int> own;
  const std::vector<Eigen::Matrix3Xd> tools = fleet(&own);
  for (auto _ : state) benchmark::DoNotOptimize(vantage::tracker::match_tool_library(tools));
}
BENCHMARK(BM_IdentFleet_Baseline_K3)->Unit(benchmark::kMillisecond);

}  // namespace
