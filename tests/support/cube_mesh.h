#pragma once

/// The unit cube [0, 1]^3 as a closed, consistently wound triangle mesh (12 triangles,
/// counter-clockwise seen from outside), for the mesh tests, and a mesh as the text of an OBJ
/// file, for the command's.

#include <Eigen/Core>
#include <sstream>
#include <string>
#include <utility>

#include "vantage/analysis/mesh.h"

namespace vantage::testing {

/// Vertex x + 2y + 4z at (x, y, z) in {0, 1}^3; each face two triangles with outward normals.
inline Mesh unit_cube() {
  Mesh mesh;
  mesh.vertices.resize(3, 8);
  for (int v = 0; v < 8; ++v) mesh.vertices.col(v) << (v & 1), ((v >> 1) & 1), ((v >> 2) & 1);
  mesh.triangles.resize(3, 12);
  mesh.triangles << 0, 0, 4, 4, 0, 0, 2, 2, 0, 0, 1, 1,  //
      2, 3, 5, 7, 1, 5, 6, 7, 4, 6, 3, 7,                //
      3, 1, 7, 6, 5, 4, 7, 3, 6, 2, 7, 5;
  return mesh;
}

/// The unit cube moved to [-0.5, 0.5]^3.
inline Mesh centred_unit_cube() {
  Mesh mesh = unit_cube();
  mesh.vertices.array() -= 0.5;
  return mesh;
}

/// `mesh` as an OBJ file's text (numbers that read back exactly), without triangle `missing` and
/// with triangle `flipped` wound the other way (-1: none).
inline std::string obj_text(const Mesh& mesh, int missing = -1, int flipped = -1) {
  std::ostringstream obj;
  obj.precision(17);
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    obj << "v " << mesh.vertices(0, v) << " " << mesh.vertices(1, v) << " " << mesh.vertices(2, v)
        << "\n";
  }
  for (Eigen::Index k = 0; k < mesh.triangles.cols(); ++k) {
    if (k == missing) continue;
    Eigen::Vector3i t = mesh.triangles.col(k);
    if (k == flipped) std::swap(t(1), t(2));
    obj << "f " << t(0) + 1 << " " << t(1) + 1 << " " << t(2) + 1 << "\n";
  }
  return obj.str();
}

}  // namespace vantage::testing
