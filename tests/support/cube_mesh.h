#pragma once

/// The unit cube [0, 1]^3 as a closed, consistently wound triangle mesh (12 triangles,
/// counter-clockwise seen from outside), for the mesh tests.

#include <Eigen/Core>

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

}  // namespace vantage::testing
