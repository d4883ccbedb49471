// `vantage tre` (issue 20; docs/math.md §23): the issue's JSON names, the done-when command on the
// NDI-like tool, the text report, and bad input (one line, exit 2, nothing written).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using testing::BadCall;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kTools = "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/tools/";
const std::string kNdi = kTools + "ndi_like.json'";
// JSON numbers are printed to round-trip; the trace of three of them, or the same RMS computed
// by the search and at the direction (isotropic FLE: equal), differ by a few roundings.
constexpr double kTraceRounding = 1e-12;
// The issue's Monte Carlo agreement.
constexpr double kMonteCarlo = 0.02;

TEST(TreCli, JsonHasTheIssuesFields) {
  ScratchDir scratch;
  const nlohmann::json j = testing::run_json(
      "tre " + kNdi +
          " --target 0,0,-150 --target 10,0,-100 --fle-rms 0.25 --direction 0.2,0.1,1 "
          "--monte-carlo 20000 --json",
      scratch);
  for (const char* field : {"targets", "fle", "model"}) EXPECT_TRUE(j.contains(field)) << field;
  ASSERT_EQ(j["targets"].size(), 2u);
  for (const nlohmann::json& t : j["targets"]) {
    for (const char* field :
         {"target", "rms_isotropic", "at_direction", "worst", "best", "monte_carlo"}) {
      EXPECT_TRUE(t.contains(field)) << field;
    }
    for (const char* field : {"direction", "rms", "covariance", "visible_markers"}) {
      EXPECT_TRUE(t["at_direction"].contains(field)) << field;
    }
    for (const char* field : {"direction", "rms", "visible_markers", "certified"}) {
      EXPECT_TRUE(t["worst"].contains(field)) << field;
      EXPECT_TRUE(t["best"].contains(field)) << field;
    }
    for (const char* field : {"trials", "rms", "rel_diff"}) {
      EXPECT_TRUE(t["monte_carlo"].contains(field)) << field;
    }
    const nlohmann::json& c = t["at_direction"]["covariance"];
    const double trace = c[0][0].get<double>() + c[1][1].get<double>() + c[2][2].get<double>();
    const double rms = t["at_direction"]["rms"].get<double>();
    EXPECT_NEAR(std::sqrt(trace), rms, kTraceRounding * rms);
    EXPECT_TRUE(t["worst"]["certified"].get<bool>());
    EXPECT_GE(t["worst"]["rms"].get<double>(), rms * (1.0 - kTraceRounding));
    EXPECT_LE(t["best"]["rms"].get<double>(), rms * (1.0 + kTraceRounding));
    EXPECT_LE(std::abs(t["monte_carlo"]["rel_diff"].get<double>()), kMonteCarlo);
    EXPECT_EQ(t["monte_carlo"]["trials"].get<long>(), 20000);
  }
  EXPECT_EQ(j["fle"]["kind"], "isotropic");
}

TEST(TreCli, DoneWhenCommandGivesAReadableReport) {
  ScratchDir scratch;
  const testing::CliRun run =
      run_vantage("tre " + kNdi + " --target 0,0,-150 --fle-sigma 0.0995,0.2985", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_THAT(run.out, HasSubstr("worst over tracked directions"));
  EXPECT_THAT(run.out, HasSubstr("best over tracked directions"));
  EXPECT_THAT(run.out, HasSubstr("certified"));
  EXPECT_THAT(run.out, HasSubstr("0.0995 across, 0.2985 along the line of sight"));
}

TEST(TreCli, AnisotropicMonteCarloAgreesAtTheWorstDirection) {
  ScratchDir scratch;
  const nlohmann::json j =
      testing::run_json("tre " + kTools +
                            "five_marker.json' --target 0,0,-120 --fle-sigma 0.0995,0.2985 "
                            "--monte-carlo 100000 --json",
                        scratch);
  const nlohmann::json& t = j["targets"][0];
  EXPECT_FALSE(t.contains("rms_isotropic"));
  EXPECT_LE(std::abs(t["monte_carlo"]["rel_diff"].get<double>()), kMonteCarlo);
  EXPECT_EQ(t["monte_carlo"]["direction"], t["worst"]["direction"]);
}

TEST(TreCli, BadInputIsOneLineAndExitTwo) {
  ScratchDir scratch;
  const std::string ndi = kNdi + " ";
  const std::string vectors = "{\"vectors\": [[1,0,0],[0,1,0],[0,0,1]]}";
  const BadCall calls[] = {
      {"no target", nullptr, "--fle-rms 0.2", "--target"},
      {"bad target", nullptr, "--target 0,0 --fle-rms 0.2", "--target"},
      {"both fle", nullptr, "--target 0,0,1 --fle-rms 0.2 --fle-sigma 0.1,0.3", "--fle-rms"},
      {"neither fle", nullptr, "--target 0,0,1", "--fle-rms"},
      {"negative sigma", nullptr, "--target 0,0,1 --fle-sigma -0.1,0.3", "--fle-sigma"},
      {"zero rms", nullptr, "--target 0,0,1 --fle-rms 0", "--fle-rms"},
      {"zero direction", nullptr, "--target 0,0,1 --fle-rms 0.2 --direction 0,0,0", "--direction"},
      {"few trials", nullptr, "--target 0,0,1 --fle-rms 0.2 --monte-carlo 10",
       "--monte-carlo: must be 0 or >= 1000"},
      {"negative threads", nullptr, "--target 0,0,1 --fle-rms 0.2 --threads -1",
       "--threads: must be >= 0"},
      // Issue 36, item 2: these reported a certified worst RMS TRE of 0.0 (or inf), RMS^2
      // having overflowed or underflowed; lengths outside [1e-50, 1e50] are refused.
      {"target 1e200", nullptr, "--target 1e200,0,0 --fle-rms 0.25", "--target: is more than"},
      {"target 1e308", nullptr, "--target 1e308,0,0 --fle-rms 0.25", "--target"},
      {"far target, large FLE", nullptr, "--target 1e45,0,0 --fle-rms 1e20",
       "--target: the RMS TRE there"},
      {"huge sigmas", nullptr, "--target 0,0,-150 --fle-sigma 1e300,1e300", "--fle-sigma"},
      {"huge rms", nullptr, "--target 0,0,-150 --fle-rms 1e300", "exceeds 1e50"},
      {"tiny rms", nullptr, "--target 0,0,-150 --fle-rms 1e-300", "below 1e-50"},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    BadCall with_file = call;
    const std::string args = ndi + call.args;
    with_file.args = args.c_str();
    testing::run_bad_call("tre", with_file, scratch);
  }
  scratch.write("vectors.json", vectors);
  testing::expect_bad_input(run_vantage("tre vectors.json --target 0,0,1 --fle-rms 0.2", scratch),
                            "points");
  scratch.write("far_apart.json", "{\"points\": [[0,0,0],[1e150,0,0],[0,1e150,0],[0,0,1e150]]}");
  testing::expect_bad_input(run_vantage("tre far_apart.json --target 0,0,1 --fle-rms 0.2", scratch),
                            "far_apart.json: points: the markers' RMS radius about their centroid");
  // Issue 36: "body": "" silently meant no body.
  scratch.write("empty_body.json",
                R"({"points": [[0,0,0],[1,0,0],[0,1,0]], "normals": [[0,0,1],[0,0,1],[0,0,1]],
                    "visibility": {"body": ""}})");
  testing::expect_bad_input(
      run_vantage("tre empty_body.json --target 0,0,1 --fle-rms 0.2", scratch),
      "empty_body.json: visibility.body: empty");
  scratch.write("broken.json", "{\"points\": [[0,0,0]]");
  testing::expect_bad_input(run_vantage("tre broken.json --target 0,0,1 --fle-rms 0.2", scratch),
                            "broken.json");
}

