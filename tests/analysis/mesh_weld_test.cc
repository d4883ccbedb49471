// first_identical_vertex() and weld_identical_vertices(): vertices at one position become one,
// every triangle keeps its corners' positions, and the vertices kept stay in their order.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "support/cube_mesh.h"
#include "support/message_of.h"
#include "vantage/analysis/mesh.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;

/// The positions of every triangle's corners, triangle by triangle.
Eigen::MatrixXd corner_positions(const Mesh& mesh) {
  Eigen::MatrixXd out(9, mesh.triangles.cols());
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    for (int c = 0; c < 3; ++c) out.block<3, 1>(3 * c, k) = mesh.vertices.col(mesh.triangles(c, k));
  }
  return out;
}

TEST(MeshWeld, FirstIdenticalVertexGroupsEqualPositionsAndMinusZero) {
  Eigen::Matrix3Xd v(3, 5);
  v << 1, 0, 1, -0.0, 1,  //
      2, 0, 2, 0, 2,      //
      3, 0, 3.0000000001, 0, 3;
  const std::vector<int> first = first_identical_vertex(v);
  EXPECT_EQ(first, (std::vector<int>{0, 1, 2, 1, 0}));
}

TEST(MeshWeld, FirstIdenticalVertexRefusesNonFiniteVertices) {
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, 2);
  v(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(testing::message_of([&] { first_identical_vertex(v); }), HasSubstr("finite"));
}

TEST(MeshWeld, ShuffledSoupWeldsToTheCubesEightVertices) {
  const Mesh cube = testing::unit_cube();
  std::mt19937 rng(36);
  for (int trial = 0; trial < 5; ++trial) {
    // Each corner its own vertex, in a random order, plus two vertices no triangle uses.
    Mesh soup;
    std::vector<int> slot(36);
    for (int k = 0; k < 36; ++k) slot[static_cast<std::size_t>(k)] = k;
    std::shuffle(slot.begin(), slot.end(), rng);
    soup.vertices = Eigen::Matrix3Xd::Constant(3, 38, 7.0);
    soup.triangles.resize(3, 12);
    for (int k = 0; k < 12; ++k) {
      for (int c = 0; c < 3; ++c) {
        const int s = slot[static_cast<std::size_t>(3 * k + c)];
        soup.vertices.col(s) = cube.vertices.col(cube.triangles(c, k));
        soup.triangles(c, k) = s;
      }
    }
    const Eigen::MatrixXd before = corner_positions(soup);
    weld_identical_vertices(&soup);
    EXPECT_EQ(soup.vertices.cols(), 8);
    EXPECT_EQ(corner_positions(soup), before);
  }
}

TEST(MeshWeld, VerticesKeptStayInTheirOrder) {
  Mesh mesh;
  mesh.vertices.resize(3, 5);
  mesh.vertices << 0, 5, 1, 0, 0,  //
      0, 5, 0, 1, 0,               //
      0, 5, 0, 0, 0;
  mesh.triangles.resize(3, 1);
  mesh.triangles << 4, 2, 3;  // vertex 4 repeats vertex 0; vertex 1 is unused
  weld_identical_vertices(&mesh);
  Eigen::Matrix3Xd expected(3, 3);
  expected << 0, 1, 0,  //
      0, 0, 1,          //
      0, 0, 0;
  EXPECT_EQ(mesh.vertices, expected);
  EXPECT_EQ(mesh.triangles.col(0), Eigen::Vector3i(0, 1, 2));
}

}  // namespace
}  // namespace vantage
