#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <vector>

#include "support/cli_runner.h"
#include "support/nlopt_build.h"
#include "support/sanitized.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kLayouts = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";
const std::string kTriad = kLayouts + "triad.json";
const std::string kFan = kLayouts + "coplanar_fan.json";
const std::string kNote3 = kLayouts + "note3_four_vectors.json";
const std::string kSatellite = kLayouts + "satellite.json";

// p-bar_min of Z = I (docs/math.md §12): sqrt(2/3).
const double kTriadPbar = std::sqrt(2.0 / 3.0);
// The global solver certifies t to 1e-9 and JSON carries doubles exactly (17 digits), so the
// same layout evaluated twice agrees to this.
constexpr double kSameLayout = 1e-9;
// Adding data never lowers p-bar_min; the values come from independent certified solves.
constexpr double kMonotone = 1e-9;

// cos(pi / (2 m)) computed twice: an ulp of a number below 1.
constexpr double kCosRounding = 1e-15;
// arccos of p-bars kSameLayout apart, in degrees: 57 x 1e-9 / sin(theta), far below this.
constexpr double kSameLayoutDeg = 1e-6;

using testing::run_json;

double ceiling(int m) { return std::cos(kPi / (2.0 * m)); }

// Contract fields of every report and the invariants between them.
void expect_contract(const nlohmann::json& json, int add) {
  for (const char* field : {"initial", "steps", "final_pbar_min", "coplanarity", "status"}) {
    ASSERT_TRUE(json.contains(field)) << field;
  }
  for (const char* field :
       {"pbar_min", "worst_viewpoints", "max_worst_case_error_deg", "ceiling", "n_vectors"}) {
    EXPECT_TRUE(json["initial"].contains(field)) << field;
  }
  for (const char* field : {"initial", "final", "nearly_coplanar"}) {
    EXPECT_TRUE(json["coplanarity"].contains(field)) << field;
  }
  ASSERT_EQ(json["steps"].size(), static_cast<size_t>(add));
  double previous = json["initial"]["pbar_min"].get<double>();
  for (const auto& step : json["steps"]) {
    for (const char* field : {"added", "pbar_min", "worst_viewpoints", "max_worst_case_error_deg",
                              "ceiling", "n_vectors", "improved", "note"}) {
      EXPECT_TRUE(step.contains(field)) << field;
    }
    const double pbar = step["pbar_min"].get<double>();
    EXPECT_GE(pbar, previous - kMonotone) << "a greedy step lowered p-bar_min";
    EXPECT_LE(pbar, step["ceiling"].get<double>() + kMonotone)
        << "above the ceiling (docs/math.md §15)";
    EXPECT_NEAR(step["ceiling"].get<double>(), ceiling(step["n_vectors"].get<int>()), kCosRounding);
    EXPECT_EQ(step["added"].size(), 3u);
    EXPECT_GE(step["worst_viewpoints"].size(), 1u);
    previous = pbar;
  }
  EXPECT_DOUBLE_EQ(json["final_pbar_min"].get<double>(), previous);
}

TEST(DesignCli, TriadPlusOneVectorStaysAtSqrtTwoThirds) {
  ScratchDir scratch;
  const auto json = run_json("design '" + kTriad + "' --add 1", scratch);
  expect_contract(json, 1);
  EXPECT_EQ(json["status"], "ok");
  EXPECT_NEAR(json["initial"]["pbar_min"].get<double>(), kTriadPbar, kSameLayout);
  EXPECT_EQ(json["initial"]["worst_viewpoints"].size(), 4u);  // (+-1, +-1, 1) / sqrt(3)
  EXPECT_EQ(json["initial"]["n_vectors"], 3);
  EXPECT_NEAR(json["final_pbar_min"].get<double>(), kTriadPbar, kSameLayout);
  const auto& step = json["steps"][0];
  EXPECT_FALSE(step["improved"].get<bool>());
  EXPECT_FALSE(step["single_vector_can_improve"].get<bool>());
  EXPECT_THAT(step["note"].get<std::string>(), HasSubstr("no single vector can raise"));
  EXPECT_EQ(step["n_vectors"], 4);
  if (!built_with_nlopt()) {
    EXPECT_EQ(json["direct_message"], "not run: built without NLopt");
    return;
  }
  // The direct optimiser cannot beat what no single vector can do.
  ASSERT_TRUE(json.contains("direct"));
  EXPECT_LE(json["direct"]["pbar_min"].get<double>(), kTriadPbar + kSameLayout);
  EXPECT_EQ(json["direct"]["added"].size(), 1u);
  EXPECT_TRUE(json["direct"].contains("method"));
}