// Issue 36: with nothing tracked `tre` exited 0 with nothing on stderr; like analyze, it prints
// its report and gives the reason on stderr, exit 1.
TEST(TreCli, NothingTrackedIsExitOneWithTheReason) {
  ScratchDir scratch;
  // Markers that face +z through 10-degree cones, a workspace about -z: nothing is ever seen.
  scratch.write("hidden.json",
                R"({"points": [[0,0,0],[40,0,0],[0,40,0],[30,30,5]],
                    "normals": [[0,0,1],[0,0,1],[0,0,1],[0,0,1]],
                    "visibility": {"cone_half_angle_deg": 10},
                    "workspace": {"axis": [0,0,-1], "half_angle_deg": 30}})");
  const testing::CliRun run =
      run_vantage("tre hidden.json --target 0,0,-100 --fle-rms 0.25", scratch);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_THAT(run.out, HasSubstr("worst"));
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("vantage: tre: no direction of the workspace sees at least 3"));
}

// A 5-DoF tool (issue 37, item 3): three collinear markers, as NDI's 8700248 stylus. A tip on
// their line is tracked, with TRE^2 = F^2/N + (2/3) F^2 D^2 / S (docs/math.md §23, "Five degrees
// of freedom"; computed here), the report says "5-DoF tool"; a target off the line is refused.
TEST(TreCli, AFiveDofToolTracksTargetsOnItsAxis) {
  ScratchDir scratch;
  scratch.write("stylus.json", R"({"points": [[0,0,0],[0,0,50],[0,0,105]]})");
  const nlohmann::json j =
      testing::run_json("tre stylus.json --target 0,0,-100 --fle-rms 0.25", scratch);
  ASSERT_TRUE(j["model"].contains("five_dof")) << j.dump();
  EXPECT_EQ(j["model"]["five_dof"]["axis"], nlohmann::json::parse("[0.0, 0.0, 1.0]"));
  const double centroid = 155.0 / 3.0;
  const double S =
      centroid * centroid + (50 - centroid) * (50 - centroid) + (105 - centroid) * (105 - centroid);
  const double D = 100.0 + centroid;
  const double expected = std::sqrt(0.25 * 0.25 / 3.0 + (2.0 / 3.0) * 0.25 * 0.25 * D * D / S);
  const nlohmann::json& t = j["targets"][0];
  EXPECT_NEAR(t["rms_isotropic"].get<double>(), expected, kTraceRounding * 1e3);
  EXPECT_NEAR(t["worst"]["rms"].get<double>(), expected, kTraceRounding * 1e3);
  EXPECT_TRUE(t["worst"]["certified"].get<bool>());
  const testing::CliRun text =
      run_vantage("tre stylus.json --target 0,0,-100 --fle-rms 0.25", scratch);
  EXPECT_EQ(text.status, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("5-DoF tool: its markers are collinear"));
  testing::expect_bad_input(
      run_vantage("tre stylus.json --target 0,3,-100 --fle-rms 0.25", scratch),
      "3 from the line of the tool's collinear markers: a 5-DoF tool");
}

}  // namespace
}  // namespace vantage
