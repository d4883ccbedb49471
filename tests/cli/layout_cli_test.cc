// `vantage layout board` and the layout formats (CSV, AprilTag YAML) through analyze, design
// and weights.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"

namespace vantage {
namespace {

using testing::BadCall;
using ::testing::HasSubstr;
using testing::run_json;
using testing::run_vantage;
using testing::ScratchDir;

// Board coordinates are products of small integers and the square size: a few ulps.
constexpr double kCoordinate = 1e-12;
// The same layout read from two formats gives the same analysis up to the solver's rounding.
constexpr double kSameAnalysis = 1e-12;

// The global search certifies t, and so the viewpoint and p-bar, to 1e-9.
constexpr double kCertified = 1e-9;

const std::string kLayouts = std::string(VANTAGE_SOURCE_DIR) + "/examples/layouts/";

nlohmann::json points_of(const ScratchDir& scratch, const std::string& name) {
  return nlohmann::json::parse(testing::read_file(scratch.path(name)))["points"];
}

TEST(LayoutBoardCli, ChessboardInnerCornersStartAtTheOrigin) {
  ScratchDir scratch;
  const auto json = run_json(
      "layout board --type chessboard --rows 4 --cols 5 --square 0.03 --out board.json", scratch);
  EXPECT_EQ(json["n_points"], 12);  // (4 - 1) x (5 - 1) inner corners
  EXPECT_EQ(json["written"], "board.json");
  const auto points = points_of(scratch, "board.json");
  ASSERT_EQ(points.size(), 12u);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      const auto& p = points[i * 4 + j];
      EXPECT_NEAR(p[0].get<double>(), 0.03 * j, kCoordinate);
      EXPECT_NEAR(p[1].get<double>(), 0.03 * i, kCoordinate);
      EXPECT_EQ(p[2].get<double>(), 0.0);
    }
  }
}

TEST(LayoutBoardCli, CharucoCornersAreOffsetByOneSquare) {
  ScratchDir scratch;
  const auto json = run_json(
      "layout board --type charuco --rows 5 --cols 7 --square 0.04 --marker 0.03 --out c.json",
      scratch);
  EXPECT_EQ(json["n_points"], 24);
  EXPECT_EQ(json["marker"], 0.03);
  const auto points = points_of(scratch, "c.json");
  EXPECT_NEAR(points[0][0].get<double>(), 0.04, kCoordinate);
  EXPECT_NEAR(points[0][1].get<double>(), 0.04, kCoordinate);
  EXPECT_NEAR(points[23][0].get<double>(), 0.04 * 6, kCoordinate);
  EXPECT_NEAR(points[23][1].get<double>(), 0.04 * 4, kCoordinate);
}

TEST(LayoutBoardCli, AprilgridFollowsKalibrsCornerGrid) {
  ScratchDir scratch;
  const double s = 0.088;
  const double g = 0.3;
  const auto json = run_json(
      "layout board --type aprilgrid --rows 2 --cols 3 --square 0.088 --out grid.json", scratch);
  EXPECT_EQ(json["n_points"], 24);  // 2 x 3 tags, four corners each
  EXPECT_EQ(json["spacing"], g);
  const auto points = points_of(scratch, "grid.json");
  // Kalibr: 4 rows x 6 columns of corners; point (r, c) at
  // (floor(c/2) (1 + g) s + (c mod 2) s, floor(r/2) (1 + g) s + (r mod 2) s).
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 6; ++c) {
      const auto& p = points[r * 6 + c];
      EXPECT_NEAR(p[0].get<double>(), (c / 2) * (1 + g) * s + (c % 2) * s, kCoordinate);
      EXPECT_NEAR(p[1].get<double>(), (r / 2) * (1 + g) * s + (r % 2) * s, kCoordinate);
    }
  }
  // Each tag's four corners span a square of side s.
  EXPECT_NEAR(points[1][0].get<double>() - points[0][0].get<double>(), s, kCoordinate);
  EXPECT_NEAR(points[2][0].get<double>() - points[1][0].get<double>(), g * s, kCoordinate);
}

