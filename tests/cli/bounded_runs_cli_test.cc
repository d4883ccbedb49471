// Issue 22: unbounded work and silent acceptance. `simulate --trials 1e15` grew to 10.7 GB and
// ended in std::bad_alloc (exit 1), `experiment` had created its --out directory by then; a
// near-degenerate layout reported 0 deg certified with exit 0; a CSV row of NaN was dropped as
// a header.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

namespace fs = std::filesystem;
using testing::expect_bad_input;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kTriad = "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/triad.json'";

TEST(BoundedRunsCli, TrialsAboveTheLimitAreRefusedBeforeAnyWork) {
  ScratchDir scratch;
  expect_bad_input(
      run_vantage("simulate " + kTriad + " --trials 1000000000000000 --csv t.csv", scratch),
      "--trials: 1000000000000000 exceeds the limit of");
  EXPECT_FALSE(fs::exists(scratch.path("t.csv")));
  for (const char* name : {"wu-snr", "bound"}) {
    expect_bad_input(
        run_vantage(std::string("experiment ") + name + " --out out --trials 1000000000000000",
                    scratch),
        "for `vantage experiment` (--allow-large lifts it)");
    EXPECT_FALSE(fs::exists(scratch.path("out"))) << name;
  }
  // Per-trial output keeps every trial in memory: a lower bound, named with its option.
  expect_bad_input(run_vantage("simulate " + kTriad + " --trials 5000000 --per-trial", scratch),
                   "--trials with --per-trial: 5000000 exceeds the limit of");
  expect_bad_input(
      run_vantage("simulate " + kTriad + " --trials 5000000 --shard 1/2", scratch),
      "--trials per shard (--trials / N of --shard K/N): 2500000 exceeds the limit of");
}

TEST(BoundedRunsCli, EmptyOutIsNamedAsTyped) {
  ScratchDir scratch;
  const testing::CliRun run = run_vantage("experiment bound --out '' --quick", scratch);
  expect_bad_input(run, "--out: must not be empty");
  EXPECT_THAT(run.err, ::testing::Not(HasSubstr("out_dir")));
}

TEST(BoundedRunsCli, CsvIsWrittenAllOrNothing) {
  ScratchDir scratch;
  const testing::CliRun ok =
      run_vantage("simulate " + kTriad + " --trials 30 --methods affine --csv t.csv", scratch);
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(testing::line_count(testing::read_file(scratch.path("t.csv"))), 31);
  // A bad target is refused before the run; nothing is left behind.
  expect_bad_input(run_vantage("simulate " + kTriad + " --trials 30 --csv no/such/t.csv", scratch),
                   "--csv: ");
  for (const auto& entry : fs::directory_iterator(scratch.dir())) {
    EXPECT_EQ(entry.path().filename().string().rfind(".vantage-write", 0), std::string::npos);
  }
}

TEST(BoundedRunsCli, NearDegenerateLayoutIsFlaggedWithExitOne) {
  ScratchDir scratch;
  // Two vectors 1e-8 rad apart: p-bar_min = 5e-9, the true worst-case error 89.99999971 deg.
  scratch.write("hair.json", R"({"vectors": [[1, 0, 0], [1, 1e-8, 0]]})");
  const testing::CliRun run = run_vantage("analyze hair.json --json", scratch);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("vantage: warning: near-degenerate layout"));
  const nlohmann::json json = nlohmann::json::parse(run.out);
  EXPECT_TRUE(json["near_degenerate"].get<bool>());
  EXPECT_FALSE(json["degenerate"].get<bool>());
  EXPECT_NEAR(json["pbar_min"].get<double>(), 5e-9, 1e-15);
  EXPECT_NEAR(json["max_worst_case_error_deg"].get<double>(), 89.99999971352110, 1e-9);
  const testing::CliRun text = run_vantage("analyze hair.json", scratch);
  EXPECT_EQ(text.status, 1);
  EXPECT_THAT(text.out, HasSubstr("NEAR-DEGENERATE"));
}

TEST(BoundedRunsCli, CsvRowOfMissingValuesIsNotAHeader) {
  ScratchDir scratch;
  scratch.write("m.csv", "m1,nan,nan,nan\nm2,0,0,0\nm3,1,0,0\nm4,0,1,0\nm5,0,0,1\n");
  expect_bad_input(run_vantage("analyze m.csv", scratch),
                   "m.csv: line 1 (m1), x: expected a finite number, got \"nan\"");
  scratch.write(
      "t.yaml",
      "tag_bundles:\n  - name: b\n    layout:\n"
      "      - {id: 0, size: 0.05, x: 0.05, y: 0, z: 0, x: 9, qw: 1, qx: 0, qy: 0, qz: 0}\n"
      "      - {id: 1, size: 0.05, x: 1, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0}\n");
  expect_bad_input(run_vantage("analyze t.yaml", scratch),
                   "t.yaml: tag_bundles[0].layout[0].x: duplicate key");
}

}  // namespace
}  // namespace vantage
