// `vantage layout snap`: markers typed a little off (or inside) a cube moved onto its faces with
// the faces' outward normals, the written layout analysed on that body, a marker far from the
// body named in one warning, and bad input refused (exit 2, one line, nothing written).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.h"
#include "support/cube_mesh.h"

namespace vantage {
namespace {

using testing::BadCall;
using testing::CliRun;
using ::testing::HasSubstr;
using testing::run_json;
using testing::run_vantage;
using testing::ScratchDir;

// Coordinates of order 1 through the closest-point arithmetic and the JSON round trip.
constexpr double kExact = 1e-12;

// Four markers near the faces of the cube [-0.5, 0.5]^3: 0.03 outside +x, 0.03 inside +y, 0.02
// above and 0.01 below +z.
constexpr const char* kNearCube =
    R"({"points": [[0.53, 0.1, 0.2], [0.1, 0.47, -0.2], [-0.2, 0.1, 0.52], [0.3, -0.2, 0.49]],
        "names": ["m1", "m2", "m3", "m4"]})";

void expect_vector(const nlohmann::json& got, const Eigen::Vector3d& want,
                   const std::string& what) {
  ASSERT_EQ(got.size(), 3u) << what;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c].get<double>(), want(c), kExact) << what << c;
}

TEST(LayoutSnapCli, MarkersGoToTheNearestFaceWithItsOutwardNormal) {
  ScratchDir scratch;
  scratch.write("cube.obj", testing::obj_text(testing::centred_unit_cube()));
  scratch.write("near.json", kNearCube);
  std::filesystem::create_directory(scratch.dir() / "out");
  const nlohmann::json json = run_json(
      "layout snap near.json --body cube.obj --marker-diameter 0.02 --out out/snapped.json",
      scratch);
  const Eigen::Vector3d normals[4] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                      Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()};
  const Eigen::Vector3d surface[4] = {
      {0.5, 0.1, 0.2}, {0.1, 0.5, -0.2}, {-0.2, 0.1, 0.5}, {0.3, -0.2, 0.5}};
  const double moved[4] = {0.02, 0.04, 0.01, 0.02};  // |centre - marker|, d / 2 = 0.01 out
  ASSERT_EQ(json["markers"].size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const nlohmann::json& m = json["markers"][i];
    EXPECT_EQ(m["name"], "m" + std::to_string(i + 1));
    expect_vector(m["surface"], surface[i], "surface");
    expect_vector(m["normal"], normals[i], "normal");
    expect_vector(m["to"], surface[i] + 0.01 * normals[i], "to");
    EXPECT_NEAR(m["moved"].get<double>(), moved[i], kExact) << i;
  }
  EXPECT_NEAR(json["max_moved"].get<double>(), 0.04, kExact);
  // The written layout: on the body (its path relative to the file), the normals, the names.
  const nlohmann::json written =
      nlohmann::json::parse(testing::read_file(scratch.path("out/snapped.json")));
  EXPECT_EQ(written["visibility"]["body"], "../cube.obj");
  EXPECT_EQ(written["names"], nlohmann::json({"m1", "m2", "m3", "m4"}));
  for (int i = 0; i < 4; ++i) {
    expect_vector(written["normals"][i], normals[i], "written normal");
    expect_vector(written["points"][i], surface[i] + 0.01 * normals[i], "written point");
  }
  // analyze finds every marker on its body: no off-body or hidden-marker warning.
  const CliRun analyze = run_vantage("analyze out/snapped.json", scratch);
  EXPECT_EQ(analyze.err, "");
  // Snapped again without a diameter, each centre goes back to its surface point, 0.01 away;
  // the layout's own body is the default.
  const nlohmann::json again = run_json("layout snap out/snapped.json --out again.json", scratch);
  EXPECT_NEAR(again["max_moved"].get<double>(), 0.01, kExact);  // back to the surface, d = 0
}

TEST(LayoutSnapCli, AMarkerFarFromTheBodyIsNamedInOneWarning) {
  ScratchDir scratch;
  scratch.write("cube.obj", testing::obj_text(testing::centred_unit_cube()));
  std::string layout = kNearCube;
  layout.replace(layout.find("0.53, 0.1, 0.2"), 14, "3.00, 0.1, 0.2");
  scratch.write("far.json", layout);
  const CliRun run = run_vantage("layout snap far.json --body cube.obj --out s.json", scratch);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("1 marker(s) moved more than 5 % of the body's size (m1;"));
  EXPECT_THAT(run.out, HasSubstr("written: s.json"));
  EXPECT_TRUE(std::filesystem::exists(scratch.path("s.json")));
}

TEST(LayoutSnapCli, BadInputIsOneLineAndNothingIsWritten) {
  const BadCall calls[] = {
      {"negative diameter", kNearCube, "in.json --body cube.obj --out s.json --marker-diameter -1",
       "--marker-diameter"},
      // Was named "--body: snapped, points[0]: coordinates beyond +-1e150".
      {"a diameter wider than the body", kNearCube,
       "in.json --body cube.obj --out s.json --marker-diameter 1e300",
       "--marker-diameter: a sphere of diameter 1e+300 is wider than the whole body (size "
       "1.73205)"},
      {"no body", kNearCube, "in.json --out s.json", "--body: required: in.json names no body"},
      {"body missing", kNearCube, "in.json --body nothing.obj --out s.json", "--body: "},
      {"vectors", R"({"vectors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})",
       "in.json --body cube.obj --out s.json", "snapping needs marker positions"},
      {"not json", kNearCube, "in.json --body cube.obj --out s.csv", "--out: "},
      {"same point", R"({"points": [[0.6, 0, 0], [0.7, 0, 0], [0, 0.6, 0]]})",
       "in.json --body cube.obj --out s.json", "--body: snapped, "},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    ScratchDir scratch;
    scratch.write("cube.obj", testing::obj_text(testing::centred_unit_cube()));
    testing::run_bad_call("layout snap", call, scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("s.json")));
    EXPECT_FALSE(std::filesystem::exists(scratch.path("s.csv")));
  }
  ScratchDir scratch;
  scratch.write("cube.obj", testing::obj_text(testing::centred_unit_cube()));
  scratch.write("in.json", kNearCube);
  scratch.write("s.json", "keep me");
  testing::expect_bad_input(
      run_vantage("layout snap in.json --body cube.obj --out s.json", scratch), "--out: ");
  EXPECT_EQ(testing::read_file(scratch.path("s.json")), "keep me");
}

}  // namespace
}  // namespace vantage
