#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

// The example's correspondences are noise-free: every method recovers the scale 2 to solver
// rounding.
constexpr double kScaleTolerance = 1e-9;
// The translation (|p| = 12) comes from the scale and rotation: their tolerance times the size.
constexpr double kTranslationTolerance = 1e-8;

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kCube = std::string(VANTAGE_SOURCE_DIR) + "/examples/correspondences/cube.json";

TEST(OrientCli, JsonOutputHasTheContractFieldsAndTheTruth) {
  ScratchDir scratch;
  for (const char* method : {"qmethod", "svd", "foam"}) {
    const auto run = run_vantage("orient '" + kCube + "' --json --method " + method, scratch);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const auto json = nlohmann::json::parse(run.out);
    for (const char* field : {"R", "p", "alpha", "residual", "status"}) {
      EXPECT_TRUE(json.contains(field)) << field;
    }
    EXPECT_EQ(json["status"], "ok");
    EXPECT_EQ(json["method"], method);
    EXPECT_NEAR(json["alpha"].get<double>(), 2.0, kScaleTolerance);  // the example's scale
    EXPECT_NEAR(json["p"][2].get<double>(), 12.0, kTranslationTolerance);
    ASSERT_EQ(json["R"].size(), 3u);
    EXPECT_EQ(json["R"][0].size(), 3u);
  }
}

TEST(OrientCli, ReadableReportByDefault) {
  ScratchDir scratch;
  const auto run = run_vantage("orient '" + kCube + "'", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("R_camera_object"));
  EXPECT_THAT(run.out, HasSubstr("status     ok"));
}

TEST(OrientCli, HelpExitsZero) {
  ScratchDir scratch;
  const auto run = run_vantage("orient --help", scratch);
  EXPECT_EQ(run.status, 0);
  EXPECT_THAT(run.out, HasSubstr("--method"));
}

using testing::BadCall;

class OrientCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(OrientCliBadInput, OneErrorLineExitTwoNothingOnStdout) {
  ScratchDir scratch;
  testing::run_bad_call("orient", GetParam(), scratch);
}

const BadCall kBadCalls[] = {
    {"NoFile", nullptr, "", "CORRESPONDENCES is required"},
    {"MissingFile", nullptr, "in.json", "in.json: cannot open file"},
    {"NotJson", "{", "in.json --json", "in.json: not valid JSON"},
    {"NoMeasured", R"({"model": [[0,0,0],[1,0,0]]})", "in.json",
     "measured: missing, required by vantage orient"},
    {"CountMismatch", R"({"model": [[0,0,0],[1,0,0]], "measured": [[0,0,0]]})", "in.json",
     "measured: has 1 entries but model has 2"},
    {"BadMethod", R"({"model": [[0,0,0]], "measured": [[0,0,0]]})", "in.json --method nope",
     "--method"},
    {"CoincidentMeasured", R"({"model": [[0,0,0],[1,0,0]], "measured": [[1,1,1],[1,1,1]]})",
     "in.json", "in.json: measured: all measured points coincide"},
};

INSTANTIATE_TEST_SUITE_P(OrientCli, OrientCliBadInput, ::testing::ValuesIn(kBadCalls),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(OrientCli, CollinearDataAreDegenerateExitOne) {
  // Points on one line do not determine the rotation about it: the pose is printed with status
  // "degenerate", the reason goes to stderr, exit 1.
  ScratchDir scratch;
  scratch.write("line.json",
                R"({"model": [[0,0,0],[1,0,0],[2,0,0]], "measured": [[1,1,1],[2,1,1],[3,1,1]]})");
  const auto run = run_vantage("orient line.json --json", scratch);
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(nlohmann::json::parse(run.out)["status"], "degenerate");
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("degenerate"));
}

TEST(Cli, UnknownSubcommandIsAUsageError) {
  ScratchDir scratch;
  const auto run = run_vantage("frobnicate", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
}

TEST(Cli, NoSubcommandIsAUsageError) {
  ScratchDir scratch;
  const auto run = run_vantage("", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
}

}  // namespace
}  // namespace vantage