TEST(LayoutBoardCli, BoardIsAnalysedAsACoplanarLayout) {
  ScratchDir scratch;
  run_json("layout board --type chessboard --rows 3 --cols 4 --square 1 --out b.json", scratch);
  const auto json = run_json("analyze b.json", scratch);
  EXPECT_EQ(json["mode"], "points");
  EXPECT_EQ(json["n_vectors"], 15);  // 6 corners -> 15 free vectors
  // All free vectors lie in z = 0, so the viewpoint along the board's normal sees them whole
  // and the worst viewpoint lies in the board's plane.
  EXPECT_NEAR(json["worst_viewpoint"][2].get<double>(), 0.0, kCertified);
}

const BadCall kBadBoards[] = {
    {"ChessboardTooFewRows", nullptr, "--type chessboard --rows 2 --cols 5 --square 1 --out b.json",
     "--rows: must be in [3, 1000]"},
    {"AprilgridNoTags", nullptr, "--type aprilgrid --rows 0 --cols 5 --square 1 --out b.json",
     "--rows: must be in [1, 1000]"},
    {"ZeroSquare", nullptr, "--type charuco --rows 4 --cols 5 --square 0 --out b.json",
     "--square: must be a positive finite length"},
    {"MarkerOnChessboard", nullptr,
     "--type chessboard --rows 4 --cols 5 --square 1 --marker 0.5 --out b.json",
     "--marker: only for charuco"},
    {"MarkerTooLarge", nullptr,
     "--type charuco --rows 4 --cols 5 --square 1 --marker 1 --out b.json",
     "--marker: must be in (0, square)"},
    {"NegativeSpacing", nullptr,
     "--type aprilgrid --rows 4 --cols 5 --square 1 --spacing -1 --out b.json",
     "--spacing: must be in (0, 10]"},
    {"UnknownType", nullptr, "--type checker --rows 4 --cols 5 --square 1 --out b.json", "--type"},
    {"CsvOut", nullptr, "--type chessboard --rows 4 --cols 5 --square 1 --out b.csv",
     "--out: b.csv: layouts are written as JSON"},
    {"NoOut", nullptr, "--type chessboard --rows 4 --cols 5 --square 1", "--out"},
    {"ExistingOut", "{}", "--type chessboard --rows 4 --cols 5 --square 1 --out in.json",
     "in.json: exists already"},
};

class LayoutBoardCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(LayoutBoardCliBadInput, OneErrorLineExitTwoNothingWritten) {
  ScratchDir scratch;
  testing::run_bad_call("layout board", GetParam(), scratch);
  EXPECT_FALSE(std::filesystem::exists(scratch.path("b.json")));
  EXPECT_FALSE(std::filesystem::exists(scratch.path("b.csv")));
  if (GetParam().file_text) {
    EXPECT_EQ(testing::read_file(scratch.path("in.json")), "{}");
  }
}

