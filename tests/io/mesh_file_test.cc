// io::read_mesh() refuses what it cannot read right: a vertex that is not finite, wherever it is
// and in whichever format, and a PLY header that declares more elements than its file holds
// (before assimp reserves memory for them). Identical positions are joined on reading.

#include "vantage/io/mesh_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "support/cube_mesh.h"
#include "support/message_of.h"

namespace vantage {
namespace {

using ::testing::HasSubstr;
using testing::message_of;

class Scratch {
 public:
  Scratch() {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           ("vantage_mesh_file_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(dir_);
  }
  ~Scratch() { std::filesystem::remove_all(dir_); }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  std::string write(const std::string& name, const std::string& bytes) const {
    const std::filesystem::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file.string();
  }

 private:
  std::filesystem::path dir_;
};

/// The unit cube's triangles as an ASCII STL, with coordinate `axis` of corner `corner` of
/// triangle `triangle` written as `bad` (when triangle >= 0).
std::string ascii_stl(int triangle = -1, int corner = 0, const std::string& bad = "nan") {
  const Mesh cube = testing::unit_cube();
  std::string out = "solid cube\n";
  for (int k = 0; k < cube.triangles.cols(); ++k) {
    out += "facet normal 0 0 0\nouter loop\n";
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d p = cube.vertices.col(cube.triangles(c, k));
      out += "vertex";
      for (int axis = 0; axis < 3; ++axis) {
        out += " " + (k == triangle && c == corner && axis == 1 ? bad : std::to_string(p(axis)));
      }
      out += "\n";
    }
    out += "endloop\nendfacet\n";
  }
  return out + "endsolid cube\n";
}

/// The unit cube as a binary STL with corner `corner` of triangle `triangle` at `bad` in y.
std::string binary_stl(int triangle, int corner, float bad) {
  const Mesh cube = testing::unit_cube();
  std::string out(80, '\0');
  const auto put = [&](const void* data, std::size_t size) {
    out.append(static_cast<const char*>(data), size);
  };
  const std::uint32_t count = static_cast<std::uint32_t>(cube.triangles.cols());
  put(&count, 4);
  for (int k = 0; k < cube.triangles.cols(); ++k) {
    const float normal[3] = {0, 0, 0};
    put(normal, sizeof normal);
    for (int c = 0; c < 3; ++c) {
      float p[3];
      for (int axis = 0; axis < 3; ++axis) {
        p[axis] = static_cast<float>(cube.vertices(axis, cube.triangles(c, k)));
      }
      if (k == triangle && c == corner) p[1] = bad;
      put(p, sizeof p);
    }
    const std::uint16_t attributes = 0;
    put(&attributes, 2);
  }
  return out;
}

struct Corner {
  int triangle;
  int corner;
};

class NonFiniteVertex : public ::testing::TestWithParam<Corner> {};

TEST_P(NonFiniteVertex, AsciiStlIsRefusedNamingTheFileTriangleAndCorner) {
  const Scratch scratch;
  const auto [triangle, corner] = GetParam();
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    const std::string path = scratch.write("body.stl", ascii_stl(triangle, corner, bad));
    EXPECT_THAT(message_of([&] { io::read_mesh(path); }),
                HasSubstr(path + ": triangle[" + std::to_string(triangle) + "]: vertex " +
                          std::to_string(corner) + " is not finite"))
        << bad;
  }
}

TEST_P(NonFiniteVertex, BinaryStlIsRefusedNamingTheTriangleAndCorner) {
  const Scratch scratch;
  const auto [triangle, corner] = GetParam();
  const std::string path = scratch.write(
      "body.stl", binary_stl(triangle, corner, std::numeric_limits<float>::quiet_NaN()));
  EXPECT_THAT(message_of([&] { io::read_mesh(path); }),
              HasSubstr("triangle[" + std::to_string(triangle) + "]: vertex " +
                        std::to_string(corner) + " is not finite"));
}

// Every corner of the first triangle, of the second, and of the last (joining identical
// vertices merged a NaN vertex of a later triangle into a finite one: it was accepted).
INSTANTIATE_TEST_SUITE_P(MeshFile, NonFiniteVertex,
                         ::testing::Values(Corner{0, 0}, Corner{0, 1}, Corner{0, 2}, Corner{1, 0},
                                           Corner{1, 1}, Corner{1, 2}, Corner{11, 0}, Corner{11, 1},
                                           Corner{11, 2}),
                         [](const auto& info) {
                           return "Triangle" + std::to_string(info.param.triangle) + "Corner" +
                                  std::to_string(info.param.corner);
                         });

TEST(MeshFile, NonFiniteVertexIsRefusedInObjAndPly) {
  const Scratch scratch;
  const std::string obj = scratch.write(
      "body.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 nan\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  EXPECT_THAT(message_of([&] { io::read_mesh(obj); }), HasSubstr("is not finite"));
  const std::string ply = scratch.write("body.ply",
                                        "ply\nformat ascii 1.0\nelement vertex 4\n"
                                        "property float x\nproperty float y\nproperty float z\n"
                                        "element face 1\nproperty list uchar int vertex_indices\n"
                                        "end_header\n0 0 0\n1 0 0\n0 1 0\ninf 0 0\n3 0 1 2\n");
  EXPECT_THAT(message_of([&] { io::read_mesh(ply); }), HasSubstr(ply + ": "));
  EXPECT_THAT(message_of([&] { io::read_mesh(ply); }), HasSubstr("is not finite"));
}

TEST(MeshFile, FiniteStlReadsWithIdenticalPositionsJoined) {
  const Scratch scratch;
  const Mesh mesh = io::read_mesh(scratch.write("cube.stl", ascii_stl()));
  EXPECT_EQ(mesh.triangles.cols(), 12);
  EXPECT_EQ(mesh.vertices.cols(), 8);
  EXPECT_DOUBLE_EQ(mesh.area(), 6.0);
}

/// A PLY of one triangle whose header declares `vertices` vertices.
std::string ply_declaring(const std::string& vertices, bool binary) {
  std::string out = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                    " 1.0\nelement vertex " + vertices +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  if (!binary) return out + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  out.append(reinterpret_cast<const char*>(p), sizeof p);
  const unsigned char n = 3;
  const std::int32_t face[3] = {0, 1, 2};
  out.append(reinterpret_cast<const char*>(&n), 1);
  out.append(reinterpret_cast<const char*>(face), sizeof face);
  return out;
}

TEST(MeshFile, PlyHeaderDeclaringMoreVerticesThanTheFileHoldsIsRefused) {
  const Scratch scratch;
  for (const bool binary : {false, true}) {
    for (const char* count : {"10000000", "1000000000", "18446744073709551615"}) {
      const std::string path = scratch.write("big.ply", ply_declaring(count, binary));
      const std::string message = message_of([&] { io::read_mesh(path); });
      EXPECT_THAT(message, HasSubstr(path + ": PLY header declares " + count +
                                     " vertices (header line 3, element \"vertex\""));
      EXPECT_THAT(message, HasSubstr("but the file holds at most"));
    }
  }
}

TEST(MeshFile, PlyHeaderWithACountThatIsNotAWholeNumberIsRefused) {
  const Scratch scratch;
  for (const char* count : {"-3", "3.0", "1e9", "99999999999999999999999"}) {
    const std::string path = scratch.write("bad.ply", ply_declaring(count, false));
    EXPECT_THAT(message_of([&] { io::read_mesh(path); }),
                HasSubstr("PLY header line 3: element \"vertex\" has count"))
        << count;
  }
}

// Issue 36, item 8: the header's words are quoted as excerpts.
TEST(MeshFile, PlyHeaderWordsAreQuotedAsExcerpts) {
  const Scratch scratch;
  const std::string long_word(100000, 'w');
  const std::string path =
      scratch.write("long.ply", "ply\nformat ascii 1.0\nelement " + long_word + " " + long_word +
                                    "\nproperty float x\nend_header\n");
  const std::string message = message_of([&] { io::read_mesh(path); });
  EXPECT_THAT(message, HasSubstr("PLY header line 3: element \"" + std::string(60, 'w') +
                                 "... (100000 bytes)\" has count \"" + std::string(60, 'w') +
                                 "... (100000 bytes)\", not a whole number"));
  EXPECT_LT(message.size(), 1000u);
}

TEST(MeshFile, PlyWhoseCountsFitItsSizeReads) {
  const Scratch scratch;
  for (const bool binary : {false, true}) {
    const Mesh mesh = io::read_mesh(scratch.write("ok.ply", ply_declaring("3", binary)));
    EXPECT_EQ(mesh.triangles.cols(), 1);
  }
  // Without a newline at the end of the file.
  std::string tight = ply_declaring("3", false);
  tight.pop_back();
  EXPECT_EQ(io::read_mesh(scratch.write("tight.ply", tight)).triangles.cols(), 1);
}

}  // namespace
}  // namespace vantage
