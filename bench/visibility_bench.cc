// The worst viewpoint of markers on a body (docs/math.md §20) beside the same markers seen whole
// (§14) in the same run: what visibility costs. Markers on an ellipsoid of half-axes (2, 1.5, 1)
// with its outward normals and 60-degree cones, from a seeded engine; with a mesh, the ellipsoid
// as about 5000 triangles (the occlusion grid is cast at the default 1 degree in each run).

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "vantage/analysis/common.h"
#include "vantage/analysis/layout.h"
#include "vantage/sdp/visibility.h"
#include "vantage/sdp/visibility_model.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace {

const Eigen::Vector3d kHalfAxes(2.0, 1.5, 1.0);
constexpr double kConeDeg = 60.0;
// Ellipsoid mesh: latitude bands x longitude steps (2 x 36 x 70 = 5040 triangles).
constexpr int kStacks = 36;
constexpr int kSlices = 70;

Eigen::Vector3d on_ellipsoid(double polar, double azimuth) {
  return Eigen::Vector3d(kHalfAxes.x() * std::sin(polar) * std::cos(azimuth),
                         kHalfAxes.y() * std::sin(polar) * std::sin(azimuth),
                         kHalfAxes.z() * std::cos(polar));
}

// n markers on the ellipsoid, normals its gradient, kConeDeg cones; with_body: the mesh too.
vantage::Layout ellipsoid_layout(int n, bool with_body) {
  std::mt19937 rng(20261202u + static_cast<unsigned>(n));
  std::normal_distribution<double> normal;
  vantage::Layout layout;
  layout.mode = vantage::LayoutMode::kPoints;
  layout.entries.resize(3, n);
  vantage::MarkerVisibility v;
  v.normals.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const Eigen::Vector3d p = d.cwiseProduct(kHalfAxes);
    layout.entries.col(i) = p;
    v.normals.col(i) = p.cwiseQuotient(kHalfAxes.cwiseProduct(kHalfAxes)).normalized();
  }
  layout.weights = Eigen::VectorXd::Ones(n);
  v.cone_half_angle_deg = Eigen::VectorXd::Constant(n, kConeDeg);
  if (with_body) {
    vantage::Mesh mesh;
    mesh.vertices.resize(3, 2 + (kStacks - 1) * kSlices);
    mesh.vertices.col(0) = on_ellipsoid(0.0, 0.0);
    mesh.vertices.col(1) = on_ellipsoid(vantage::kPi, 0.0);
    for (int s = 1; s < kStacks; ++s) {
      for (int k = 0; k < kSlices; ++k) {
        mesh.vertices.col(2 + (s - 1) * kSlices + k) =
            on_ellipsoid(vantage::kPi * s / kStacks, 2 * vantage::kPi * k / kSlices);
      }
    }
    auto ring = [](int s, int k) { return 2 + (s - 1) * kSlices + (k % kSlices); };
    std::vector<Eigen::Vector3i> triangles;
    for (int k = 0; k < kSlices; ++k) {
      triangles.emplace_back(0, ring(1, k), ring(1, k + 1));
      triangles.emplace_back(1, ring(kStacks - 1, k + 1), ring(kStacks - 1, k));
      for (int s = 1; s + 1 < kStacks; ++s) {
        triangles.emplace_back(ring(s, k), ring(s + 1, k), ring(s + 1, k + 1));
        triangles.emplace_back(ring(s, k), ring(s + 1, k + 1), ring(s, k + 1));
      }
    }
    mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      mesh.triangles.col(static_cast<Eigen::Index>(t)) = triangles[t];
    }
    v.body = mesh;
    v.body_path = "ellipsoid";
  }
  layout.visibility = v;
  return layout;
}

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
  const vantage::sdp::VisibilityModel model = vantage::sdp::VisibilityModel::of(layout);
  long patches = 0;
  bool certified = false;
  for (auto _ : state) {
    const vantage::sdp::VisibilityWorstViewpoint w =
        vantage::sdp::visibility_worst_viewpoint(model.problem());
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
    const vantage::sdp::VisibilityModel model = vantage::sdp::VisibilityModel::of(layout);
    const vantage::sdp::VisibilityWorstViewpoint w =
        vantage::sdp::visibility_worst_viewpoint(model.problem());
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