TEST(DesignCli, CoplanarFanStartsAtItsCeilingAndIsFlagged) {
  ScratchDir scratch;
  const auto json = run_json("design '" + kFan + "' --add 2 --no-direct", scratch);
  expect_contract(json, 2);
  EXPECT_FALSE(json.contains("direct"));
  // Three coplanar vectors 60 degrees apart reach cos(pi/6), the ceiling for m = 3.
  EXPECT_NEAR(json["initial"]["pbar_min"].get<double>(), ceiling(3), kSameLayout);
  EXPECT_NEAR(json["initial"]["ceiling"].get<double>(), ceiling(3), kCosRounding);
  EXPECT_LT(json["coplanarity"]["initial"].get<double>(), 1e-12);
  // The augmenter leaves the plane: the ambiguity measure rises off zero.
  EXPECT_GT(json["coplanarity"]["final"].get<double>(), 0.1);
  EXPECT_FALSE(json["coplanarity"]["nearly_coplanar"].get<bool>());
  // The fan sits at its ceiling, so the first addition (off the plane) can and does raise it.
  EXPECT_TRUE(json["steps"][0]["improved"].get<bool>());
  EXPECT_GT(json["steps"][0]["pbar_min"].get<double>(), ceiling(3));
  // Every step improves, or sits at its ceiling, or says (exactly) that no vector could.
  for (const auto& step : json["steps"]) {
    const bool at_ceiling = step["pbar_min"].get<double>() >= step["ceiling"].get<double>() - 1e-9;
    const bool proven_stuck = !step["single_vector_can_improve"].get<bool>();
    EXPECT_TRUE(step["improved"].get<bool>() || at_ceiling || proven_stuck) << step.dump();
    if (proven_stuck) {
      EXPECT_THAT(step["note"].get<std::string>(), HasSubstr("no single vector can raise"));
    }
  }
}

TEST(DesignCli, GreedyStepsNeverLowerPbarAndStayBelowTheCeiling) {
  ScratchDir scratch;
  const auto json = run_json("design '" + kNote3 + "' --add 3 --no-direct", scratch);
  expect_contract(json, 3);
  EXPECT_GT(json["final_pbar_min"].get<double>(), json["initial"]["pbar_min"].get<double>());
}

TEST(DesignCli, WrittenLayoutReanalysesToEveryReportedStep) {
  ScratchDir scratch;
  const auto two =
      run_json("design '" + kNote3 + "' --add 2 --no-direct --write two.json", scratch);
  const auto one =
      run_json("design '" + kNote3 + "' --add 1 --no-direct --write one.json", scratch);
  EXPECT_EQ(two["written"], "two.json");
  const auto file = nlohmann::json::parse(testing::read_file(scratch.path("two.json")));
  ASSERT_EQ(file["vectors"].size(), 6u);
  for (int j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(file["vectors"][4][j].get<double>(),
                     two["steps"][0]["added"][j].get<double>());
  }
  // The greedy run is deterministic, so the K = 1 file holds step 1 of the K = 2 run.
  const auto again_two = run_json("design two.json --add 1 --no-direct", scratch);
  const auto again_one = run_json("design one.json --add 1 --no-direct", scratch);
  EXPECT_NEAR(again_two["initial"]["pbar_min"].get<double>(), two["final_pbar_min"].get<double>(),
              kSameLayout);
  EXPECT_NEAR(again_one["initial"]["pbar_min"].get<double>(),
              two["steps"][0]["pbar_min"].get<double>(), kSameLayout);
  EXPECT_NEAR(again_two["initial"]["max_worst_case_error_deg"].get<double>(),
              two["steps"][1]["max_worst_case_error_deg"].get<double>(), kSameLayoutDeg);
}