INSTANTIATE_TEST_SUITE_P(LayoutBoardCli, LayoutBoardCliBadInput, ::testing::ValuesIn(kBadBoards),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(LayoutFormatsCli, CsvAnalysesLikeTheSameLayoutInJson) {
  ScratchDir scratch;
  scratch.write("same.json",
                R"({"points": [[0,0,0],[0.12,0,0.01],[-0.045,0.06,0],[-0.04,-0.075,0.005],)"
                R"([0.01,0.015,0.085]], "weights": [1, 1, 0.5, 1, 0.5]})");
  const auto csv = run_json("analyze '" + kLayouts + "mocap_rigid_body.csv'", scratch);
  const auto json = run_json("analyze same.json", scratch);
  EXPECT_EQ(csv["name"], "mocap_rigid_body");
  EXPECT_NEAR(csv["pbar_min"].get<double>(), json["pbar_min"].get<double>(), kSameAnalysis);
  ASSERT_EQ(csv["swaps"].size(), json["swaps"].size());
  EXPECT_NEAR(csv["swaps"][0]["error_deg"].get<double>(),
              json["swaps"][0]["error_deg"].get<double>(), kSameAnalysis);
}

TEST(LayoutFormatsCli, AprilTagBundleAnalysesItsCornersOrCentres) {
  ScratchDir scratch;
  const std::string file = "'" + kLayouts + "apriltag_cube.yaml'";
  const auto corners = run_json("analyze " + file, scratch);
  EXPECT_EQ(corners["name"], "cube");
  EXPECT_EQ(corners["n_vectors"], 66);  // 12 corners
  const auto centres = run_json("analyze " + file + " --tag-points centres", scratch);
  EXPECT_EQ(centres["n_vectors"], 3);
  // The three centres are (0.05, 0, 0), (0, 0.05, 0), (0, 0, 0.05): their free vectors are
  // the coplanar fan of three directions 60 degrees apart, whose worst case is p-bar = 0.866.
  EXPECT_NEAR(centres["pbar_min"].get<double>(), std::sqrt(3.0) / 2, kCertified);
}

TEST(LayoutFormatsCli, FormatOverridesTheExtension) {
  ScratchDir scratch;
  scratch.write("markers.txt", "a,0,0,0\nb,1,0,0\nc,0,1,0\nd,0,0,1\n");
  const auto json = run_json("weights markers.txt --format csv", scratch);
  EXPECT_EQ(json["mode"], "points");
  EXPECT_EQ(json["n"], 4);
}

TEST(LayoutFormatsCli, DesignOnACsvWritesJson) {
  ScratchDir scratch;
  const auto json =
      run_json("design '" + kLayouts + "mocap_rigid_body.csv' --add 1 --no-direct --write out.json",
               scratch);
  EXPECT_EQ(json["written"], "out.json");
  const auto written = nlohmann::json::parse(testing::read_file(scratch.path("out.json")));
  EXPECT_EQ(written["points"].size(), 6u);
}

const BadCall kBadFiles[] = {
    {"CsvBadNumber", nullptr, "bad.csv", "bad.csv: line 2 (b), y: expected a finite number"},
    {"YamlMissingSize", nullptr, "bad.yaml",
     "bad.yaml: tag_bundles[0].layout[0]: missing field \"size\""},
    {"UnknownExtension", nullptr, "bad.txt", "bad.txt: cannot tell the layout format"},
    {"BadFormatName", nullptr, "bad.csv --format xml", "--format"},
    {"TwoBundles", nullptr, "two.yaml", "choose one with --bundle (a, b)"},
    {"NoSuchBundle", nullptr, "two.yaml --bundle c", "no bundle named \"c\""},
};

class LayoutFormatsCliBadInput : public ::testing::TestWithParam<BadCall> {};

TEST_P(LayoutFormatsCliBadInput, EveryReaderReportsFileRowAndExitsTwo) {
  ScratchDir scratch;
  scratch.write("bad.csv", "a,0,0,0\nb,1,x,0\nc,0,1,0\n");
  scratch.write("bad.yaml", "tag_bundles:\n  - name: b\n    layout:\n      - {id: 0, x: 0}\n");
  scratch.write("bad.txt", "a,0,0,0\n");
  const std::string tag = "{id: 0, size: 1, x: 0, y: 0, z: 0, qw: 1, qx: 0, qy: 0, qz: 0}";
  scratch.write("two.yaml", "tag_bundles:\n  - {name: a, layout: [" + tag +
                                "]}\n  - {name: b, "
                                "layout: [" +
                                tag + "]}\n");
  for (const char* command : {"analyze", "design", "weights"}) {
    BadCall call = GetParam();
    const std::string args = std::string(call.args) + (command[0] == 'd' ? " --add 1" : "");
    call.args = args.c_str();
    testing::run_bad_call(command, call, scratch);
  }
}

INSTANTIATE_TEST_SUITE_P(LayoutFormatsCli, LayoutFormatsCliBadInput, ::testing::ValuesIn(kBadFiles),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace vantage
