#include "vantage/simulate/experiments.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

// Linear interpolation in log10 of round numbers: a few ulps of the knee (5 and 15 dB).
constexpr double kKneeRounding = 1e-12;

class ScratchDir {
 public:
  ScratchDir()
      : path_(std::filesystem::temp_directory_path() /
              ("vantage_experiment_" + std::to_string(::getpid()))) {}
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  std::string sub(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

long lines_of(const std::string& path) {
  std::ifstream in(path);
  long lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(Experiments, EveryQuickExperimentWritesItsFiles) {
  ScratchDir scratch;
  ASSERT_EQ(experiment_registry().size(), 8u);
  int verdicts = 0;
  for (const Experiment& e : experiment_registry()) {
    ExperimentOptions options;
    options.out_dir = scratch.sub(e.name);
    options.quick = true;
    options.threads = 2;
    const ExperimentResult result = run_experiment(e.name, options);
    EXPECT_EQ(result.summary["experiment"], e.name);
    EXPECT_FALSE(result.table.empty()) << e.name;
    ASSERT_GE(result.files.size(), 3u) << e.name;  // CSV(s), summary.json, summary.md
    for (const std::string& file : result.files) EXPECT_GE(lines_of(file), 2) << file;
    // Only the bound check has a verdict; a renamed key fails at() (it throws).
    if (e.name == std::string("bound")) {
      ++verdicts;
      EXPECT_TRUE(result.summary.at("passed").get<bool>());
    } else {
      EXPECT_FALSE(result.summary.contains("passed")) << e.name << ": a new verdict to test";
    }
  }
  EXPECT_EQ(verdicts, 1) << "the bound experiment is no longer registered";
}

TEST(Experiments, NewMethodBeatsStandardInMedian) {
  ScratchDir scratch;
  ExperimentOptions options;
  options.trials = 200;
  // mcinroy-orientation: one case per number of vectors (3 and 5, the paper's Figs. 4-5); at()
  // throws, and so fails the test, when a key is renamed.
  options.out_dir = scratch.sub("mcinroy-orientation");
  const ExperimentResult orientation = run_experiment("mcinroy-orientation", options);
  const auto& cases = orientation.summary.at("cases");
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases.at(0).at("n").get<int>(), 3);
  EXPECT_EQ(cases.at(1).at("n").get<int>(), 5);
  for (const auto& c : cases) {
    EXPECT_GT(c.at("median_ratio_standard_over_new").get<double>(), 1.0) << c.at("n");
  }
  // mcinroy-pose: one ratio for the whole run (the paper's Fig. 6 table).
  options.out_dir = scratch.sub("mcinroy-pose");
  const ExperimentResult pose = run_experiment("mcinroy-pose", options);
  EXPECT_GT(pose.summary.at("median_ratio_standard_over_new").get<double>(), 1.0);
}

TEST(Experiments, RejectsBadOptions) {
  ExperimentOptions options;
  EXPECT_THROW(run_experiment("bound", options), InvalidArgument);  // no out_dir
  options.out_dir = "/tmp";
  EXPECT_THROW(run_experiment("no-such-experiment", options), InvalidArgument);
  options.trials = -1;
  EXPECT_THROW(run_experiment("bound", options), InvalidArgument);
}

TEST(SnrKnee, InterpolatesInLogError) {
  // error 10 at 0 dB, 0.1 at 10 dB: 1 deg is reached halfway in log10.
  EXPECT_NEAR(snr_knee({0, 10, 20}, {10, 0.1, 0.01}, 1.0), 5.0, kKneeRounding);
  EXPECT_TRUE(std::isnan(snr_knee({0, 10}, {10, 5}, 1.0)));
  EXPECT_EQ(snr_knee({0, 10}, {0.5, 0.1}, 1.0), 0.0);
  // A non-monotone curve: the knee is where it stays below.
  EXPECT_NEAR(snr_knee({0, 10, 20, 30}, {0.5, 10, 0.1, 0.01}, 1.0), 15.0, kKneeRounding);
}

}  // namespace
}  // namespace vantage::simulate