// Four arm tips and a top marker (issue 17's drone; tests/design/augment_search_test.cc).
// The point search of the tests whose property holds at any budget: under the sanitizers it stops
// at 30 000 evaluations (5 s of the drone's --add 2 instead of 26 s).
const std::string kPointSearch = testing::kUnderSanitizer ? " --search-budget 30000" : "";

constexpr const char* kDrone = R"({"name": "drone", "points": [
  [0.1263, 0.1632, -0.0053], [-0.1183, 0.1462, -0.0111], [-0.1448, -0.1299, 0.0016],
  [0.1499, -0.1345, -0.0101], [0.0280, -0.0209, 0.0431]]})";

TEST(DesignCli, PointStepsAreTheSameWhereverTheyRunFrom) {
  // --add 2 in one run, and --add 1 on the layout --add 1 wrote: the same second marker.
  ScratchDir scratch;
  scratch.write("drone.json", kDrone);
  const auto two = run_json("design drone.json --add 2 --no-direct" + kPointSearch, scratch);
  run_json("design drone.json --add 1 --no-direct --write one.json" + kPointSearch, scratch);
  const auto again = run_json("design one.json --add 1 --no-direct" + kPointSearch, scratch);
  EXPECT_EQ(two["steps"][1]["added"], again["steps"][0]["added"]);
  EXPECT_EQ(two["steps"][1]["pbar_min"], again["steps"][0]["pbar_min"]);
  EXPECT_EQ(two["final_pbar_min"], again["final_pbar_min"]);
}

TEST(DesignCli, TheDefaultBoxFindsAtLeastWhatTheMarkersOwnBoxFinds) {
  ScratchDir scratch;
  scratch.write("drone.json", kDrone);
  const auto inner = run_json("design drone.json --add 1 --no-direct --margin 0", scratch);
  const auto grown = run_json("design drone.json --add 1 --no-direct", scratch);
  EXPECT_GE(grown["final_pbar_min"].get<double>(),
            inner["final_pbar_min"].get<double>() - kMonotone);
  EXPECT_TRUE(grown["steps"][0]["search"]["closed"].get<bool>());
  EXPECT_LE(grown["steps"][0]["search"]["t_lower"].get<double>(),
            grown["steps"][0]["t"].get<double>());
}

// Eq. (24.1) by brute force over every two distinct pairs of the JSON points.
double brute_distance_difference_cli(const nlohmann::json& points) {
  std::vector<double> d;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      double s = 0.0;
      for (int r = 0; r < 3; ++r) {
        const double e = points[i][r].get<double>() - points[j][r].get<double>();
        s += e * e;
      }
      d.push_back(std::sqrt(s));
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < d.size(); ++a) {
    for (std::size_t b = 0; b < d.size(); ++b) {
      if (a != b) best = std::min(best, std::abs(d[a] - d[b]));
    }
  }
  return best;
}

