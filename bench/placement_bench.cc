// Marker placement (docs/math.md §21) against one evaluation of its own answer in the same run:
// what choosing K of N sites costs, in evaluations of the objective (affine: a certified search;
// camera: the CRB over the lattice; tracker: the certified worst TRE). Sites on the ellipsoid of
// bench/ellipsoid_layout.h (seeded), 80-degree cones, whole sphere; with the ellipsoid's mesh
// for the greedy (its occlusion grid is cast once, outside the timing).

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <thread>

#include "ellipsoid_layout.h"
#include "placement_anneal.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"
#include "vantage/design/placement_layout.h"
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

// ---- Against a plain simulated annealing at equal wall time (docs/math.md §21, "Search") -----

// The objectives as the annealer sees them, computed here from the public searches on the chosen
// sites alone: a subset that leaves more than one workspace lattice direction untrackable scores
// above every complete one (by its uncovered fraction); a complete one scores t_upper (affine) or
// log of the worst RMS TRE bound (tracker).
constexpr double kIncomplete = 100.0;

double coverage_energy(const visibility::VisibilityProblem& problem, int samples, bool* complete) {
  const visibility::VisibilityCoverage c = visibility::visibility_coverage(problem, samples);
  const double missing = std::round((1.0 - c.trackable_fraction) * c.samples);
  *complete = missing <= 1.0;
  return kIncomplete + (1.0 - c.trackable_fraction);
}

double affine_energy(const Sites& s, const design::PlaceOptions& o,
                     const std::vector<int>& chosen) {
  const visibility::VisibilityProblem problem = answer_problem(s, chosen);
  bool complete = false;
  const double incomplete = coverage_energy(problem, o.coverage_samples, &complete);
  if (!complete) return incomplete;
  return visibility::visibility_worst_viewpoint(problem, o.search).t_upper;
}

double tracker_energy(const Sites& s, const design::PlaceOptions& o,
                      const std::vector<int>& chosen) {
  const visibility::VisibilityProblem problem = answer_problem(s, chosen);
  bool complete = false;
  const double incomplete = coverage_energy(problem, o.coverage_samples, &complete);
  if (!complete) return incomplete;
  double worst = 0.0;
  for (const Eigen::Vector3d& target : o.tracker->targets) {
    worst = std::max(worst, vantage::tracker::tre_worst(problem, target, o.tracker->fle).rms_bound);
  }
  return std::log(worst);
}

// The camera objective by `vantage crb`'s map of the chosen sites (the aim and lattice of the
// objective): 100 + the uncovered fraction when more than one lattice direction of the workspace
// sees too few markers, else log of the worst first-order rot_rms.
double camera_energy(const Sites& s, const design::PlaceOptions& o,
                     const std::vector<int>& chosen) {
  vantage::Layout answer = s.layout;
  const Eigen::Index k = static_cast<Eigen::Index>(chosen.size());
  answer.entries.resize(3, k);
  answer.weights = Eigen::VectorXd::Ones(k);
  answer.visibility->normals.resize(3, k);
  answer.visibility->cone_half_angle_deg.resize(k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const int site = chosen[static_cast<std::size_t>(j)];
    answer.entries.col(j) = s.layout.entries.col(site);
    answer.visibility->normals.col(j) = s.layout.visibility->normals.col(site);
    answer.visibility->cone_half_angle_deg(j) = s.layout.visibility->cone_half_angle_deg(site);
  }
  const vantage::camera::PoseCrbMap map =
      vantage::camera::pose_crb_map(vantage::camera::PoseCrbModel(answer, o.camera->crb));
  const double directions = static_cast<double>(map.samples.size());
  const double covered = map.trackable_fraction + map.unbounded_fraction;
  if (map.status != vantage::camera::PoseCrbMap::Status::kOk ||
      std::round((1.0 - covered) * directions) > 1.0) {
    return kIncomplete + (1.0 - covered);
  }
  return std::log(map.worst.first_order_rot_rms_deg);
}

// place_markers() on the sites, then two annealing chains (one per core, as place uses both) for
// `multiple` times its wall time, each from its own seed; counters: both energies by the function
// above, the place run's seconds and the chains' evaluations.
template <class Energy>
void against_annealing(benchmark::State& state, const Sites& s, const design::PlaceOptions& o,
                       const vantage_bench::AnnealSchedule& schedule, double multiple,
                       Energy energy) {
  double place_energy = 0.0;
  double anneal_energy = 0.0;
  double seconds = 0.0;
  long evaluations = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const design::PlacementResult r = design::place_markers(s.problem, o);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    place_energy = energy(r.chosen);
    const double budget = multiple * seconds;
    vantage_bench::AnnealResult chains[2];
    std::thread second([&] {
      vantage_bench::AnnealSchedule two = schedule;
      two.seconds = budget;
      two.seed = schedule.seed + 1;
      chains[1] = vantage_bench::anneal(static_cast<int>(s.problem.sites.points.cols()),
                                        s.problem.markers, two, energy);
    });
    vantage_bench::AnnealSchedule one = schedule;
    one.seconds = budget;
    chains[0] = vantage_bench::anneal(static_cast<int>(s.problem.sites.points.cols()),
                                      s.problem.markers, one, energy);
    second.join();
    anneal_energy = std::min(chains[0].energy, chains[1].energy);
    evaluations = chains[0].evaluations + chains[1].evaluations;
  }
  state.counters["place_energy"] = place_energy;
  state.counters["anneal_energy"] = anneal_energy;
  state.counters["place_s"] = seconds;
  state.counters["anneal_evaluations"] = static_cast<double>(evaluations);
}

