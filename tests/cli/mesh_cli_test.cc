// `vantage analyze` of a layout with a body: the "mesh" object of --json, the one warning line
// for a body that is open or wound inconsistently, and bodies that cannot be read right (a
// vertex that is not finite, a PLY header that claims more than its file holds): exit 2, one
// line, nothing written.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.h"
#include "support/cube_mesh.h"

namespace vantage {
namespace {

using testing::CliRun;
using ::testing::HasSubstr;
using testing::run_vantage;
using testing::ScratchDir;

// Four markers on the faces of the cube [-0.5, 0.5]^3, each with its face's normal.
constexpr const char* kOnCube =
    R"({"points": [[0.5, 0.1, 0.2], [0.1, 0.5, -0.2], [-0.2, 0.1, 0.5], [0.3, -0.2, 0.5]],
        "normals": [[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 1]],
        "visibility": {"cone_half_angle_deg": 80, "body": "cube.obj"}})";

TEST(MeshCli, ClosedBodyGetsItsMeshObjectAndNoWarning) {
  ScratchDir scratch;
  scratch.write("cube.obj", testing::obj_text(testing::centred_unit_cube()));
  scratch.write("on_cube.json", kOnCube);
  const nlohmann::json json = testing::run_json("analyze on_cube.json", scratch);
  ASSERT_TRUE(json.contains("mesh"));
  const nlohmann::json& mesh = json["mesh"];
  EXPECT_EQ(mesh["triangles"], 12);
  EXPECT_EQ(mesh["vertices"], 8);
  EXPECT_EQ(mesh["closed"], true);
  EXPECT_EQ(mesh["manifold"], true);
  EXPECT_EQ(mesh["consistently_wound"], true);
  EXPECT_EQ(mesh["boundary_edges"], 0);
  EXPECT_EQ(mesh["bounding_box_size"], nlohmann::json::array({1.0, 1.0, 1.0}));
  EXPECT_EQ(mesh["units_hint"], "metres");
  const CliRun text = run_vantage("analyze on_cube.json", scratch);
  EXPECT_EQ(text.status, 0);
  EXPECT_EQ(text.err, "");
}

TEST(MeshCli, LayoutWithoutBodyHasNoMeshObject) {
  ScratchDir scratch;
  scratch.write("corner.json", R"({"points": [[0.5, 0.1, 0.2], [0.1, 0.5, -0.2], [-0.2, 0.1, 0.5]],
                                   "normals": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})");
  EXPECT_FALSE(testing::run_json("analyze corner.json", scratch).contains("mesh"));
}

TEST(MeshCli, OpenAndMiswoundBodyGivesOneWarningLine) {
  ScratchDir scratch;
  scratch.write("cube.obj",
                testing::obj_text(testing::centred_unit_cube(), /*missing=*/0, /*flipped=*/5));
  scratch.write("on_cube.json", kOnCube);
  for (const char* json : {"", " --json"}) {
    const CliRun run = run_vantage(std::string("analyze on_cube.json") + json, scratch);
    EXPECT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(testing::line_count(run.err), 1) << run.err;
    EXPECT_EQ(run.err,
              "vantage: warning: body cube.obj is open (3 boundary edges) and 1 triangle is wound "
              "against its neighbours: occlusion and sampled normals may be wrong\n");
  }
  const nlohmann::json mesh =
      nlohmann::json::parse(run_vantage("analyze on_cube.json --json", scratch).out)["mesh"];
  EXPECT_EQ(mesh["closed"], false);
  EXPECT_EQ(mesh["consistently_wound"], false);
  EXPECT_EQ(mesh["inconsistent_edges"], 3);
  EXPECT_EQ(mesh["triangles_against_neighbours"], 1);
}

TEST(MeshCli, BodiesThatCannotBeReadRightAreRefused) {
  const struct {
    const char* body;
    const char* text;
    const char* expected;
  } cases[] = {
      {"cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 nan 0\nf 1 3 2\nf 1 2 4\nf 2 5 4\n",
       "cube.obj: triangle[2]: vertex 1 is not finite"},
      {"cube.ply",
       "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
       "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "cube.ply: PLY header declares 1000000000 vertices"},
  };
  for (const auto& c : cases) {
    ScratchDir scratch;
    scratch.write(c.body, c.text);
    std::string layout = kOnCube;
    layout.replace(layout.find("cube.obj"), 8, c.body);
    scratch.write("in.json", layout);
    const CliRun run = run_vantage("analyze in.json", scratch);
    testing::expect_bad_input(run, c.expected);
    EXPECT_THAT(run.err, HasSubstr("in.json: visibility.body: "));
  }
}

}  // namespace
}  // namespace vantage