TEST(DesignCli, MinDistanceDifferenceIsKeptByTheWrittenLayout) {
  // The drone's own distances differ by 0.0037; its free --add 2 squeezes two closer than 0.002.
  constexpr double kGap = 0.002;
  ScratchDir scratch;
  scratch.write("drone.json", kDrone);
  const auto free =
      run_json("design drone.json --add 2 --no-direct --write free.json" + kPointSearch, scratch);
  EXPECT_EQ(free["min_distance_difference"].get<double>(), 0.0);
  const double free_gap = brute_distance_difference_cli(
      nlohmann::json::parse(testing::read_file(scratch.path("free.json")))["points"]);
  ASSERT_LT(free_gap, kGap) << "the free run must break the gap for the test to mean anything";
  EXPECT_NEAR(free["final_distance_difference"].get<double>(), free_gap, 1e-12);

  const auto kept = run_json(
      "design drone.json --add 2 --no-direct --min-distance-difference 0.002 --write kept.json" +
          kPointSearch,
      scratch);
  EXPECT_EQ(kept["status"], "ok");
  EXPECT_EQ(kept["min_distance_difference"].get<double>(), kGap);
  const double kept_gap = brute_distance_difference_cli(
      nlohmann::json::parse(testing::read_file(scratch.path("kept.json")))["points"]);
  EXPECT_GE(kept_gap, kGap);
  EXPECT_NEAR(kept["final_distance_difference"].get<double>(), kept_gap, 1e-12);
}

TEST(DesignCli, NoFeasibleAdditionFailsAndWritesNothing) {
  // A triangle with sides 2.9, 1, 2 in its own box: six distances at most the box's diagonal
  // (2.92) cannot be 0.8 apart (5 x 0.8 > 2.92), so no fourth marker keeps 0.8.
  ScratchDir scratch;
  scratch.write("tri.json", R"({"points": [[0,0,0],[2.9,0,0],[0.932759,0.360363,0]]})");
  const testing::CliRun run = run_vantage(
      "design tri.json --add 1 --margin 0 --search-budget 30000 --min-distance-difference 0.8 "
      "--write out.json --json",
      scratch);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("no_feasible_addition"));
  EXPECT_FALSE(std::filesystem::exists(scratch.path("out.json")));
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["status"], "no_feasible_addition");
  EXPECT_TRUE(json["steps"].empty());
}

TEST(DesignCli, LimitsComeFromTheEstimatedTimeNotFromCounts) {
  // 30 markers --add 3 (528 data vectors) was refused at 200 data vectors although it takes a
  // few seconds; its estimate is 7.5 s of the 30 s budget (design/limits.h). --add 20 on the same
  // layout is estimated at 76 s and refused, before any work, unless --allow-large.
  ScratchDir scratch;
  nlohmann::json layout;
  std::mt19937 rng(30);
  std::uniform_real_distribution<double> box(-1.0, 1.0);
  for (int k = 0; k < 30; ++k) layout["points"].push_back({box(rng), box(rng), box(rng)});
  scratch.write("rand30.json", layout.dump());
  // The 3 additions run in 3 s here; under the sanitizers one (n markers give n (n - 1) / 2
  // data vectors).
  const int add = testing::kUnderSanitizer ? 1 : 3;
  const auto json =
      run_json("design rand30.json --add " + std::to_string(add) + " --no-direct", scratch);
  ASSERT_EQ(json["steps"].size(), static_cast<std::size_t>(add));
  EXPECT_EQ(json["steps"][add - 1]["n_vectors"], (30 + add) * (29 + add) / 2);
  testing::expect_bad_input(run_vantage("design rand30.json --add 20", scratch),
                            "rand30.json: --add 20 on 1225 data vectors: about 77 s of CPU exceeds "
                            "the budget of 30 s");
  // A larger search budget is part of the estimate: 3 x (1.5 s + 1.1e-6 s x 99 550 000 + 1.9e-3 s
  // x 528).
  testing::expect_bad_input(
      run_vantage("design rand30.json --add 3 --search-budget 100000000", scratch),
      "about 336 s of CPU exceeds the budget of 30 s");
  testing::expect_bad_input(run_vantage("design rand30.json --add 1 --search-budget -1", scratch),
                            "--search-budget: must be >= 0");
}

