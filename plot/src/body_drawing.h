#pragma once

// A body mesh in the vectors figure: translucent faces (far first) and its feature edges (where
// the surface folds, or ends), projected as the figure projects points. Private to vantage::plot.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>

#include "canvas.h"
#include "vantage/analysis/mesh.h"

namespace vantage::plot::internal {

/// An edge is drawn where its faces meet at more than this angle (or it has not two faces).
inline constexpr double kFeatureEdgeDeg = 25.0;

/// The mesh's feature edges as pairs of vertex positions (vertices at one position, as STL
/// repeats them, count as one; face orientation does not matter).
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> feature_edges(const Mesh& mesh);

/// Draws the mesh mapped into the scene by `to_scene`, projected by `project`, seen along
/// `view` (unit, towards the camera).
void draw_body(Canvas& canvas, const Mesh& mesh,
               const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& to_scene,
               const std::function<Eigen::Vector2d(const Eigen::Vector3d&)>& project,
               const Eigen::Vector3d& view);

}  // namespace vantage::plot::internal
