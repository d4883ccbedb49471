#pragma once

/// The sphere of directions as the six faces of a cube: the one parameterisation that the
/// visibility search, the occlusion grids and the maps share (docs/math.md §20).
///
/// Face f in 0..5 is +x, +y, +z, -x, -y, -z. A point (u, v) in [-1, 1]^2 of face f is the
/// direction normalize(s e_k + u e_{k+1} + v e_{k+2}) with k = f mod 3 (indices mod 3) and s = +1
/// for f < 3, -1 otherwise.

#include <Eigen/Core>

namespace vantage {

/// The unit direction of (u, v) on `face`.
Eigen::Vector3d cube_face_direction(int face, double u, double v);

/// Where a non-zero direction meets the cube: its face and (u, v) in [-1, 1]^2.
struct CubeFacePoint {
  int face = 2;
  double u = 0.0;
  double v = 0.0;
};

/// The face and coordinates of direction `a` (any non-zero length).
CubeFacePoint cube_face_point(const Eigen::Vector3d& a);

/// The angular radius (radians) of the patch of centre (u, v) and half-width h on any face: the
/// largest angle between its centre direction and its corners (the farthest points), rounded
/// up so that it bounds the patch.
double cube_patch_radius(double u, double v, double h);

}  // namespace vantage
