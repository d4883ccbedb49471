// Marker placement (docs/math.md §21) against one evaluation of its own answer in the same run:
// what choosing K of N sites costs, in evaluations of the objective (affine: a certified search;
// camera: the CRB over the lattice; tracker: the certified worst TRE). Sites on the ellipsoid of
// bench/ellipsoid_layout.h (seeded), 80-degree cones, whole sphere; with the ellipsoid's mesh
// for the greedy (its occlusion grid is cast once, outside the timing).

#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include "ellipsoid_layout.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"
#include "vantage/tracker/tre_search.h"
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

// The answer of a placement as its own problem (the chosen sites, their grid rows).
visibility::VisibilityProblem answer_problem(const Sites& s, const std::vector<int>& chosen) {
  visibility::VisibilityProblem problem = s.problem.sites;
  const Eigen::Index k = static_cast<Eigen::Index>(chosen.size());
  problem.points.resize(3, k);
  problem.normals.resize(3, k);
  problem.cos_cone.resize(k);
  problem.occlusion_markers.clear();
  for (Eigen::Index j = 0; j < k; ++j) {
    const int site = chosen[static_cast<std::size_t>(j)];
    problem.points.col(j) = s.problem.sites.points.col(site);
    problem.normals.col(j) = s.problem.sites.normals.col(site);
    problem.cos_cone(j) = s.problem.sites.cos_cone(site);
    problem.occlusion_markers.push_back(s.problem.sites.occlusion_marker(site));
  }
  return problem;
}

// The baseline: one certified search of the answer of BM_Place_Greedy.
void BM_Place_OneSearch(benchmark::State& state) {
  const Sites s = sites(static_cast<int>(state.range(0)), true, static_cast<int>(state.range(1)));
  const design::PlacementResult answer = design::place_markers(s.problem, options());
  const visibility::VisibilityProblem problem = answer_problem(s, answer.chosen);
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

// The exact objectives on N sites of the ellipsoid with its mesh, K markers, the workspace 75 deg
// about +z (a body seen from above).
constexpr double kWorkspaceDeg = 75.0;
constexpr int kCrbSamples = 2000;

Sites workspace_sites(int n, int markers) {
  vantage::Layout layout = ellipsoid_layout(n, true);
  layout.visibility->cone_half_angle_deg.setConstant(kConeDeg);
  layout.workspace = vantage::LayoutWorkspace{Eigen::Vector3d::UnitZ(), kWorkspaceDeg};
  Sites out{layout, visibility::VisibilityModel::of(layout), {}};
  out.problem.sites = out.model.problem();
  out.problem.markers = markers;
  return out;
}

design::PlaceOptions camera_options(const Sites& s) {
  design::PlaceOptions o = options();
  design::CameraObjective camera;
  camera.sites = s.layout;
  camera.crb.distance = 10.0;
  camera.crb.focal_length = 1000.0;
  camera.crb.noise_px = 0.2;
  camera.crb.samples = kCrbSamples;
  camera.crb.aim = Eigen::Vector3d::Zero();
  o.camera = camera;
  return o;
}

design::PlaceOptions tracker_options() {
  design::PlaceOptions o = options();
  design::TrackerObjective tracker;
  tracker.targets = {Eigen::Vector3d(0.0, 0.0, -3.0)};
  tracker.fle = vantage::tracker::FleModel::isotropic(0.25);
  o.tracker = tracker;
  return o;
}

// One placement (greedy and swaps) over N sites with the objective of `o`; `counter` names its
// value.
void run_placement(benchmark::State& state, const Sites& s, const design::PlaceOptions& o,
                   const char* counter) {
  double value = 0.0;
  long evaluations = 0;
  for (auto _ : state) {
    const design::PlacementResult r = design::place_markers(s.problem, o);
    value = r.value.objective;
    evaluations = r.evaluations;
  }
  state.counters[counter] = value;
  state.counters["evaluations"] = static_cast<double>(evaluations);
}

Sites workspace_sites(const benchmark::State& state) {
  return workspace_sites(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
}

// `vantage place --objective camera`.
void BM_Place_Camera(benchmark::State& state) {
  const Sites s = workspace_sites(state);
  run_placement(state, s, camera_options(s), "rot_rms_deg");
}

// Its baseline: `vantage crb`'s map of K of the same sites (the first K; the objective of one
// layout, as crb runs it).
void BM_Place_CameraOneMap(benchmark::State& state) {
  const Sites s = workspace_sites(state);
  const design::PlaceOptions o = camera_options(s);
  vantage::Layout answer = s.layout;
  const int k = static_cast<int>(state.range(1));
  answer.entries = s.layout.entries.leftCols(k);
  answer.weights = Eigen::VectorXd::Ones(k);
  answer.visibility->normals = s.layout.visibility->normals.leftCols(k);
  answer.visibility->cone_half_angle_deg = s.layout.visibility->cone_half_angle_deg.head(k);
  const vantage::camera::PoseCrbModel model(answer, o.camera->crb);
  for (auto _ : state) {
    const vantage::camera::PoseCrbMap map = vantage::camera::pose_crb_map(model);
    benchmark::DoNotOptimize(map.trackable_fraction);
  }
}

// `vantage place --objective tracker`.
void BM_Place_Tracker(benchmark::State& state) {
  run_placement(state, workspace_sites(state), tracker_options(), "rms_tre");
}

// Its baseline: one certified worst TRE of the tracker placement's answer.
void BM_Place_TrackerOneSearch(benchmark::State& state) {
  const Sites s = workspace_sites(state);
  const design::PlaceOptions o = tracker_options();
  const design::PlacementResult answer = design::place_markers(s.problem, o);
  const visibility::VisibilityProblem problem = answer_problem(s, answer.chosen);
  for (auto _ : state) {
    const vantage::tracker::TreExtreme w =
        vantage::tracker::tre_worst(problem, o.tracker->targets.front(), o.tracker->fle);
    benchmark::DoNotOptimize(w.rms_bound);
  }
}

BENCHMARK(BM_Place_OneSearch)->Args({200, 12})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Greedy)->Args({200, 12})->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Place_Exhaustive)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_CameraOneMap)->Args({1000, 8})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Camera)->Args({1000, 8})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Place_TrackerOneSearch)->Args({1000, 8})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Tracker)->Args({1000, 8})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
