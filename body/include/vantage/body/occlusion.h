#pragma once

/// The occlusion grid of markers on a body: for each marker and each cell of the cube-face grid
/// (occlusion_grid.h) that meets the marker's cone, whether the ray from the marker along the
/// cell's sample direction (its centre, or the nearest direction of the cone when the centre
/// lies outside it) meets the mesh (docs/math.md §20).

#include <Eigen/Core>

#include "vantage/analysis/common.h"
#include "vantage/analysis/mesh.h"
#include "vantage/analysis/occlusion_grid.h"

namespace vantage::body {

/// Options of build_occlusion_grid().
struct OcclusionOptions {
  /// Largest angular size of a grid cell, radians, in [0.45 deg, 30 deg] (the grid is the
  /// resolution of the occlusion test).
  double resolution = 1.0 * kPi / 180.0;
  int threads = 0;  ///< ray casting threads, >= 0 (0 = all cores)

  bool is_valid(std::string* why = nullptr) const;
};

/// The grid for markers at `points` (3 x n) with unit outward `normals` and cone cosines
/// `cos_cone` (n entries: cells outside a marker's cone are not cast and stay clear, as the cone
/// test hides the marker there anyway). Each ray starts at p_i + eps nu_i, eps = 1e-6 of the
/// mesh's size, so a marker on a face does not shadow itself. Throws InvalidArgument on sizes or
/// options.
OcclusionGrid build_occlusion_grid(const Mesh& mesh, const Eigen::Matrix3Xd& points,
                                   const Eigen::Matrix3Xd& normals, const Eigen::VectorXd& cos_cone,
                                   const OcclusionOptions& options = {});

}  // namespace vantage::body
