// Where `vantage place` may put markers (docs/math.md §21, "Where markers may go"): --exclude
// keep-out volumes, --region parts of the body, normals outward whatever the mesh's winding, and
// their bad input (one line naming the option, exit 2, nothing written). The truth is the
// geometry of the boxes written here.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/cli_runner.h"
#include "support/cube_mesh.h"

namespace vantage {
namespace {

using testing::BadCall;
using testing::ScratchDir;

constexpr double kOnFace = 1e-12;

// An OBJ of the unit cube mapped onto the box [lo, hi]; `flip_every_other` winds every other
// triangle the other way (no consistent winding).
std::string box_obj(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                    bool flip_every_other = false) {
  const Mesh cube = testing::unit_cube();
  std::ostringstream obj;
  obj.precision(17);
  for (Eigen::Index v = 0; v < cube.vertices.cols(); ++v) {
    const Eigen::Vector3d p = lo + (hi - lo).cwiseProduct(cube.vertices.col(v));
    obj << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  }
  for (Eigen::Index t = 0; t < cube.triangles.cols(); ++t) {
    const bool flip = flip_every_other && t % 2 == 1;
    obj << "f " << cube.triangles(0, t) + 1 << " " << cube.triangles(flip ? 2 : 1, t) + 1 << " "
        << cube.triangles(flip ? 1 : 2, t) + 1 << "\n";
  }
  return obj.str();
}

// Two faces of the body box [0,2]x[0,1]x[0,0.5], wound inward: the top z = 0.5 and the side
// x = 2.
const char* const kTopAndSideInward =
    "v 0 0 0.5\nv 2 0 0.5\nv 2 1 0.5\nv 0 1 0.5\nv 2 0 0\nv 2 1 0\n"
    "f 1 3 2\nf 1 4 3\nf 2 6 5\nf 2 3 6\n";

Eigen::Vector3d vector_of(const nlohmann::json& xyz) {
  return {xyz[0].get<double>(), xyz[1].get<double>(), xyz[2].get<double>()};
}

// The placed markers' surface points (centre minus D/2 times the normal) and normals.
struct Placed {
  Eigen::Matrix3Xd surface;
  Eigen::Matrix3Xd normals;
};

Placed read_placed(const ScratchDir& scratch, const std::string& file, double diameter) {
  const nlohmann::json layout = nlohmann::json::parse(testing::read_file(scratch.path(file)));
  const nlohmann::json& points = layout["points"];
  Placed out{Eigen::Matrix3Xd(3, points.size()), Eigen::Matrix3Xd(3, points.size())};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Index c = static_cast<Eigen::Index>(i);
    out.normals.col(c) = vector_of(layout["normals"][i]);
    out.surface.col(c) = vector_of(points[i]) - 0.5 * diameter * out.normals.col(c);
  }
  return out;
}

const std::string kPlace =
    "place body.obj --markers 5 --candidates 300 --workspace 0,0,1,60 --random-trials 20 ";

TEST(PlaceRegionsCli, ExcludedVolumesHoldNoMarkerAndTheirSitesAreCounted) {
  // The keep-out box covers x >= 1.2 of the body; with 0.05 spheres no surface point of a marker
  // is within 0.05 of it. The same seed draws the same sites: those dropped are the difference.
  constexpr double kDiameter = 0.05;
  ScratchDir scratch;
  scratch.write("body.obj", box_obj({0, 0, 0}, {2, 1, 0.5}));
  scratch.write("keep.obj", box_obj({1.2, -1, -1}, {3, 2, 2}));
  const nlohmann::json all =
      testing::run_json(kPlace + "--marker-diameter 0.05 --out a.json", scratch);
  // BODY after a repeatable option: --exclude takes one file each time.
  const nlohmann::json json = testing::run_json(
      "place --exclude keep.obj body.obj --markers 5 --candidates 300 --workspace 0,0,1,60 "
      "--random-trials 20 --marker-diameter 0.05 --out e.json",
      scratch);
  EXPECT_EQ(json["drawn"], all["drawn"]);
  EXPECT_EQ(all["excluded"], 0);
  EXPECT_GT(json["excluded"].get<int>(), 0);
  EXPECT_EQ(json["n_candidates"].get<int>() + json["excluded"].get<int>(),
            all["n_candidates"].get<int>());
  const Placed placed = read_placed(scratch, "e.json", kDiameter);
  ASSERT_EQ(placed.surface.cols(), 5);
  for (Eigen::Index i = 0; i < placed.surface.cols(); ++i) {
    EXPECT_LT(placed.surface(0, i), 1.2 - kDiameter) << i;
  }
  const nlohmann::json analysed = testing::run_json("analyze e.json", scratch);
  EXPECT_EQ(analysed["visibility"]["pbar_min"], json["visibility"]["pbar_min"]);
}

TEST(PlaceRegionsCli, ARegionIsTheOnlyPartSampledAndItsNormalsFaceOut) {
  // The region is the body's top and +x faces wound inward: every marker sits on one of them,
  // facing out of the body.
  ScratchDir scratch;
  scratch.write("body.obj", box_obj({0, 0, 0}, {2, 1, 0.5}));
  scratch.write("part.obj", kTopAndSideInward);
  const nlohmann::json json =
      testing::run_json(kPlace + "--region part.obj --min-coverage 0.5 --out r.json", scratch);
  EXPECT_EQ(json["excluded"], 0);
  const Placed placed = read_placed(scratch, "r.json", 0.0);
  ASSERT_EQ(placed.surface.cols(), 5);
  for (Eigen::Index i = 0; i < placed.surface.cols(); ++i) {
    const bool top = std::abs(placed.surface(2, i) - 0.5) <= kOnFace;
    const bool side = std::abs(placed.surface(0, i) - 2.0) <= kOnFace;
    ASSERT_TRUE(top || side) << i;
    EXPECT_TRUE(
        placed.normals.col(i).isApprox(top ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX()))
        << i;
  }
}

TEST(PlaceRegionsCli, NormalsFaceOutOfABodyWithoutAConsistentWinding) {
  // Every other triangle of the body wound the other way: the sites' normals still face out of
  // the box (n . (p - centre) > 0 for its faces).
  ScratchDir scratch;
  scratch.write("body.obj", box_obj({0, 0, 0}, {2, 1, 0.5}, true));
  testing::run_json(kPlace + "--out m.json", scratch);
  const Placed placed = read_placed(scratch, "m.json", 0.0);
  const Eigen::Vector3d centre(1.0, 0.5, 0.25);
  for (Eigen::Index i = 0; i < placed.surface.cols(); ++i) {
    EXPECT_GT(placed.normals.col(i).dot(placed.surface.col(i) - centre), 0.0) << i;
  }
}

TEST(PlaceRegionsCli, BadInputGetsOneLineAndWritesNothing) {
  ScratchDir scratch;
  scratch.write("body.obj", box_obj({0, 0, 0}, {2, 1, 0.5}));
  scratch.write("all.obj", box_obj({-1, -1, -1}, {3, 2, 2}));
  scratch.write("far.obj", box_obj({10, 10, 10}, {11, 11, 11}));
  scratch.write("sites.json", R"({"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
      "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1], [0, 0, 1]]})");
  const std::string body = "body.obj --markers 4 --out o.json ";
  const std::string missing = body + "--exclude none.stl";
  const std::string everything = body + "--exclude all.obj";
  const std::string far = body + "--region far.obj";
  const std::string no_region = body + "--region none.obj";
  const BadCall calls[] = {
      {"an exclude mesh that does not load", nullptr, missing.c_str(), "--exclude: "},
      {"every site excluded", nullptr, everything.c_str(), "--exclude: "},
      {"a region off the body", nullptr, far.c_str(), "--region: far.obj: not on the body"},
      {"a region that does not load", nullptr, no_region.c_str(), "--region: "},
      {"--exclude with --sites", nullptr,
       "--sites sites.json --markers 4 --out o.json --exclude all.obj", "--exclude: "},
  };
  for (const BadCall& call : calls) {
    SCOPED_TRACE(call.name);
    testing::run_bad_call("place", call, scratch);
    EXPECT_FALSE(std::filesystem::exists(scratch.path("o.json")));
  }
}

}  // namespace
}  // namespace vantage
