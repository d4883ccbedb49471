// Absolute orientation from n = 10 seeded random correspondences: vantage's three solvers against
// Eigen::umeyama, the baseline a user would pick. All four solve the same similarity problem
// (rotation, translation and scale from point pairs): vantage::absolute_pose centres the data
// and runs Theorem 1 / SVD / FOAM on the centred moments; Eigen::umeyama(with_scaling = true)
// centres and takes an SVD of the covariance.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <random>

#include "vantage/analysis/absolute_orientation.h"

namespace {

constexpr unsigned kBenchSeed = 20061122;

struct Correspondences {
  Eigen::Matrix3Xd model;
  Eigen::Matrix3Xd measured;
};

/// measured = (R model + p) / alpha plus small Gaussian noise, for a seeded random pose.
Correspondences make_correspondences(int n) {
  std::mt19937 rng(kBenchSeed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Eigen::Matrix3d R =
      Eigen::Quaterniond(uniform(rng), uniform(rng), uniform(rng), uniform(rng))
          .normalized()
          .toRotationMatrix();
  const Eigen::Vector3d p(uniform(rng), uniform(rng), 5.0 + uniform(rng));
  const double alpha = 2.0;
  Correspondences c{Eigen::Matrix3Xd(3, n), Eigen::Matrix3Xd(3, n)};
  for (int j = 0; j < n; ++j) {
    c.model.col(j) = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    c.measured.col(j) = (R * c.model.col(j) + p) / alpha;
    for (int i = 0; i < 3; ++i) c.measured(i, j) += noise(rng);
  }
  return c;
}

void run_vantage(benchmark::State& state, vantage::OrientationMethod method) {
  const Correspondences c = make_correspondences(static_cast<int>(state.range(0)));
  vantage::OrientationOptions options;
  options.method = method;
  const Eigen::VectorXd no_weights;
  for (auto _ : state) {
    vantage::PoseResult result = vantage::absolute_pose(c.model, c.measured, no_weights, options);
    benchmark::DoNotOptimize(result.R_camera_object.data());
    benchmark::ClobberMemory();
  }
}

void BM_AbsoluteOrientation_QMethod(benchmark::State& state) {
  run_vantage(state, vantage::OrientationMethod::kQMethod);
}

void BM_AbsoluteOrientation_Svd(benchmark::State& state) {
  run_vantage(state, vantage::OrientationMethod::kSvd);
}

void BM_AbsoluteOrientation_Foam(benchmark::State& state) {
  run_vantage(state, vantage::OrientationMethod::kFoam);
}

void BM_AbsoluteOrientation_EigenUmeyama(benchmark::State& state) {
  const Correspondences c = make_correspondences(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Eigen::Matrix4d T = Eigen::umeyama(c.model, c.measured, true);
    benchmark::DoNotOptimize(T.data());
    benchmark::ClobberMemory();
  }
}

BENCHMARK(BM_AbsoluteOrientation_QMethod)->Arg(10);
BENCHMARK(BM_AbsoluteOrientation_Svd)->Arg(10);
BENCHMARK(BM_AbsoluteOrientation_Foam)->Arg(10);
BENCHMARK(BM_AbsoluteOrientation_EigenUmeyama)->Arg(10);

}  // namespace