TEST(DesignCli, CandidatesOnlyPicksACandidateAndWritesItAsAMarker) {
  ScratchDir scratch;
  // The satellite has a body: design says in one line that it searches seen whole.
  const auto run = run_vantage(
      "design '" + kSatellite + "' --add 1 --candidates-only --no-direct --write out.json --json",
      scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("vantage: warning: design: "));
  const auto json = nlohmann::json::parse(run.out);
  expect_contract(json, 1);
  EXPECT_EQ(json["mode"], "points");
  const auto& step = json["steps"][0];
  ASSERT_TRUE(step.contains("candidate_index"));
  const auto layout = nlohmann::json::parse(testing::read_file(kSatellite));
  const int c = step["candidate_index"].get<int>();
  EXPECT_EQ(step["added"], layout["candidates"][c]);
  const auto file = nlohmann::json::parse(testing::read_file(scratch.path("out.json")));
  ASSERT_EQ(file["points"].size(), layout["points"].size() + 1);
  EXPECT_EQ(file["points"].back(), layout["candidates"][c]);
  // The used candidate is a marker now, not a place for another one.
  EXPECT_EQ(file["candidates"].size(), layout["candidates"].size() - 1);
  const auto again =
      run_json("design out.json --seen-whole --add 1 --candidates-only --no-direct", scratch);
  EXPECT_NEAR(again["initial"]["pbar_min"].get<double>(), json["final_pbar_min"].get<double>(),
              kSameLayout);
}

// Issue 36, item 5: design augmented a body layout seen whole (p-bar_min 0.931 where analyze
// reports the body's value) and added markers without normals, saying neither.
TEST(DesignCli, ABodyLayoutIsSaidToBeDesignedSeenWhole) {
  ScratchDir scratch;
  const std::string drone = "design '" + kLayouts + "drone.json' --add 1 --no-direct";
  const auto run = run_vantage(drone, scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("vantage: warning: design: "));
  EXPECT_THAT(run.err, HasSubstr("does not use"));
  const auto seen_whole = run_vantage(drone + " --seen-whole", scratch);
  EXPECT_EQ(seen_whole.status, 0);
  EXPECT_EQ(seen_whole.err, "");
  EXPECT_EQ(seen_whole.out, run.out);  // the same design: the warning says what was done
}

TEST(DesignCli, WriteRefusesToOverwriteUnlessTold) {
  ScratchDir scratch;
  const std::string original = testing::read_file(kTriad);
  const std::string input = scratch.write("in.json", original);
  scratch.write("taken.json", "keep me");

  auto run = run_vantage("design in.json --add 1 --no-direct --write taken.json", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("exists already"));
  EXPECT_EQ(testing::read_file(scratch.path("taken.json")), "keep me");

  run = run_vantage("design in.json --add 1 --no-direct --write in.json", scratch);
  EXPECT_EQ(run.status, 2);
  EXPECT_THAT(run.err, HasSubstr("is the input layout"));
  EXPECT_EQ(testing::read_file(input), original);

  run = run_vantage("design in.json --add 1 --no-direct --write taken.json --overwrite", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(testing::read_file(scratch.path("taken.json")))["vectors"].size(),
            4u);
  EXPECT_THAT(run.out, HasSubstr("written: taken.json"));
}

