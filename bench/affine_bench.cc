// Prop. 4's sign enumeration: Gray code with the Eq. (17) update of D, top_eigenpair() and O(1)
// J_2d (BM_AffineOrientation_GrayCode) against recomputing D, Eigen's SelfAdjointEigenSolver and
// an O(n) J_2d for every pattern (BM_AffineOrientation_Naive). Same data in all.
// BM_AffineOrientation_GrayCodeEigen is the paper's procedure taken literally (Eq. 17 on D and
// top_eigenpair() per pattern).

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <random>

#include "vantage/analysis/affine_pose.h"

namespace {

struct AffineData {
  Eigen::Matrix3Xd z;
  Eigen::Matrix2Xd d;
};

/// Noise-free affine data (alpha = 1) with no vector in the image plane: all 2^n patterns run.
AffineData make_data(int n) {
  std::mt19937 rng(20061122u + static_cast<unsigned>(n));
  std::normal_distribution<double> normal;
  const Eigen::Matrix3d R = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
                                .normalized()
                                .toRotationMatrix();
  AffineData data{Eigen::Matrix3Xd(3, n), Eigen::Matrix2Xd(2, n)};
  for (int i = 0; i < n; ++i) {
    data.z.col(i) = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
  }
  data.d = (R * data.z).topRows<2>();
  return data;
}

void run(benchmark::State& state, vantage::SignEnumeration enumeration) {
  const AffineData data = make_data(static_cast<int>(state.range(0)));
  vantage::AffineOrientationOptions options;
  options.enumeration = enumeration;
  std::uint64_t patterns = 0;
  for (auto _ : state) {
    const vantage::AffineOrientationResult result =
        vantage::affine_orientation(data.z, data.d, 1.0, {}, options);
    patterns = result.sign_patterns;
    benchmark::DoNotOptimize(result.R_camera_object.data());
  }
  state.counters["patterns"] = static_cast<double>(patterns);
  // Seconds per pattern (printed with an SI prefix, e.g. 40n = 40 ns).
  state.counters["per_pattern"] =
      benchmark::Counter(static_cast<double>(patterns) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_AffineOrientation_GrayCode(benchmark::State& state) {
  run(state, vantage::SignEnumeration::kGrayCode);
}
/// The paper's procedure literally: Eq. (17) update of D and top_eigenpair() per pattern.
void BM_AffineOrientation_GrayCodeEigen(benchmark::State& state) {
  run(state, vantage::SignEnumeration::kGrayCodeEigen);
}
void BM_AffineOrientation_Naive(benchmark::State& state) {
  run(state, vantage::SignEnumeration::kNaive);
}

BENCHMARK(BM_AffineOrientation_GrayCode)
    ->Arg(8)
    ->Arg(12)
    ->Arg(16)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AffineOrientation_GrayCodeEigen)
    ->Arg(8)
    ->Arg(12)
    ->Arg(16)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AffineOrientation_Naive)
    ->Arg(8)
    ->Arg(12)
    ->Arg(16)
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);

}  // namespace
