#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

// The paper prints the triad's bound to four decimals (35.2644 degrees).
constexpr double kPaperDigits = 1e-4;
// At the certified worst viewpoint the largest error is asin(t_lower), the bound asin(t_upper):
// the certificate tolerance (1e-9) apart.
constexpr double kAtWorstViewpoint = 1e-6;
// The bound is asin of the certified upper t: the measured ratio exceeds 1 by rounding only.
constexpr double kRatioRounding = 1e-9;

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

std::string layout(const char* name) {
  return "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/" + name + ".json'";
}

TEST(SimulateCli, JsonContractAndBoundCheck) {
  ScratchDir scratch;
  const auto json = testing::run_json("simulate " + layout("triad") + " --trials 50", scratch);
  for (const char* field : {"layout", "mode", "trials", "total_trials", "seed", "shard",
                            "estimators", "bound_check", "config"}) {
    EXPECT_TRUE(json.contains(field)) << field;
  }
  for (const char* name : {"affine", "standard"}) {
    const auto& e = json["estimators"][name];
    for (const char* field : {"rot_err_deg", "trans_err_rel", "time_us"}) {
      for (const char* stat : {"median", "mean", "p95", "max"}) {
        EXPECT_TRUE(e[field].contains(stat)) << name << " " << field << " " << stat;
      }
    }
    EXPECT_TRUE(e.contains("failures"));
    EXPECT_TRUE(e.contains("wrong_but_ok"));
  }
  const auto& b = json["bound_check"];
  EXPECT_EQ(b["trials"], 50);
  EXPECT_EQ(b["vectors"], 3);
  EXPECT_LE(b["max_ratio"].get<double>(), 1.0 + kRatioRounding);
  EXPECT_NEAR(b["bound_deg"].get<double>(), 35.2644, kPaperDigits);
  EXPECT_TRUE(b["passed"].get<bool>());
  EXPECT_FALSE(json.contains("per_trial"));
}

TEST(SimulateCli, WorstViewpointReachesTheBound) {
  ScratchDir scratch;
  const auto json = testing::run_json(
      "simulate " + layout("satellite") + " --trials 20 --viewpoint worst --methods affine",
      scratch);
  EXPECT_NEAR(json["bound_check"]["max_ratio"].get<double>(), 1.0, kAtWorstViewpoint);
  EXPECT_EQ(json["bound_check"]["vectors"], 66);
  EXPECT_EQ(json["bound_check"]["affine_relation"][0]["free_vectors"], "auto");
}

TEST(SimulateCli, ShardsMergeToTheUnshardedRun) {
  ScratchDir scratch;
  const std::string base = "simulate " + layout("satellite") +
                           " --trials 24 --noise-px 0.5 --methods standard,full3d --seed 4";
  auto whole = testing::run_json(base + " --threads 1", scratch);
  for (int k = 1; k <= 3; ++k) {
    const testing::CliRun run =
        run_vantage(base + " --threads 2 --shard " + std::to_string(k) + "/3 --json", scratch);
    ASSERT_EQ(run.status, 0) << run.err;
    scratch.write("s" + std::to_string(k) + ".json", run.out);
  }
  auto merged = testing::run_json("simulate --merge s3.json s1.json s2.json", scratch);
  EXPECT_EQ(merged["trials"], 24);
  for (const char* name : {"standard", "full3d"}) {
    for (const char* field : {"rot_err_deg", "trans_err_rel"}) {
      EXPECT_EQ(merged["estimators"][name][field], whole["estimators"][name][field]) << name;
    }
  }
  EXPECT_EQ(merged["bound_check"]["max_error_deg"], whole["bound_check"]["max_error_deg"]);
  testing::expect_bad_input(run_vantage("simulate --merge s1.json s1.json", scratch),
                            "overlapping");
}

TEST(SimulateCli, CsvHasOneRowPerTrialAndEstimator) {
  ScratchDir scratch;
  const testing::CliRun run =
      run_vantage("simulate " + layout("satellite") +
                      " --trials 7 --camera pinhole --methods oi-foam,oi-svd --csv out.csv --quiet",
                  scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("oi-foam"));
  EXPECT_EQ(testing::line_count(testing::read_file(scratch.path("out.csv"))), 1 + 7 * 2);
}

TEST(SimulateCli, BadInputIsOneLineAndWritesNothing) {
  ScratchDir scratch;
  const std::string triad = layout("triad");
  const testing::BadCall calls[] = {
      {"zero trials", nullptr, "--trials 0", "--trials"},
      {"both noises", nullptr, "--noise-px 1 --snr-db 40", "--snr-db"},
      {"negative noise", nullptr, "--noise-px -1", "--noise-px"},
      {"bad range", nullptr, "--range 0", "--range"},
      {"bad focal", nullptr, "--focal -3", "--focal"},
      {"pinhole vectors", nullptr, "--camera pinhole", "--camera"},
      {"unknown method", nullptr, "--methods nope", "--methods"},
      {"inapplicable method", nullptr, "--methods oi-foam", "oi-foam"},
      {"bad shard", nullptr, "--shard 4/3", "--shard"},
      {"bad camera", nullptr, "--camera fisheye", "--camera"},
  };
  for (const testing::BadCall& call : calls) {
    const std::string args = triad + " " + call.args + " --csv never.csv";
    testing::expect_bad_input(run_vantage("simulate " + args, scratch), call.expected);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("never.csv"))) << call.name;
  }
  testing::expect_bad_input(run_vantage("simulate", scratch), "LAYOUT");
  testing::expect_bad_input(run_vantage("simulate missing.json", scratch), "missing.json");
  scratch.write("junk.json", "{}");
  testing::expect_bad_input(run_vantage("simulate --merge junk.json", scratch), "per_trial");
}

TEST(ExperimentCli, EveryExperimentRunsQuick) {
  ScratchDir scratch;
  for (const char* name : {"mcinroy-orientation", "mcinroy-pose", "bound", "haralick-2d2d",
                           "haralick-3d3d", "haralick-two-view", "wu-points", "wu-snr"}) {
    const auto json = testing::run_json(
        std::string("experiment ") + name + " --quick --out out_" + name, scratch);
    EXPECT_EQ(json["experiment"], name);
    EXPECT_TRUE(std::filesystem::exists(scratch.path(std::string("out_") + name + "/summary.md")));
  }
}

TEST(ExperimentCli, BadInput) {
  ScratchDir scratch;
  testing::expect_bad_input(run_vantage("experiment nope --out x", scratch), "nope");
  testing::expect_bad_input(run_vantage("experiment bound --out x --trials -2", scratch),
                            "--trials");
  testing::expect_bad_input(run_vantage("experiment wu-snr --out x --layouts a.json", scratch),
                            "--layouts");
  EXPECT_FALSE(std::filesystem::exists(scratch.path("x")));
}

}  // namespace
}  // namespace vantage
