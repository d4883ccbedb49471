// `vantage crb` (issue 21; docs/math.md §22): the issue's JSON names, the text report's worst
// direction beside the affine bound, the bound at a direction against `vantage analyze`'s own
// affine answer, the distance sweep, and bad input (one line, exit 2, nothing written).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "vantage/analysis/common.h"

namespace vantage {
namespace {

using testing::BadCall;
using testing::CliRun;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

const std::string kCube =
    "'" + std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/apriltag_cube.yaml'";
const std::string kCamera = " --distance 2 --focal 900 --noise-px 0.3";
// JSON numbers are printed to round-trip, so a value read back is the value computed.
constexpr double kRoundTrip = 1e-12;
// The trace of three printed entries, a square root and a change of units: a few roundings.
constexpr double kTraceRounding = 1e-11;

TEST(CrbCli, JsonHasTheIssuesFields) {
  ScratchDir scratch;
  const nlohmann::json j =
      testing::run_json("crb " + kCube + kCamera + " --direction 0.3,0.2,0.9", scratch);
  for (const char* field : {"at_direction", "worst", "best", "trackable_fraction",
                            "affine_bound_deg", "camera", "percentiles", "sliver"}) {
    EXPECT_TRUE(j.contains(field)) << field;
  }
  for (const char* field :
       {"direction", "rot_rms_deg", "trans_rms", "covariance", "visible_markers"}) {
    EXPECT_TRUE(j["at_direction"].contains(field)) << field;
  }
  for (const char* field : {"direction", "rot_rms_deg", "trans_rms", "visible_markers"}) {
    EXPECT_TRUE(j["worst"].contains(field)) << field;
    EXPECT_TRUE(j["best"].contains(field)) << field;
  }
  for (const char* field : {"p50", "p95", "p99"}) EXPECT_TRUE(j["percentiles"].contains(field));
  const nlohmann::json& c = j["at_direction"]["covariance"];
  ASSERT_EQ(c.size(), 6u);
  double rot_trace = 0.0;
  for (int k = 3; k < 6; ++k) rot_trace += c[k][k].get<double>();
  EXPECT_NEAR(std::sqrt(rot_trace) * 180.0 / kPi, j["at_direction"]["rot_rms_deg"].get<double>(),
              kTraceRounding * j["at_direction"]["rot_rms_deg"].get<double>());
  EXPECT_GE(j["worst"]["rot_rms_deg"].get<double>(), j["percentiles"]["p99"].get<double>());
  EXPECT_LE(j["best"]["rot_rms_deg"].get<double>(), j["percentiles"]["p50"].get<double>());
  EXPECT_EQ(j["camera"]["focal"].get<double>(), 900.0);
}

TEST(CrbCli, AffineBoundIsTheAnalyzeAnswerOfTheSameLayout) {
  ScratchDir scratch;
  const nlohmann::json crb = testing::run_json("crb " + kCube + kCamera, scratch);
  const nlohmann::json analyze =
      testing::run_json("analyze " + kCube + " --no-crosscheck", scratch);
  const double expected = analyze.contains("visibility")
                              ? analyze["visibility"]["max_worst_case_error_deg"].get<double>()
                              : analyze["max_worst_case_error_deg"].get<double>();
  EXPECT_NEAR(crb["affine_bound_deg"].get<double>(), expected, kRoundTrip * expected);
}

TEST(CrbCli, TextReportShowsTheWorstBesideTheAffineBound) {
  ScratchDir scratch;
  const CliRun run = run_vantage("crb " + kCube + kCamera, scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_THAT(run.out, HasSubstr("worst direction"));
  EXPECT_THAT(run.out, HasSubstr("rot_rms"));
  EXPECT_THAT(run.out, HasSubstr("affine bound"));
}

// A row's worst is at least its median, or unbounded, and then no figure (docs/math.md §22).
void expect_worst_at_least_median(const nlohmann::json& row) {
  if (row["worst"]["unbounded"] == true) {
    EXPECT_TRUE(row["worst"]["rot_rms_deg"].is_null()) << row;
    EXPECT_FALSE(row["median"]["unbounded"].get<bool>()) << row;
    return;
  }
  EXPECT_GE(row["worst"]["rot_rms_deg"].get<double>(), row["median"]["rot_rms_deg"].get<double>());
}

TEST(CrbCli, DistanceSweepHasOneRowPerDistance) {
  ScratchDir scratch;
  const nlohmann::json j = testing::run_json(
      "crb " + kCube + kCamera + " --sweep-distance 1:4:4 --samples 1000", scratch);
  ASSERT_EQ(j["sweep_distance"].size(), 4u);
  EXPECT_EQ(j["sweep_distance"][0]["distance"].get<double>(), 1.0);
  EXPECT_EQ(j["sweep_distance"][3]["distance"].get<double>(), 4.0);
  for (const auto& row : j["sweep_distance"]) expect_worst_at_least_median(row);
}

// The cube's three tagged faces, each tiled k x k: the rows' counts and sizes follow the face's
// extent (its one 8 cm tag), and the tag's pixels are size * f / D.
TEST(CrbCli, TagSweepHasOneRowPerTiling) {
  ScratchDir scratch;
  const nlohmann::json j =
      testing::run_json("crb " + kCube + kCamera +
                            " --samples 1000 --sweep-tags --tags-per-side 1,2 --tag-fill "
                            "0.5,0.9",
                        scratch);
  const nlohmann::json& sweep = j["sweep_tags"];
  ASSERT_EQ(sweep["faces"].size(), 3u);
  ASSERT_EQ(sweep["rows"].size(), 4u);
  const double extent = sweep["faces"][0]["extent"].get<double>();
  const int per_side[] = {1, 1, 2, 2};
  const double fill[] = {0.5, 0.9, 0.5, 0.9};
  for (int r = 0; r < 4; ++r) {
    const nlohmann::json& row = sweep["rows"][r];
    EXPECT_EQ(row["tags_per_side"].get<int>(), per_side[r]);
    EXPECT_EQ(row["tags"].get<int>(), 3 * per_side[r] * per_side[r]);
    EXPECT_NEAR(row["tag_size"].get<double>(), fill[r] * extent / per_side[r], 1e-12);
    EXPECT_NEAR(row["tag_pixels"].get<double>(), row["tag_size"].get<double>() * 900 / 2, 1e-9);
    EXPECT_EQ(row["status"], "ok");
    expect_worst_at_least_median(row);
  }
  // Each face's extent is its own tag: fill 1 at one tag per side is the layout itself.
  const std::string flags = kCamera + " --samples 1000";
  const nlohmann::json own = testing::run_json("crb " + kCube + flags, scratch);
  const nlohmann::json itself = testing::run_json(
      "crb " + kCube + flags + " --sweep-tags --tags-per-side 1 --tag-fill 1", scratch);
  EXPECT_NEAR(itself["sweep_tags"]["rows"][0]["median"]["rot_rms_deg"].get<double>(),
              own["percentiles"]["p50"].get<double>(), 1e-9);
  EXPECT_EQ(itself["sweep_tags"]["rows"][0]["worst"]["unbounded"], own["worst"]["unbounded"]);
  if (own["worst"]["unbounded"] == false) {
    EXPECT_NEAR(itself["sweep_tags"]["rows"][0]["worst"]["rot_rms_deg"].get<double>(),
                own["worst"]["rot_rms_deg"].get<double>(), 1e-9);
  }
}

// Issue 36, item 5: at 1e5 (the cube is 1e-6 of the distance) every direction that sees enough
// markers fails the condition test. That was reported as "no sampled direction is trackable",
// exit 0, the same words as a layout that no direction sees; it is now said which, exit 1.
TEST(CrbCli, IllConditioningIsToldApartFromVisibility) {
  ScratchDir scratch;
  const CliRun far =
      run_vantage("crb " + kCube + " --distance 1e5 --focal 900 --noise-px 0.3", scratch);
  EXPECT_EQ(far.status, 1);
  EXPECT_THAT(far.out, HasSubstr("not trackable    ill_conditioned: "));
  EXPECT_THAT(far.err, HasSubstr("condition number exceeds 1e12"));
  EXPECT_EQ(testing::line_count(far.err), 1) << far.err;
  const CliRun far_json =
      run_vantage("crb " + kCube + " --distance 1e5 --focal 900 --noise-px 0.3 --json", scratch);
  EXPECT_EQ(far_json.status, 1);
  const nlohmann::json j = nlohmann::json::parse(far_json.out);
  EXPECT_EQ(j["status"], "ill_conditioned");
  EXPECT_THAT(j["message"].get<std::string>(), HasSubstr("not determined to first order"));
  EXPECT_TRUE(j["worst"].is_null());

  // Markers no direction sees (every cone faces away from the only direction the workspace
  // holds): untrackable, and said so.
  scratch.write("away.json", R"({"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
      "normals": [[0, 0, -1], [0, 0, -1], [0, 0, -1], [0, 0, -1]],
      "visibility": {"cone_half_angle_deg": 60, "min_visible": 3},
      "workspace": {"axis": [0, 0, 1], "half_angle_deg": 20}})");
  const CliRun away = run_vantage("crb " + scratch.path("away.json") + kCamera, scratch);
  EXPECT_EQ(away.status, 1);
  EXPECT_THAT(away.out, HasSubstr("not trackable    untrackable: "));
  EXPECT_THAT(away.err, HasSubstr("sees enough markers"));
  EXPECT_EQ(testing::line_count(away.err), 1) << away.err;
}

// Issue 36, item 4: a 0.2-degree workspace held none of the sphere's 10 000 sampled directions,
// so crb said untrackable and simulate refused ("no direction ... in 0 sampled directions"),
// although the cube is seen throughout it. It is sampled on its own cap (100 directions).
TEST(CrbCli, ATinyWorkspaceIsSampledOnItsOwnCap) {
  ScratchDir scratch;
  const CliRun crb = run_vantage("crb " + kCube + kCamera + " --workspace 1,1,1,0.2", scratch);
  EXPECT_EQ(crb.status, 0) << crb.err;
  EXPECT_THAT(crb.out, HasSubstr("100 directions sampled, trackable fraction 1, unbounded 0\n"));
  // The bound is flat over 0.2 degrees: the workspace's edge, not the bound, ends every cut, so
  // the worst is not a sliver (it was flagged, "0.14 deg across").
  EXPECT_THAT(crb.out, HasSubstr("sliver           no (the region within 2x of the worst reaches "
                                 "the workspace's edge along every cut)"));
  const CliRun simulate =
      run_vantage("simulate " + kCube + " --workspace 1,1,1,0.2 --trials 10", scratch);
  EXPECT_EQ(simulate.status, 0) << simulate.err;
}

TEST(CrbCli, BadInputIsOneLineNamingTheOption) {
  ScratchDir scratch;
  const BadCall calls[] = {
      {"zero noise", nullptr, "--distance 2 --focal 900 --noise-px 0", "--noise-px"},
      {"negative focal", nullptr, "--distance 2 --focal -900 --noise-px 1", "--focal"},
      {"inside the markers", nullptr, "--distance 0.01 --focal 900 --noise-px 1", "--distance"},
      {"bad direction", nullptr, "--distance 2 --focal 900 --noise-px 1 --direction 1,0",
       "--direction"},
      {"bad sweep", nullptr, "--distance 2 --focal 900 --noise-px 1 --sweep-distance 3:1:4",
       "--sweep-distance"},
      {"direction mode", R"({"vectors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})",
       "in.json --distance 2 --focal 900 --noise-px 1", "vectors"},
      {"tag fill above 1", nullptr,
       "--distance 2 --focal 900 --noise-px 1 --sweep-tags "
       "--tag-fill 0.5,1.2",
       "--tag-fill"},
      {"touching tags", nullptr,
       "--distance 2 --focal 900 --noise-px 1 --sweep-tags "
       "--tags-per-side 1,2 --tag-fill 1",
       "--tag-fill"},
      {"no tags per side", nullptr,
       "--distance 2 --focal 900 --noise-px 1 --sweep-tags "
       "--tags-per-side 0",
       "--tags-per-side"},
      // Issue 36: these were silently ignored without --sweep-tags.
      {"tags per side alone", nullptr, "--distance 2 --focal 900 --noise-px 1 --tags-per-side 2",
       "--tags-per-side: takes effect only with --sweep-tags"},
      {"tag fill alone", nullptr, "--distance 2 --focal 900 --noise-px 1 --tag-fill 0.5",
       "--tag-fill: takes effect only with --sweep-tags"},
      {"not tag corners", R"({"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]})",
       "in.json --distance 5 --focal 900 --noise-px 1 --sweep-tags", "names"},
      // Issue 36, item 5: f^2 / S^2 overflowed and the map said "no sampled direction is
      // trackable", exit 0.
      {"huge focal", nullptr, "--distance 2 --focal 1e300 --noise-px 0.3",
       "--focal: must be in [1e-50, 1e50] pixels"},
      {"tiny noise", nullptr, "--distance 2 --focal 900 --noise-px 1e-300",
       "--noise-px: must be in [1e-50, 1e50] pixels"},
      // F ~ (f / (S D))^2 overflowed inside those ranges (review).
      {"focal over noise", nullptr, "--distance 2 --focal 1e50 --noise-px 1e-50",
       "--noise-px: the focal length over the noise must be in [1e-12, 1e12]"},
      {"distance beyond 1e50", nullptr, "--distance 1e60 --focal 900 --noise-px 0.3",
       "--distance: must be in [1e-50, 1e50]"},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    const std::string file = call.file_text ? "" : kCube + " ";
    testing::run_bad_call("crb " + file, call, scratch);
  }
}

}  // namespace
}  // namespace vantage
