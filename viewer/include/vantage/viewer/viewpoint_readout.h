#pragma once

/// What the viewer shows for one viewpoint (the hovered or pinned point of the sphere) and the
/// shading of the sphere of viewpoints. Both are thin wrappers over analysis/error_bounds.h.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace vantage::viewer {

/// The data vectors seen from viewpoint a.
struct ViewpointReadout {
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();  ///< unit
  Eigen::VectorXd p;           ///< p_i = sqrt(1 - (a.n_i)^2), projected_fractions (Eq. 19)
  double pbar_at = 1.0;        ///< p-bar(a) = max_i p_i (Eq. 27)
  Eigen::VectorXd errors_deg;  ///< Eq. (26) with p_i and p_bar: worst_case_errors_deg(vectors, a)
  double max_error_deg = 0.0;  ///< max_i errors_deg = arccos p_bar (docs/math.md §11)
  int limiting = 0;            ///< the vector that sets p_bar (first on ties)
};

/// The readout at unit viewpoint a for data vectors (3 x m, m >= 1, non-zero finite columns).
/// Throws InvalidArgument on bad input.
ViewpointReadout read_viewpoint(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a);

/// The unit sphere of viewpoints as a latitude-longitude mesh with the worst-case error
/// arccos p_bar(a) at each vertex (pbar_at_viewpoints, analysis/error_bounds.h).
struct SphereShading {
  Eigen::Matrix3Xd vertices;                  ///< unit vectors
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise seen from outside
  Eigen::VectorXd error_deg;                  ///< arccos p_bar at each vertex, degrees
};

/// Mesh with `rings` >= 2 latitude bands and `segments` >= 3 longitude sectors, shaded for data
/// vectors (3 x m, m >= 1). Throws InvalidArgument on bad arguments.
SphereShading shade_sphere(const Eigen::Matrix3Xd& vectors, int rings = 120, int segments = 240);

}  // namespace vantage::viewer
