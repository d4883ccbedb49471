// Every subcommand that reads a layout reads every layout format (JSON, CSV, AprilTag YAML)
// through one reader; `design --write` writes the format its extension names or refuses it;
// marker names survive (issue 17).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/sanitized.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using testing::run_json;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kLayouts = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";
const std::string kCsv = "'" + kLayouts + "mocap_rigid_body.csv'";
const std::string kYaml = "'" + kLayouts + "apriltag_cube.yaml'";
const std::string kTriad = "'" + kLayouts + "triad.json'";
const std::vector<std::string> kCsvNames = {"hub", "arm_long", "arm_short", "arm_side", "mast"};

TEST(LayoutFormatsCli, PlotReadsCsvAndYaml) {
  ScratchDir scratch;
  for (const std::string& file : {kCsv, kYaml}) {
    const auto json = run_json("plot " + file + " --out figs --only vectors", scratch);
    EXPECT_EQ(json["status"], "certified") << file;
    EXPECT_TRUE(std::filesystem::exists(scratch.path("figs/vectors.png"))) << file;
  }
  // --layout-format (plot's --format is the figure's) reads any extension.
  scratch.write("markers.txt", "a,0,0,0\nb,1,0,0\nc,0,1,0\nd,0,0,1\n");
  const auto json =
      run_json("plot markers.txt --layout-format csv --out txt --only vectors", scratch);
  EXPECT_EQ(json["status"], "certified");
}

TEST(LayoutFormatsCli, SimulateReadsCsvAndYaml) {
  ScratchDir scratch;
  for (const std::string& file : {kCsv, kYaml}) {
    const auto json = run_json("simulate " + file + " --trials 5 --methods affine", scratch);
    EXPECT_EQ(json["mode"], "points") << file;
    EXPECT_TRUE(json["bound_check"]["passed"].get<bool>()) << file;
  }
  const auto centres =
      run_json("simulate " + kYaml + " --tag-points centres --trials 5 --methods affine", scratch);
  EXPECT_EQ(centres["bound_check"]["vectors"], 3);  // three tag centres, three free vectors
}

TEST(LayoutFormatsCli, ExperimentLayoutsReadCsvAndYaml) {
  ScratchDir scratch;
  const auto json =
      run_json("experiment bound --quick --out b --layouts " + kCsv + " " + kYaml, scratch);
  EXPECT_EQ(json["experiment"], "bound");
  const std::string summary = testing::read_file(scratch.path("b/summary.md"));
  EXPECT_THAT(summary, HasSubstr("mocap_rigid_body"));
  EXPECT_THAT(summary, HasSubstr("apriltag_cube"));
}

TEST(LayoutFormatsCli, DesignWritesCsvToACsvNameWithTheMarkerNames) {
  ScratchDir scratch;
  const auto json = run_json("design " + kCsv + " --add 1 --no-direct --write out.csv", scratch);
  EXPECT_EQ(json["written"], "out.csv");
  EXPECT_EQ(json["steps"][0]["name"], "added1");
  const std::string text = testing::read_file(scratch.path("out.csv"));
  EXPECT_THAT(text, HasSubstr("name,x,y,z,weight\n"));
  EXPECT_THAT(text, Not(HasSubstr("{")));
  EXPECT_THAT(text, HasSubstr("\nhub,0,0,0,1\n"));
  EXPECT_THAT(text, HasSubstr("\nadded1,"));
  // Read back (as `weights` reads it): the same markers, named as before plus the addition.
  const auto again = run_json("weights out.csv", scratch);
  std::vector<std::string> names = kCsvNames;
  names.push_back("added1");
  EXPECT_EQ(again["names"].get<std::vector<std::string>>(), names);
  EXPECT_EQ(again["n"], 6);
}

TEST(LayoutFormatsCli, DesignKeepsTheNamesInJsonToo) {
  ScratchDir scratch;
  // The names do not depend on where the search stops: under the sanitizers it stops early.
  const std::string budget = testing::kUnderSanitizer ? " --search-budget 30000" : "";
  run_json("design " + kCsv + " --add 2 --no-direct --write out.json" + budget, scratch);
  const auto file = nlohmann::json::parse(testing::read_file(scratch.path("out.json")));
  std::vector<std::string> names = kCsvNames;
  names.insert(names.end(), {"added1", "added2"});
  EXPECT_EQ(file["names"].get<std::vector<std::string>>(), names);
  ASSERT_EQ(file["points"].size(), 7u);
  // And through a second design run, which names its marker after the ones already taken.
  const auto third =
      run_json("design out.json --add 1 --no-direct --write third.csv" + budget, scratch);
  EXPECT_EQ(third["steps"][0]["name"], "added3");
}

TEST(LayoutFormatsCli, DesignRefusesWritesItCannotHonourBeforeTheSearch) {
  ScratchDir scratch;
  struct Refused {
    std::string args;
    std::string target;
    std::string expected;
  };
  const Refused refused[] = {
      {kCsv + " --add 1 --write out.yaml", "out.yaml", "out.yaml: cannot write an AprilTag"},
      {kCsv + " --add 1 --write out.txt", "out.txt", "name the file .json, .csv, .ini or .rom"},
      {kTriad + " --add 1 --write out.csv", "out.csv", "holds marker positions"},
  };
  for (const Refused& r : refused) {
    const auto run = run_vantage("design " + r.args, scratch);
    testing::expect_bad_input(run, r.expected);
    EXPECT_THAT(run.err, HasSubstr("--write")) << r.args;
    EXPECT_FALSE(std::filesystem::exists(scratch.path(r.target))) << r.args;
  }
}

}  // namespace
}  // namespace vantage
