// io::read_mesh() and mesh_report() on meshes written by others (VANTAGE_REAL_INPUTS_DIR, the
// folder of real-inputs/README.md): the triangles and the bounding box are those the file's
// own bytes give (read here without assimp), and the units hint is the README's.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "vantage/analysis/mesh_report.h"
#include "vantage/io/mesh_file.h"

namespace vantage {
namespace {

const std::string kMeshes = std::string(VANTAGE_REAL_INPUTS_DIR) + "/meshes/";

/// What a file's bytes say: its triangle count and the bounding box of its vertices.
struct FileTruth {
  long triangles = 0;
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = -min;

  void add(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
};

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A binary STL: 80 bytes, a uint32 count, then 50 bytes per triangle (normal, 3 vertices,
/// attribute), little-endian floats.
FileTruth binary_stl_truth(const std::string& path) {
  const std::string bytes = bytes_of(path);
  FileTruth truth;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  truth.triangles = count;
  for (std::uint32_t k = 0; k < count; ++k) {
    for (int c = 0; c < 3; ++c) {
      float p[3];
      std::memcpy(p, bytes.data() + 84 + 50 * k + 12 * (c + 1), sizeof p);
      truth.add(Eigen::Vector3d(p[0], p[1], p[2]));
    }
  }
  return truth;
}

/// An ASCII STL: a "facet" per triangle, a "vertex x y z" per corner (as float, as assimp).
FileTruth ascii_stl_truth(const std::string& path) {
  std::istringstream in(bytes_of(path));
  FileTruth truth;
  for (std::string word; in >> word;) {
    if (word == "facet") ++truth.triangles;
    if (word != "vertex") continue;
    float p[3];
    in >> p[0] >> p[1] >> p[2];
    truth.add(Eigen::Vector3d(p[0], p[1], p[2]));
  }
  return truth;
}

struct RealMesh {
  const char* file;
  bool binary;
  long readme_triangles;  ///< real-inputs/README.md's count, 0 where it gives a range
};

class RealMeshes : public ::testing::TestWithParam<RealMesh> {};

TEST_P(RealMeshes, TrianglesAndBoundingBoxAreTheFilesOwn) {
  const std::string path = kMeshes + GetParam().file;
  const FileTruth truth = GetParam().binary ? binary_stl_truth(path) : ascii_stl_truth(path);
  if (GetParam().readme_triangles > 0) {
    EXPECT_EQ(truth.triangles, GetParam().readme_triangles);
  }
  const Mesh mesh = io::read_mesh(path);
  const MeshReport report = mesh_report(mesh);
  EXPECT_EQ(report.triangles, truth.triangles);
  EXPECT_EQ(mesh.triangles.cols(), truth.triangles);
  EXPECT_EQ(report.vertices, mesh.vertices.cols());  // read_mesh joined identical positions
  EXPECT_EQ(report.bounding_box_size, truth.max - truth.min);
  EXPECT_EQ(mesh.vertices.rowwise().minCoeff(), truth.min);
}

INSTANTIATE_TEST_SUITE_P(
    MeshRealInputs, RealMeshes,
    ::testing::Values(RealMesh{"PlusLibData__8700248.stl", true, 27108},
                      RealMesh{"PlusLibData__Stylus_Example.stl", true, 816},
                      RealMesh{"PlusLibData__Probe_L14-5_38_lowres.stl", true, 26387},
                      RealMesh{"PlusLibData__P4_001.stl", true, 0},
                      RealMesh{"PlusLibData__N4_001.stl", true, 0},
                      RealMesh{"AtracsysAstm__pointer_RAS.stl", false, 712},
                      RealMesh{"AtracsysAstm__ftk500_RAS.stl", false, 76}),
    [](const auto& info) {
      std::string name = info.param.file;
      name.erase(
          std::remove_if(name.begin(), name.end(),
                         [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }),
          name.end());
      return name;
    });

/// Boundary and non-manifold edges of a binary STL counted from its bytes with a map from each
/// edge's two corner positions (as floats) to its triangles: the naive count.
std::pair<long, long> naive_edge_counts(const std::string& path) {
  using Corner = std::array<float, 3>;
  const std::string bytes = bytes_of(path);
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  std::map<std::pair<Corner, Corner>, int> triangles_of_edge;
  for (std::uint32_t k = 0; k < count; ++k) {
    Corner corner[3];
    for (int c = 0; c < 3; ++c) {
      std::memcpy(corner[c].data(), bytes.data() + 84 + 50 * k + 12 * (c + 1), 12);
    }
    for (int c = 0; c < 3; ++c) {
      const Corner& a = corner[c];
      const Corner& b = corner[(c + 1) % 3];
      if (a != b) ++triangles_of_edge[{std::min(a, b), std::max(a, b)}];
    }
  }
  long boundary = 0, non_manifold = 0;
  for (const auto& [edge, triangles] : triangles_of_edge) {
    boundary += triangles == 1;
    non_manifold += triangles > 2;
  }
  return {boundary, non_manifold};
}

// The probe is open, with edges of three triangles and four triangles wound the other way; the
// marker tree is closed. (Neither has a degenerate triangle, so the naive count applies.)
TEST(MeshRealInputs, EdgeCountsAreTheNaiveCountsOfTheFile) {
  for (const char* file : {"PlusLibData__Probe_L14-5_38_lowres.stl", "PlusLibData__8700248.stl"}) {
    const MeshReport report = mesh_report(io::read_mesh(kMeshes + file));
    ASSERT_EQ(report.degenerate_triangles, 0) << file;
    const auto [boundary, non_manifold] = naive_edge_counts(kMeshes + file);
    EXPECT_EQ(report.boundary_edges, boundary) << file;
    EXPECT_EQ(report.non_manifold_edges, non_manifold) << file;
    EXPECT_EQ(report.closed, boundary == 0 && non_manifold == 0) << file;
  }
}

// The README gives these marker trees and the probe in millimetres.
TEST(MeshRealInputs, NdiBodiesInMillimetresAreHintedSo) {
  for (const char* file :
       {"PlusLibData__8700248.stl", "PlusLibData__P4_001.stl", "PlusLibData__N4_001.stl"}) {
    EXPECT_EQ(mesh_report(io::read_mesh(kMeshes + file)).units_hint, UnitsHint::kMillimetres)
        << file;
  }
}

}  // namespace
}  // namespace vantage
