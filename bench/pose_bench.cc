// Orthogonal iteration with the FOAM absolute-orientation step (Wu & Wu, seed 004) against the
// same iteration with the SVD step (Lu et al.), on identical seeded scenes.
//
// BM_Pose_OiFoam/n and BM_Pose_OiSvd/n: one full pose solve (weak-perspective start, iteration
// to the default thresholds) per benchmark iteration, cycling through kScenes random scenes of n
// points, noise 1e-3 in normalised coordinates. Counter "oi_steps": mean rotation steps per
// solve (identical for both, since both steps return the same rotation to rounding).
// BM_Pose_RotationStepFoam / BM_Pose_RotationStepSvd: the absolute-orientation step alone
// (vantage::optimal_rotation) on the cross-covariances such solves produce.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <random>
#include <vector>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/orthogonal_iteration.h"

namespace {

constexpr unsigned kBenchSeed = 20130604;
constexpr int kScenes = 32;

struct Scene {
  Eigen::Matrix3Xd model;
  Eigen::Matrix2Xd image;
};

/// Seed 004's setting: points in a cube, random rotation, object ahead of the camera.
std::vector<Scene> make_scenes(int n) {
  std::mt19937 rng(kBenchSeed + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> depth(4.0, 8.0);
  std::normal_distribution<double> normal;
  std::normal_distribution<double> noise(0.0, 1e-3);
  std::vector<Scene> scenes(kScenes);
  for (Scene& s : scenes) {
    const Eigen::Matrix3d R = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
                                  .normalized()
                                  .toRotationMatrix();
    const Eigen::Vector3d p(0.5 * unit(rng), 0.5 * unit(rng), depth(rng));
    s.model.resize(3, n);
    s.image.resize(2, n);
    for (int i = 0; i < n; ++i) {
      s.model.col(i) = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      const Eigen::Vector3d x = R * s.model.col(i) + p;
      s.image.col(i) = x.head<2>() / x.z() + Eigen::Vector2d(noise(rng), noise(rng));
    }
  }
  return scenes;
}

void run_oi(benchmark::State& state, vantage::OrientationMethod step) {
  const std::vector<Scene> scenes = make_scenes(static_cast<int>(state.range(0)));
  vantage::OrthogonalIterationOptions options;
  options.rotation_step = step;
  std::size_t k = 0;
  double steps = 0.0;
  double solves = 0.0;
  for (auto _ : state) {
    const Scene& s = scenes[k++ % scenes.size()];
    const vantage::OrthogonalIterationResult result =
        vantage::orthogonal_iteration_pose(s.model, s.image, {}, options);
    benchmark::DoNotOptimize(result.R_camera_object.data());
    steps += result.iterations;
    solves += 1.0;
  }
  state.counters["oi_steps"] = steps / std::max(solves, 1.0);
}

void BM_Pose_OiFoam(benchmark::State& state) { run_oi(state, vantage::OrientationMethod::kFoam); }
void BM_Pose_OiSvd(benchmark::State& state) { run_oi(state, vantage::OrientationMethod::kSvd); }

BENCHMARK(BM_Pose_OiFoam)->Arg(4)->Arg(10)->Arg(30);
BENCHMARK(BM_Pose_OiSvd)->Arg(4)->Arg(10)->Arg(30);

/// The cross-covariances H = sum (x_i - x_bar) q_i^T that the last OI step of each n = 10 scene
/// works on (q_i = V_i (R x_i + p) at the converged pose), so the step is timed on real input.
std::vector<Eigen::Matrix3d> make_covariances() {
  std::vector<Eigen::Matrix3d> hs;
  for (const Scene& s : make_scenes(10)) {
    const vantage::OrthogonalIterationResult pose =
        vantage::orthogonal_iteration_pose(s.model, s.image);
    const Eigen::Vector3d mean = s.model.rowwise().mean();
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (Eigen::Index i = 0; i < s.model.cols(); ++i) {
      const Eigen::Vector3d m(s.image(0, i), s.image(1, i), 1.0);
      const Eigen::Vector3d x = pose.R_camera_object * s.model.col(i) + pose.p_camera_object;
      H += (s.model.col(i) - mean) * (m * (m.dot(x) / m.squaredNorm())).transpose();
    }
    hs.push_back(H);
  }
  return hs;
}

void run_step(benchmark::State& state, vantage::OrientationMethod method) {
  const std::vector<Eigen::Matrix3d> hs = make_covariances();
  vantage::OrientationOptions options;
  options.method = method;
  std::size_t k = 0;
  for (auto _ : state) {
    const Eigen::Matrix3d R = vantage::optimal_rotation(hs[k++ % hs.size()], options);
    benchmark::DoNotOptimize(R.data());
  }
}

void BM_Pose_RotationStepFoam(benchmark::State& state) {
  run_step(state, vantage::OrientationMethod::kFoam);
}
void BM_Pose_RotationStepSvd(benchmark::State& state) {
  run_step(state, vantage::OrientationMethod::kSvd);
}

BENCHMARK(BM_Pose_RotationStepFoam);
BENCHMARK(BM_Pose_RotationStepSvd);

}  // namespace