// An L-shaped prism (the L of [0,2]x[0,1] and [0,1]x[0,2], height 1): a non-convex body whose
// faces shadow each other, as 20 triangles wound outward.
vantage::Mesh l_prism() {
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  vantage::Mesh mesh;
  mesh.vertices.resize(3, 12);
  for (int i = 0; i < 6; ++i) {
    mesh.vertices.col(i) = Eigen::Vector3d(xy[i][0], xy[i][1], 0.0);
    mesh.vertices.col(i + 6) = Eigen::Vector3d(xy[i][0], xy[i][1], 1.0);
  }
  std::vector<Eigen::Vector3i> triangles = {
      {0, 2, 1}, {0, 3, 2}, {0, 5, 4},   {0, 4, 3},    // bottom, facing -z
      {6, 7, 8}, {6, 8, 9}, {6, 10, 11}, {6, 9, 10}};  // top, facing +z
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    triangles.emplace_back(i, j, j + 6);
    triangles.emplace_back(i, j + 6, i + 6);
  }
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    mesh.triangles.col(static_cast<Eigen::Index>(t)) = triangles[t];
  }
  return mesh;
}

// N sites sampled on the L-shaped prism (seeded), 80-degree cones, K markers, the workspace 75
// degrees about +z.
Sites l_prism_sites(int n, int markers) {
  const vantage::Mesh mesh = l_prism();
  vantage::Layout layout =
      design::surface_sites_layout(design::sample_surface_sites(mesh, n, 0.0, 7), mesh, "l-prism");
  layout.visibility->cone_half_angle_deg.setConstant(kConeDeg);
  layout.workspace = vantage::LayoutWorkspace{Eigen::Vector3d::UnitZ(), kWorkspaceDeg};
  Sites out{layout, visibility::VisibilityModel::of(layout), {}};
  out.problem.sites = out.model.problem();
  out.problem.markers = markers;
  return out;
}

// `vantage place` (affine) against the annealer, energy t_upper, on the ellipsoid's sites
// (range(2) 0) or the L-shaped prism's (1), the annealer running range(3) times place's time,
// place with range(4) --perturbations.
void BM_Place_AffineAgainstAnnealing(benchmark::State& state) {
  const Sites s = state.range(2) == 0 ? workspace_sites(state)
                                      : l_prism_sites(static_cast<int>(state.range(0)),
                                                      static_cast<int>(state.range(1)));
  design::PlaceOptions o = options();
  o.perturbations = static_cast<int>(state.range(4));
  vantage_bench::AnnealSchedule schedule;
  schedule.start = 0.05;
  schedule.end = 0.0005;
  against_annealing(state, s, o, schedule, static_cast<double>(state.range(3)),
                    [&](const std::vector<int>& chosen) { return affine_energy(s, o, chosen); });
}

// `vantage place --objective tracker` against the annealer, energy log(worst RMS TRE).
void BM_Place_TrackerAgainstAnnealing(benchmark::State& state) {
  const Sites s = workspace_sites(state);
  const design::PlaceOptions o = tracker_options();
  vantage_bench::AnnealSchedule schedule;
  schedule.start = 0.3;
  schedule.end = 0.003;
  against_annealing(state, s, o, schedule, 1.0,
                    [&](const std::vector<int>& chosen) { return tracker_energy(s, o, chosen); });
}

// `vantage place --objective camera` against the annealer, energy log(worst rot_rms).
void BM_Place_CameraAgainstAnnealing(benchmark::State& state) {
  const Sites s = workspace_sites(state);
  const design::PlaceOptions o = camera_options(s);
  vantage_bench::AnnealSchedule schedule;
  schedule.start = 0.3;
  schedule.end = 0.003;
  against_annealing(state, s, o, schedule, 1.0,
                    [&](const std::vector<int>& chosen) { return camera_energy(s, o, chosen); });
}

BENCHMARK(BM_Place_OneSearch)->Args({200, 12})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Greedy)->Args({200, 12})->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Place_Exhaustive)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_CameraOneMap)->Args({1000, 8})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Camera)->Args({1000, 8})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Place_TrackerOneSearch)->Args({1000, 8})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Place_Tracker)->Args({1000, 8})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Place_AffineAgainstAnnealing)
    ->Args({300, 8, 0, 1, 0})
    ->Args({300, 8, 1, 1, 0})
    ->Args({300, 8, 1, 20, 0})
    ->Args({300, 8, 0, 1, 20})
    ->Args({300, 8, 1, 1, 20})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_Place_TrackerAgainstAnnealing)
    ->Args({1000, 8})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_Place_CameraAgainstAnnealing)
    ->Args({1000, 8})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