TEST(DesignCli, ReadableReportHasTheStepTable) {
  ScratchDir scratch;
  const auto run = run_vantage("design '" + kTriad + "' --add 1 --no-direct", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  for (const char* text : {"step", "added", "pbar_min", "max err deg", "ceiling", "note",
                           "0.816497", "0.923880", "no single vector can raise", "coplanarity"}) {
    EXPECT_THAT(run.out, HasSubstr(text));
  }
}

TEST(DesignCli, HelpExitsZero) {
  ScratchDir scratch;
  const auto run = run_vantage("design --help", scratch);
  EXPECT_EQ(run.status, 0);
  for (const char* option : {"--add", "--candidates-only", "--margin", "--no-direct", "--write",
                             "--overwrite", "--json"}) {
    EXPECT_THAT(run.out, HasSubstr(option));
  }
}

using testing::BadCall;

class DesignCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(DesignCliBadInput, OneErrorLineExitTwoNothingWritten) {
  // Every call also asks for --write out.json: nothing may be written.
  ScratchDir scratch;
  testing::run_bad_call("design", GetParam(), scratch);
  EXPECT_FALSE(std::filesystem::exists(scratch.path("out.json")));
}

constexpr const char* kTriadText = R"({"vectors": [[1,0,0],[0,1,0],[0,0,1]]})";
constexpr const char* kPointsWithCandidates =
    R"({"points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "candidates": [[1,1,1],[1,0,0]]})";

const BadCall kBadCalls[] = {
    {"NoLayout", nullptr, "--add 1 --write out.json", "LAYOUT is required"},
    {"MissingFile", nullptr, "in.json --add 1 --write out.json", "in.json: cannot open file"},
    {"NotJson", "{", "in.json --add 1 --write out.json --json", "in.json: not valid JSON"},
    {"OneVector", R"({"vectors": [[1,0,0]]})", "in.json --add 1 --write out.json", "vectors"},
    {"ZeroVector", R"({"vectors": [[1,0,0],[0,0,0]]})", "in.json --add 1 --write out.json",
     "vectors[1]"},
    {"NoAdd", kTriadText, "in.json --write out.json", "--add is required"},
    {"AddZero", kTriadText, "in.json --add 0 --write out.json", "--add: must be >= 1"},
    {"AddNegative", kTriadText, "in.json --add -2 --write out.json", "--add"},
    {"AddNotANumber", kTriadText, "in.json --add two --write out.json", "--add"},
    {"NegativeMargin", kTriadText, "in.json --add 1 --margin -0.5 --write out.json",
     "--margin: must be in [0, 100]"},
    {"CandidatesOnlyWithoutCandidates", kTriadText,
     "in.json --add 1 --candidates-only --write out.json",
     "--candidates-only: needs a layout with candidates"},
    {"MoreThanTheCandidates", kPointsWithCandidates,
     "in.json --add 3 --candidates-only --write out.json", "exceeds the 2 candidates"},
    {"CandidateOnAMarker", kPointsWithCandidates,
     "in.json --add 1 --candidates-only --write out.json",
     "candidates[1]: coincides with points[1]"},
    {"OverwriteWithoutWrite", kTriadText, "in.json --add 1 --overwrite", "--overwrite"},
    {"WriteIntoMissingDirectory", kTriadText, "in.json --add 1 --write nowhere/out.json",
     "does not exist"},
    {"NegativeGap", kDrone, "in.json --add 1 --min-distance-difference -0.1 --write out.json",
     "--min-distance-difference: must be a finite number >= 0"},
    {"InfiniteGap", kDrone, "in.json --add 1 --min-distance-difference inf --write out.json",
     "--min-distance-difference"},
    {"NanGap", kDrone, "in.json --add 1 --min-distance-difference nan --write out.json",
     "--min-distance-difference"},
    {"GapNotANumber", kDrone, "in.json --add 1 --min-distance-difference wide --write out.json",
     "--min-distance-difference"},
    {"GapOnVectors", kTriadText, "in.json --add 1 --min-distance-difference 0.1 --write out.json",
     "in.json: --min-distance-difference: needs a point layout"},
    {"GapTheLayoutBreaks", kDrone,
     "in.json --add 1 --min-distance-difference 0.01 --write out.json",
     "in.json: --min-distance-difference: the layout's own distances"},
};

INSTANTIATE_TEST_SUITE_P(DesignCli, DesignCliBadInput, ::testing::ValuesIn(kBadCalls),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vantage
