// Orthogonal iteration with the FOAM absolute-orientation step (Wu & Wu [W]) against the
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
#include <cmath>
#include <random>
#include <vector>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/refined_pose.h"

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
  options.camera.focal_length = 1.0;  // normalised coordinates
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
  vantage::OrthogonalIterationOptions options;
  options.camera.focal_length = 1.0;  // normalised coordinates
  for (const Scene& s : make_scenes(10)) {
    const vantage::OrthogonalIterationResult pose =
        vantage::orthogonal_iteration_pose(s.model, s.image, {}, options);
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

namespace {

// affine-refined: Levenberg-Marquardt on (R, alpha, p) against a 1-D golden-section search on
// alpha with Prop. 4 inside (issue 11 asks which is better). Same seeded scenes: 8 random points
// in a unit cube, random rotation, affine image at alpha = 0.01 (range 10 at f = 1000 px) with
// 0.5 px noise. Counter "rot_err_deg": mean rotation error; "vs_truth": mean image RMS over the
// truth's (< 1: fits better than the truth, the maximum-likelihood signature).

struct AffineScene {
  Eigen::Matrix3Xd model;
  Eigen::Matrix2Xd image;
  Eigen::Matrix3d R;
  double truth_rms = 0.0;
};

std::vector<AffineScene> make_affine_scenes() {
  std::mt19937 rng(kBenchSeed + 100);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  std::normal_distribution<double> normal;
  std::vector<AffineScene> scenes(kScenes);
  constexpr double kAlpha = 0.01;
  constexpr double kNoisePx = 0.5;
  for (AffineScene& s : scenes) {
    s.R = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
              .normalized()
              .toRotationMatrix();
    s.model.resize(3, 8);
    s.image.resize(2, 8);
    double sse = 0.0;
    for (int i = 0; i < 8; ++i) {
      s.model.col(i) = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      const Eigen::Vector2d noise(kNoisePx * normal(rng), kNoisePx * normal(rng));
      s.image.col(i) = (s.R * s.model.col(i)).head<2>() / kAlpha + noise;
      sse += noise.squaredNorm();
    }
    s.truth_rms = std::sqrt(sse / 8.0);
  }
  return scenes;
}

/// Pixel RMS of the best Eq. (36) translation for (R, alpha) on free vectors, and that R.
double scale_search_rms(const vantage::FreeVectors& free, double alpha, Eigen::Matrix3d* R) {
  const vantage::AffineOrientationResult o =
      vantage::affine_orientation(free.z_object, free.d, alpha, free.weights);
  *R = o.R_camera_object;
  return std::sqrt(o.residual / free.weights.sum()) / alpha;
}

/// Golden-section search of alpha in [0.3, 1] x the LUB scale (the LUB bounds alpha from above).
Eigen::Matrix3d scale_search(const AffineScene& s, int evaluations) {
  const vantage::FreeVectors free = vantage::affine_free_vectors(s.model, s.image, {}, {});
  const double lub = vantage::lub_scale(free.z_object, free.d).alpha;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = 0.3 * lub, b = lub;
  Eigen::Matrix3d Rc, Rd;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = scale_search_rms(free, c, &Rc), fd = scale_search_rms(free, d, &Rd);
  for (int k = 2; k < evaluations; ++k) {
    if (fc < fd) {
      b = d, d = c, fd = fc, Rd = Rc;
      c = b - g * (b - a);
      fc = scale_search_rms(free, c, &Rc);
    } else {
      a = c, c = d, fc = fd, Rc = Rd;
      d = a + g * (b - a);
      fd = scale_search_rms(free, d, &Rd);
    }
  }
  return fc < fd ? Rc : Rd;
}

double angle_deg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return vantage::rotation_angle_between(a, b) * vantage::kDegreesPerRadian;
}

void BM_Pose_AffineRefinedLm(benchmark::State& state) {
  const std::vector<AffineScene> scenes = make_affine_scenes();
  std::size_t k = 0;
  double error = 0.0, ratio = 0.0, solves = 0.0;
  for (auto _ : state) {
    const AffineScene& s = scenes[k++ % scenes.size()];
    const vantage::RefinedPoseResult r = vantage::affine_refined_pose(s.model, s.image);
    benchmark::DoNotOptimize(r.R_camera_object.data());
    error += angle_deg(r.R_camera_object, s.R);
    ratio += r.reprojection_rms_px / s.truth_rms;
    solves += 1.0;
  }
  state.counters["rot_err_deg"] = error / std::max(solves, 1.0);
  state.counters["vs_truth"] = ratio / std::max(solves, 1.0);
}

void BM_Pose_AffineScaleSearch(benchmark::State& state) {
  const std::vector<AffineScene> scenes = make_affine_scenes();
  const int evaluations = static_cast<int>(state.range(0));
  std::size_t k = 0;
  double error = 0.0, solves = 0.0;
  for (auto _ : state) {
    const AffineScene& s = scenes[k++ % scenes.size()];
    const Eigen::Matrix3d R = scale_search(s, evaluations);
    benchmark::DoNotOptimize(R.data());
    error += angle_deg(R, s.R);
    solves += 1.0;
  }
  state.counters["rot_err_deg"] = error / std::max(solves, 1.0);
}

void BM_Pose_AffinePaper(benchmark::State& state) {
  const std::vector<AffineScene> scenes = make_affine_scenes();
  std::size_t k = 0;
  double error = 0.0, solves = 0.0;
  for (auto _ : state) {
    const AffineScene& s = scenes[k++ % scenes.size()];
    const vantage::AffinePoseResult r = vantage::affine_pose(s.model, s.image);
    benchmark::DoNotOptimize(r.R_camera_object.data());
    error += angle_deg(r.R_camera_object, s.R);
    solves += 1.0;
  }
  state.counters["rot_err_deg"] = error / std::max(solves, 1.0);
}

BENCHMARK(BM_Pose_AffinePaper);
BENCHMARK(BM_Pose_AffineRefinedLm);
BENCHMARK(BM_Pose_AffineScaleSearch)->Arg(20)->Arg(40);

}  // namespace
