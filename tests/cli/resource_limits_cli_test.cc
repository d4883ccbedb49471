// Issue 36, item 6: counts without a bound. `crb --sweep-distance 1:2:1000000` and `--sweep-tags`
// with 200 x 200 options ran for hours, `tre --monte-carlo 1000000000000000` and `ident` on 2000
// tools ended in std::bad_alloc. Each count now has a bound (vantage/commands/limits.h), checked
// before any work; the README's "Limits" table shows the same numbers.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/sanitized.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb_tags.h"
#include "vantage/commands/limits.h"

namespace vantage {
namespace {

using testing::expect_bad_input;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kExamples = std::string(VANTAGE_SOURCE_DIR) + "/examples/";
const std::string kCube = "'" + kExamples + "layouts/apriltag_cube.yaml'";
const std::string kCamera = " --distance 2 --focal 900 --noise-px 0.3 --samples 100";
const std::string kTool = "'" + kExamples + "tools/ndi_like.json'";
const std::string kTre = " --target 0,0,-150 --fle-sigma 0.0995,0.2985";

// `count` copies of `value`, comma-separated.
std::string repeated(const std::string& value, long count) {
  std::string out;
  for (long i = 0; i < count; ++i) out += (i == 0 ? "" : ",") + value;
  return out;
}

TEST(ResourceLimitsCli, SweepDistanceAboveTheLimitIsRefused) {
  ScratchDir scratch;
  const std::string n = std::to_string(commands::kMaxCrbSweepDistances + 1);
  expect_bad_input(run_vantage("crb " + kCube + kCamera + " --sweep-distance 1:2:" + n, scratch),
                   "--sweep-distance: " + n + " exceeds the limit of " +
                       std::to_string(commands::kMaxCrbSweepDistances) +
                       " for `vantage crb` (--allow-large lifts it)");
  expect_bad_input(run_vantage("plot " + kCube + " --crb" + kCamera + " --sweep-distance 1:2:" + n +
                                   " --out figs",
                               scratch),
                   "--sweep-distance: " + n + " exceeds the limit of");
  EXPECT_FALSE(std::filesystem::exists(scratch.path("figs")));
}

TEST(ResourceLimitsCli, SweepDistanceAtTheLimitPassesTheCheck) {
  // The maximum itself takes about 28 s (README "Limits"): the check, not the run.
  const commands::LimitWords words{"`vantage ", "`", "--allow-large"};
  const long limit = commands::kMaxCrbSweepDistances;
  EXPECT_NO_THROW(commands::check_limit("--sweep-distance", limit, limit, "crb", false, words));
  EXPECT_THROW(commands::check_limit("--sweep-distance", limit + 1, limit, "crb", false, words),
               InvalidArgument);
  EXPECT_NO_THROW(commands::check_limit("--sweep-distance", limit + 1, limit, "crb", true, words));
}

TEST(ResourceLimitsCli, TagTilingsAboveTheLimitAreRefusedAndTheLimitRuns) {
  ScratchDir scratch;
  const long rows = commands::kMaxTagSweepRows;
  ASSERT_EQ(rows % 2, 0);  // the tilings below: rows / 2 counts times two fills
  const std::string fills = " --tag-fill 0.5,0.8";
  expect_bad_input(run_vantage("crb " + kCube + kCamera + " --sweep-tags --tags-per-side " +
                                   repeated("1", rows / 2 + 1) + fills,
                               scratch),
                   "--sweep-tags (--tags-per-side values x --tag-fill values): " +
                       std::to_string(rows + 2) + " exceeds the limit of " + std::to_string(rows));
  const std::string k = std::to_string(camera::TagSweepOptions::kMaxPerSide + 1);
  expect_bad_input(
      run_vantage("crb " + kCube + kCamera + " --sweep-tags --tags-per-side " + k, scratch),
      "--tags-per-side: each count must be in [1, " +
          std::to_string(camera::TagSweepOptions::kMaxPerSide) + "]");
  const nlohmann::json json = testing::run_json(
      "crb " + kCube + kCamera + " --sweep-tags --tags-per-side " + repeated("1", rows / 2) + fills,
      scratch);
  EXPECT_EQ(json["sweep_tags"]["rows"].size(), static_cast<std::size_t>(rows));
}

TEST(ResourceLimitsCli, MonteCarloAboveTheLimitIsRefusedAndTheLimitRuns) {
  ScratchDir scratch;
  const std::string above = std::to_string(commands::kMaxTreTrials + 1);
  expect_bad_input(run_vantage("tre " + kTool + kTre + " --monte-carlo " + above, scratch),
                   "--monte-carlo: " + above + " exceeds the limit of " +
                       std::to_string(commands::kMaxTreTrials) + " for `vantage tre`");
  // The issue's 10^15: refused at once, not std::bad_alloc.
  expect_bad_input(run_vantage("tre " + kTool + kTre + " --monte-carlo 1000000000000000", scratch),
                   "--monte-carlo: 1000000000000000 exceeds the limit of");
  // The maximum: about 7 s of CPU, no progress line off a terminal (under the sanitizers, 40 s:
  // a hundredth of it there, the same code).
  const long trials = commands::kMaxTreTrials / (testing::kUnderSanitizer ? 100 : 1);
  const nlohmann::json json = testing::run_json(
      "tre " + kTool + kTre + " --monte-carlo " + std::to_string(trials), scratch);
  EXPECT_EQ(json["targets"][0]["monte_carlo"]["trials"].get<long>(), trials);
}

TEST(ResourceLimitsCli, IdentToolsAboveTheLimitAreRefusedBeforeReadingAndTheLimitRuns) {
  ScratchDir scratch;
  const long limit = commands::kMaxIdentTools;
  // Files that do not exist: the count is refused before any is read.
  std::string missing;
  for (long i = 0; i <= limit; ++i) missing += " missing" + std::to_string(i) + ".json";
  expect_bad_input(run_vantage("ident" + missing, scratch),
                   "TOOL files: " + std::to_string(limit + 1) + " exceeds the limit of " +
                       std::to_string(limit) + " for `vantage ident` (--allow-large lifts it)");
  scratch.write("t.json", R"({"points": [[0, 0, 0], [40, 0, 0], [0, 55, 0], [10, 20, 70]]})");
  std::string tools;
  for (long i = 0; i < limit; ++i) tools += " t.json";
  const testing::CliRun run = run_vantage("ident" + tools, scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("vantage ident: " + std::to_string(limit) + " tools"));
}

// The README's row of the limit whose first cell begins with `row`: its second cell.
std::string readme_bound(const std::string& row) {
  std::istringstream readme(testing::read_file(std::string(VANTAGE_SOURCE_DIR) + "/README.md"));
  std::string line;
  while (std::getline(readme, line)) {
    if (line.rfind("| " + row, 0) != 0) continue;
    const std::size_t begin = line.find(" | ") + 3;
    return line.substr(begin, line.find(" | ", begin) - begin);
  }
  return "no README row beginning \"| " + row + "\"";
}

// 20000 as the README writes it: "20 000".
std::string grouped(long value) {
  std::string digits = std::to_string(value);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(i, " ");
  return digits;
}

TEST(ResourceLimitsCli, ReadmeLimitsTableShowsTheConstants) {
  const std::vector<std::pair<std::string, long>> rows = {
      {"`analyze`: data vectors", commands::kMaxAnalyzeVectors},
      {"`analyze --dropout`", commands::kMaxDropoutVectors},
      {"`weights`: vectors or points", commands::kMaxWeightsEntries},
      {"`simulate`, `experiment` (per cell): `--trials`", commands::kMaxTrials},
      {"`simulate --per-trial`", commands::kMaxPerTrialTrials},
      {"`crb --sweep-distance", commands::kMaxCrbSweepDistances},
      {"`crb --sweep-tags`", commands::kMaxTagSweepRows},
      {"`crb --tags-per-side`", camera::TagSweepOptions::kMaxPerSide},
      {"`tre --monte-carlo`", commands::kMaxTreTrials},
      {"`ident`: tools", commands::kMaxIdentTools}};
  for (const auto& [row, value] : rows) {
    const std::string bound = readme_bound(row);
    const std::string expected = grouped(value);
    EXPECT_EQ(bound.substr(0, expected.size()), expected) << row << ": " << bound;
    EXPECT_FALSE(bound.size() > expected.size() && std::isdigit(bound[expected.size()]))
        << row << ": " << bound;
  }
  const std::string design = readme_bound("`design`: estimated CPU time");
  EXPECT_EQ(design.rfind(grouped(static_cast<long>(commands::kMaxDesignSeconds)) + " s", 0), 0u)
      << design;
}

}  // namespace
}  // namespace vantage
