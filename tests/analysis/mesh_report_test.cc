// mesh_report() (docs/math.md §20, "The body's mesh report"): the counts of a cube built by
// hand, and of the cube with one triangle removed, flipped or repeated, where each count is
// known from the construction.

#include "vantage/analysis/mesh_report.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "support/cube_mesh.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::unit_cube;

/// The mesh without triangle k.
Mesh without_triangle(const Mesh& mesh, Eigen::Index k) {
  Mesh out = mesh;
  out.triangles.resize(3, mesh.triangles.cols() - 1);
  out.triangles << mesh.triangles.leftCols(k),
      mesh.triangles.rightCols(mesh.triangles.cols() - k - 1);
  return out;
}

/// Every triangle with its own three vertices (an STL file's layout).
Mesh as_triangle_soup(const Mesh& mesh) {
  Mesh out;
  out.vertices.resize(3, 3 * mesh.triangles.cols());
  out.triangles.resize(3, mesh.triangles.cols());
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    for (int c = 0; c < 3; ++c) {
      out.vertices.col(3 * k + c) = mesh.vertices.col(mesh.triangles(c, k));
      out.triangles(c, k) = static_cast<int>(3 * k + c);
    }
  }
  return out;
}

TEST(MeshReport, TheCubeFixtureIsWoundOutward) {
  const Mesh cube = unit_cube();
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  for (Eigen::Index k = 0; k < cube.triangles.cols(); ++k) {
    const Eigen::Vector3d a = cube.vertices.col(cube.triangles(0, k));
    const Eigen::Vector3d b = cube.vertices.col(cube.triangles(1, k));
    const Eigen::Vector3d c = cube.vertices.col(cube.triangles(2, k));
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3 - centre), 0.0) << "triangle " << k;
  }
}

TEST(MeshReport, ClosedCubeIsClosedManifoldAndConsistent) {
  const MeshReport r = mesh_report(unit_cube());
  EXPECT_EQ(r.triangles, 12);
  EXPECT_EQ(r.vertices, 8);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.inconsistent_edges, 0);
  EXPECT_EQ(r.triangles_against_neighbours, 0);
  EXPECT_EQ(r.degenerate_triangles, 0);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_TRUE(r.consistently_wound);
  EXPECT_EQ(r.bounding_box_size, Eigen::Vector3d::Ones());
  EXPECT_EQ(r.warning("cube.stl"), "");
}

TEST(MeshReport, CubeWithoutATriangleIsOpenAlongItsThreeEdges) {
  for (Eigen::Index k = 0; k < 12; ++k) {
    const MeshReport r = mesh_report(without_triangle(unit_cube(), k));
    EXPECT_EQ(r.triangles, 11);
    EXPECT_EQ(r.boundary_edges, 3) << k;
    EXPECT_FALSE(r.closed);
    EXPECT_TRUE(r.manifold);
    EXPECT_TRUE(r.consistently_wound);
    EXPECT_EQ(r.warning("cube.stl"),
              "body cube.stl is open (3 boundary edges): occlusion and sampled normals may be "
              "wrong");
  }
}

TEST(MeshReport, CubeWithAFlippedTriangleIsInconsistentAtItsThreeEdges) {
  for (Eigen::Index k = 0; k < 12; ++k) {
    Mesh cube = unit_cube();
    std::swap(cube.triangles(1, k), cube.triangles(2, k));
    const MeshReport r = mesh_report(cube);
    EXPECT_TRUE(r.closed);
    EXPECT_FALSE(r.consistently_wound);
    EXPECT_EQ(r.inconsistent_edges, 3) << k;
    EXPECT_EQ(r.triangles_against_neighbours, 1) << k;
    EXPECT_THAT(r.warning("cube.stl"),
                HasSubstr("body cube.stl 1 triangle is wound against its neighbours"));
  }
}

TEST(MeshReport, CubeTurnedInsideOutIsStillConsistent) {
  Mesh cube = unit_cube();
  cube.triangles.row(1).swap(cube.triangles.row(2));
  const MeshReport r = mesh_report(cube);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.consistently_wound);
}

TEST(MeshReport, TriangleSoupIsWeldedBeforeEdgesAreCounted) {
  const MeshReport soup = mesh_report(as_triangle_soup(unit_cube()));
  EXPECT_EQ(soup.vertices, 8);
  EXPECT_TRUE(soup.closed);
  EXPECT_TRUE(soup.consistently_wound);
}

TEST(MeshReport, ARepeatedTriangleMakesThreeNonManifoldEdges) {
  Mesh cube = unit_cube();
  cube.triangles.conservativeResize(3, 13);
  cube.triangles.col(12) = cube.triangles.col(0);
  const MeshReport r = mesh_report(cube);
  EXPECT_EQ(r.non_manifold_edges, 3);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.manifold);
  EXPECT_THAT(r.warning("cube.stl"), HasSubstr("has 3 edges shared by more than two triangles"));
}

TEST(MeshReport, DegenerateTrianglesAreCountedAndLeftOutOfTheEdges) {
  Mesh cube = unit_cube();
  cube.triangles.conservativeResize(3, 14);
  cube.triangles.col(12) << 0, 0, 7;
  cube.triangles.col(13) << 5, 5, 5;
  const MeshReport r = mesh_report(cube);
  EXPECT_EQ(r.degenerate_triangles, 2);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.consistently_wound);
}

TEST(MeshReport, OpenAndInconsistentGiveOneLine) {
  Mesh cube = without_triangle(unit_cube(), 0);
  std::swap(cube.triangles(1, 5), cube.triangles(2, 5));
  const std::string warning = mesh_report(cube).warning("drone.stl");
  EXPECT_THAT(warning, HasSubstr("body drone.stl is open (3 boundary edges) and 1 triangle is "
                                 "wound against its neighbours: occlusion"));
  EXPECT_EQ(warning.find('\n'), std::string::npos);
}

TEST(MeshReport, UnitsHintFollowsTheLargestExtent) {
  const struct {
    double scale;
    UnitsHint hint;
  } cases[] = {{0.2, UnitsHint::kMetres},       {10.0, UnitsHint::kMetres},
               {10.5, UnitsHint::kUnclear},     {29.0, UnitsHint::kUnclear},
               {30.0, UnitsHint::kMillimetres}, {250.0, UnitsHint::kMillimetres}};
  for (const auto& c : cases) {
    Mesh cube = unit_cube();
    cube.vertices *= c.scale;
    EXPECT_EQ(mesh_report(cube).units_hint, c.hint) << c.scale;
  }
}

TEST(MeshReport, UnitsHintParsesWhatItPrints) {
  for (UnitsHint hint : {UnitsHint::kMetres, UnitsHint::kMillimetres, UnitsHint::kUnclear}) {
    EXPECT_EQ(parse_units_hint(to_string(hint)), hint);
  }
  EXPECT_EQ(parse_units_hint("inches"), std::nullopt);
}

}  // namespace
}  // namespace vantage
