// The worst viewpoint of markers on a body (docs/math.md §20) beside the same markers seen whole
// (§14) in the same run: what visibility costs. Markers on an ellipsoid of half-axes (2, 1.5, 1)
// with its outward normals and 60-degree cones, from a seeded engine; with a mesh, the ellipsoid
// as about 5000 triangles (the occlusion grid is cast at the default 1 degree in each run).

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "ellipsoid_layout.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/visibility_model.h"

namespace {

using vantage_bench::ellipsoid_layout;

// The baseline: the same markers seen whole, §14's certified search on their free vectors.
void BM_WorstViewpoint_VisibilityBaseline(benchmark::State& state) {
  const vantage::Layout layout = ellipsoid_layout(static_cast<int>(state.range(0)), false);
  const Eigen::Matrix3Xd z = vantage::data_vectors(layout).vectors;
  for (auto _ : state) {
    const vantage::sdp::WorstViewpoint w = vantage::sdp::global_worst_viewpoint(z);
    benchmark::DoNotOptimize(w.t);
  }
  state.counters["vectors"] = static_cast<double>(z.cols());
}

// Cone model: the certified worst viewpoint over the trackable directions.
void BM_WorstViewpoint_Visibility(benchmark::State& state) {
  const vantage::Layout layout = ellipsoid_layout(static_cast<int>(state.range(0)), false);
  const vantage::visibility::VisibilityModel model =
      vantage::visibility::VisibilityModel::of(layout);
  long patches = 0;
  bool certified = false;
  for (auto _ : state) {
    const vantage::visibility::VisibilityWorstViewpoint w =
        vantage::visibility::visibility_worst_viewpoint(model.problem());
    benchmark::DoNotOptimize(w.t);
    patches = w.patches;
    certified = w.certified();
  }
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["certified"] = certified ? 1.0 : 0.0;
}

// Cone and mesh: the occlusion grid cast on the 5040-triangle ellipsoid (Embree, 2 threads),
// then the search.
void BM_WorstViewpoint_VisibilityMesh(benchmark::State& state) {
  const vantage::Layout layout = ellipsoid_layout(static_cast<int>(state.range(0)), true);
  long patches = 0;
  bool certified = false;
  for (auto _ : state) {
    const vantage::visibility::VisibilityModel model =
        vantage::visibility::VisibilityModel::of(layout);
    const vantage::visibility::VisibilityWorstViewpoint w =
        vantage::visibility::visibility_worst_viewpoint(model.problem());
    benchmark::DoNotOptimize(w.t);
    patches = w.patches;
    certified = w.certified();
  }
  state.counters["triangles"] = static_cast<double>(layout.visibility->body->triangles.cols());
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["certified"] = certified ? 1.0 : 0.0;
}

}  // namespace

BENCHMARK(BM_WorstViewpoint_VisibilityBaseline)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WorstViewpoint_Visibility)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WorstViewpoint_VisibilityMesh)->Arg(30)->Unit(benchmark::kMillisecond)->UseRealTime();
