#include "vantage/simulate/monte_carlo.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "support/eigen_testing.h"
#include "vantage/analysis/common.h"
#include "vantage/simulate/report_json.h"

namespace vantage::simulate {
namespace {

// Noise-free estimates of exact methods are exact to rounding (degrees, relative).
constexpr double kExactDeg = 1e-6;
constexpr double kExactRelative = 1e-9;

// An angle of a few tenths of a radian from a rotation's entries, in degrees: a few ulps of 17.
constexpr double kAngleRounding = 1e-12;
// One division of exact small numbers (|3 - 2| / 2, 2 / 2): correctly rounded.
constexpr double kRatioRounding = 1e-15;
// The RMS of 200 000 draws of sigma = 2 has a standard deviation of about sigma / sqrt(2 N) =
// 0.0032 (Gaussian; less for uniform): this is 6 of them.
constexpr double kRmsSampling = 0.02;
// Haralick quotes sigma for 92 dB and 26 dB to one significant digit: exact to 1 %.
constexpr double kPaperRelative = 0.01;

const Eigen::Matrix3Xd kPoints = (Eigen::Matrix3Xd(3, 5) << 0.5, -0.5, 0.5, -0.5, 0.1,  //
                                  0.5, 0.5, -0.5, -0.5, 0.2,                            //
                                  0.7, -0.7, -0.7, 0.7, 0.0)
                                     .finished();

SceneGenerator layout_generator(const LayoutSceneOptions& options) {
  return [options](long, TrialRandom& random) {
    return make_layout_scene(kPoints, false, options, random);
  };
}

std::vector<Estimator> all_for(const SceneGenerator& generator) {
  TrialRandom random(1);
  return select_estimators({}, generator(0, random), "methods");
}

/// Everything but the wall-clock times must be bit-identical.
void expect_same_values(const MonteCarloRun& a, const MonteCarloRun& b) {
  ASSERT_EQ(a.trial_index, b.trial_index);
  ASSERT_EQ(a.names, b.names);
  for (std::size_t e = 0; e < a.names.size(); ++e) {
    for (std::size_t k = 0; k < a.trial_index.size(); ++k) {
      const TrialError& x = a.errors[e][k];
      const TrialError& y = b.errors[e][k];
      EXPECT_EQ(std::memcmp(&x.rot_err_deg, &y.rot_err_deg, sizeof(double)), 0);
      EXPECT_EQ(std::isnan(x.trans_err_rel), std::isnan(y.trans_err_rel));
      if (!std::isnan(x.trans_err_rel)) {
        EXPECT_EQ(x.trans_err_rel, y.trans_err_rel);
      }
      EXPECT_EQ(x.status, y.status);
      EXPECT_EQ(x.ok, y.ok);
    }
  }
}

TEST(MonteCarlo, BitIdenticalAtOneAndFourThreads) {
  LayoutSceneOptions scene;
  scene.noise_px = 0.5;
  const SceneGenerator generator = layout_generator(scene);
  MonteCarloOptions options;
  options.trials = 60;
  options.seed = 7;
  options.threads = 1;
  options.keep_trials = true;
  const MonteCarloRun one = run_monte_carlo(generator, all_for(generator), options);
  options.threads = 4;
  const MonteCarloRun four = run_monte_carlo(generator, all_for(generator), options);
  ASSERT_EQ(one.names.size(), 5u);  // affine, affine-spanning, affine-refined, standard, full3d
  expect_same_values(one, four);
  options.seed = 8;
  const MonteCarloRun other = run_monte_carlo(generator, all_for(generator), options);
  EXPECT_NE(other.errors[0][0].rot_err_deg, one.errors[0][0].rot_err_deg);  // the control
}

TEST(MonteCarlo, ShardsMergedEqualOneRunThroughJson) {
  LayoutSceneOptions scene;
  scene.camera = CameraModel::kPinhole;
  scene.noise_px = 1.0;
  const SceneGenerator generator = layout_generator(scene);
  MonteCarloOptions options;
  options.trials = 31;
  options.keep_trials = true;
  const MonteCarloRun whole = run_monte_carlo(generator, all_for(generator), options);
  std::vector<MonteCarloRun> shards;
  std::vector<std::string> sources;
  for (int k = 3; k >= 1; --k) {  // any order
    options.shard = {k, 3};
    const MonteCarloRun shard = run_monte_carlo(generator, all_for(generator), options);
    const Json text = Json::parse(per_trial_json(shard).dump());
    shards.push_back(run_from_json(text, options.trials, options.seed, "shard"));
    sources.push_back("shard" + std::to_string(k));
  }
  const MonteCarloRun merged = merge_runs(shards, sources);
  expect_same_values(whole, merged);
  const auto a = summarize(whole);
  const auto b = summarize(merged);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t e = 0; e < a.size(); ++e) {
    EXPECT_EQ(a[e].rot_err_deg.median, b[e].rot_err_deg.median);
    EXPECT_EQ(a[e].rot_err_deg.p95, b[e].rot_err_deg.p95);
    EXPECT_EQ(a[e].rot_err_deg.mean, b[e].rot_err_deg.mean);
    EXPECT_EQ(a[e].trans_err_rel.max, b[e].trans_err_rel.max);
    EXPECT_EQ(a[e].by_status, b[e].by_status);
  }
  EXPECT_THROW(merge_runs({shards[0], shards[0]}, {"a", "b"}), InvalidArgument);  // overlap
}

TEST(MonteCarlo, NoiseFreeExactMethodsReturnTheTruth) {
  LayoutSceneOptions scene;
  scene.camera = CameraModel::kPinhole;
  const SceneGenerator generator = layout_generator(scene);
  MonteCarloOptions options;
  options.trials = 20;
  const auto summaries = summarize(run_monte_carlo(generator, all_for(generator), options));
  int checked = 0;
  for (const EstimatorSummary& s : summaries) {
    if (s.name != "full3d" && s.name != "oi-foam" && s.name != "oi-svd" &&
        s.name != "perspective") {
      continue;
    }
    EXPECT_LT(s.rot_err_deg.max, kExactDeg) << s.name;
    EXPECT_LT(s.trans_err_rel.max, kExactRelative) << s.name;
    EXPECT_EQ(s.failures, 0) << s.name;
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

TEST(MonteCarlo, NoiseFreeAffineRefinedReturnsTheTruthWhereTheLubScaleDoesNot) {
  const SceneGenerator generator = layout_generator(LayoutSceneOptions{});
  MonteCarloOptions options;
  options.trials = 20;
  const auto summaries = summarize(run_monte_carlo(generator, all_for(generator), options));
  const auto find = [&](const std::string& name) {
    for (const EstimatorSummary& s : summaries) {
      if (s.name == name) return s;
    }
    ADD_FAILURE() << name << " did not run";
    return EstimatorSummary{};
  };
  const EstimatorSummary refined = find("affine-refined");
  EXPECT_LT(refined.rot_err_deg.max, kExactDeg);
  EXPECT_LT(refined.trans_err_rel.max, kExactRelative);
  EXPECT_EQ(refined.failures, 0);
  // Lemma 7's LUB scale is exact only when a free vector lies in the image plane: the control.
  EXPECT_GT(find("affine").rot_err_deg.max, 1000.0 * kExactDeg);
}

TEST(MonteCarlo, TrialErrorMeasuresTheRotationAngle) {
  Scene scene;
  scene.p_true = Eigen::Vector3d(0.0, 0.0, 2.0);
  PoseEstimate estimate;
  estimate.R_camera_object = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).matrix();
  estimate.p_camera_object = Eigen::Vector3d(0.0, 0.0, 3.0);
  estimate.alpha = 2.0;
  const TrialError e = trial_error(estimate, scene);
  EXPECT_NEAR(e.rot_err_deg, 0.3 * kDegreesPerRadian, kAngleRounding);
  EXPECT_NEAR(e.trans_err_rel, 0.5, kRatioRounding);
  EXPECT_NEAR(e.trans_err_deg, 0.0, kAngleRounding);
  EXPECT_NEAR(e.scale_err, 1.0, kRatioRounding);
  EXPECT_EQ(e.status, "ok");
  EXPECT_TRUE(e.ok);
  // No translation (a NaN entry): no translation error; an ambiguous estimate is not ok.
  estimate.p_camera_object.setConstant(std::nan(""));
  estimate.ambiguous = true;
  const TrialError f = trial_error(estimate, scene);
  EXPECT_TRUE(std::isnan(f.trans_err));
  EXPECT_EQ(f.status, "ambiguous");
  EXPECT_FALSE(f.ok);
}

TEST(Statistics, OrderStatisticsAndNaN) {
  const double nan = std::nan("");
  const Summary s = summarize(std::vector<double>{5, 1, nan, 3, 2, 4});
  EXPECT_EQ(s.count, 5);
  EXPECT_EQ(s.median, 3);
  EXPECT_EQ(s.mean, 3);
  EXPECT_EQ(s.p95, 5);  // ceil(0.95 * 5) = 5th smallest
  EXPECT_EQ(s.max, 5);
  EXPECT_EQ(summarize(std::vector<double>{1, 2, 3, 4}).median, 2.5);
  EXPECT_TRUE(std::isnan(summarize(std::vector<double>{nan}).median));
}

TEST(Statistics, StreamedSummaryIsExactUpToItsBufferThenWithinTheHistogramResolution) {
  // Relative half-width of a histogram bucket (statistics.h): the bound the streamed median and
  // p95 keep against the exact order statistics.
  const double resolution = std::ldexp(1.0, -(SummaryAccumulator::kHistogramBits + 1));
  std::mt19937_64 rng(testing::kSeed);
  std::lognormal_distribution<double> spread(0.0, 3.0);  // values over many binades
  for (const long n :
       {1000L, SummaryAccumulator::kExactSamples, 3 * SummaryAccumulator::kExactSamples + 1}) {
    std::vector<double> values;
    SummaryAccumulator accumulator;
    for (long k = 0; k < n; ++k) {
      const double x = k % 97 == 0 ? std::nan("") : spread(rng);
      values.push_back(x);
      accumulator.add(x);
    }
    const Summary exact = summarize(values);
    const Summary streamed = accumulator.summary();
    EXPECT_EQ(streamed.count, exact.count);
    EXPECT_EQ(streamed.mean, exact.mean);  // the same sum in the same order
    EXPECT_EQ(streamed.max, exact.max);
    EXPECT_EQ(accumulator.approximate(), exact.count > SummaryAccumulator::kExactSamples);
    if (!accumulator.approximate()) {
      EXPECT_EQ(streamed.median, exact.median);
      EXPECT_EQ(streamed.p95, exact.p95);
    } else {
      EXPECT_NEAR(streamed.median, exact.median, resolution * exact.median);
      EXPECT_NEAR(streamed.p95, exact.p95, resolution * exact.p95);
      EXPECT_NE(streamed.median, exact.median);  // the control: it is the histogram's value
    }
  }
}

TEST(MonteCarlo, StreamedRunKeepsNoTrialsAndGivesTheSameStatistics) {
  const SceneGenerator generator = layout_generator(LayoutSceneOptions{});
  MonteCarloOptions options;
  options.threads = 2;
  options.trials = 2 * 2 * kTrialsPerWorker + 17;  // several blocks, the last one partial
  options.keep_trials = true;
  const MonteCarloRun kept = run_monte_carlo(generator, all_for(generator), options);
  options.keep_trials = false;
  long seen = 0;
  long previous = -1;
  options.on_trial = [&](const MonteCarloRun& run, long trial,
                         const std::vector<TrialError>& errors) {
    EXPECT_EQ(trial, previous + 1);  // in trial order
    EXPECT_EQ(errors.size(), run.names.size());
    EXPECT_EQ(
        std::memcmp(&errors[0].rot_err_deg, &kept.errors[0][trial].rot_err_deg, sizeof(double)), 0);
    previous = trial;
    ++seen;
  };
  const MonteCarloRun streamed = run_monte_carlo(generator, all_for(generator), options);
  EXPECT_EQ(seen, options.trials);
  EXPECT_EQ(streamed.trials, options.trials);
  EXPECT_TRUE(streamed.trial_index.empty());
  for (const auto& errors : streamed.errors) EXPECT_TRUE(errors.empty());
  const auto a = summarize(kept);
  const auto b = summarize(streamed);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t e = 0; e < a.size(); ++e) {
    EXPECT_EQ(a[e].rot_err_deg.median, b[e].rot_err_deg.median);
    EXPECT_EQ(a[e].rot_err_deg.mean, b[e].rot_err_deg.mean);
    EXPECT_EQ(a[e].trans_err_rel.p95, b[e].trans_err_rel.p95);
    EXPECT_EQ(a[e].by_status, b[e].by_status);
  }
}

TEST(Shards, ParseAndPartition) {
  EXPECT_EQ(parse_shard("2/5", "--shard").index, 2);
  for (const char* bad : {"0/3", "4/3", "1/0", "a/b", "1/2x", "12"}) {
    EXPECT_THROW(parse_shard(bad, "--shard"), InvalidArgument) << bad;
  }
  long covered = 0;
  for (int k = 1; k <= 7; ++k) {
    const auto [first, last] = shard_range(100, {k, 7});
    EXPECT_EQ(first, covered);
    covered = last;
  }
  EXPECT_EQ(covered, 100);
}

TEST(Noise, StandardDeviationAndSnr) {
  TrialRandom random(3);
  for (NoiseKind kind : {NoiseKind::kGaussian, NoiseKind::kUniform}) {
    double sum2 = 0.0;
    constexpr int kSamples = 200000;
    for (int i = 0; i < kSamples; ++i) sum2 += std::pow(noise_sample(kind, 2.0, random), 2);
    EXPECT_NEAR(std::sqrt(sum2 / kSamples), 2.0, kRmsSampling) << to_string(kind);
  }
  // Haralick Sec. 4.4: 92 dB <-> 0.0001 and 26 dB <-> 0.2 for a peak-to-peak extent of 4.
  EXPECT_NEAR(sigma_from_snr(92.0, 4.0), 1e-4, kPaperRelative * 1e-4);
  EXPECT_NEAR(sigma_from_snr(26.0, 4.0), 0.2, kPaperRelative * 0.2);
}

TEST(Random, TrialEnginesAreIndependentOfOrder) {
  TrialRandom a = TrialRandom::for_trial(5, 9);
  TrialRandom b = TrialRandom::for_trial(5, 9);
  const Eigen::Matrix3d R = a.rotation();
  EXPECT_EQ(R, b.rotation());
  EXPECT_THAT(R, testing::IsRotation());
  EXPECT_NE(trial_seed(5, 9), trial_seed(5, 10));
}

}  // namespace
}  // namespace vantage::simulate
