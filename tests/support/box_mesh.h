#pragma once

/// An axis-aligned box as a closed mesh of 12 triangles (outward winding), for the visibility
/// tests.

#include <Eigen/Core>

#include "vantage/analysis/mesh.h"

namespace vantage::testing {

/// The box from lo to hi: vertex k at (k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? ...).
inline Mesh box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Mesh mesh;
  mesh.vertices.resize(3, 8);
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.col(k) << ((k & 1) ? hi.x() : lo.x()), ((k & 2) ? hi.y() : lo.y()),
        ((k & 4) ? hi.z() : lo.z());
  }
  const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                           {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  mesh.triangles.resize(3, 12);
  for (int f = 0; f < 6; ++f) {
    mesh.triangles.col(2 * f) << quads[f][0], quads[f][1], quads[f][2];
    mesh.triangles.col(2 * f + 1) << quads[f][0], quads[f][2], quads[f][3];
  }
  return mesh;
}

}  // namespace vantage::testing
