#pragma once

/// How the markers of a layout are seen on their body (docs/math.md §20): the fields a layout
/// file gives with "normals", "visibility" and "workspace" (README, "File formats").

#include <Eigen/Core>
#include <optional>
#include <string>

#include "vantage/analysis/mesh.h"

namespace vantage {

/// The markers' faces, cones and body.
struct MarkerVisibility {
  static constexpr double kDefaultConeDeg = 90.0;  ///< NDI's default marker angle

  Eigen::Matrix3Xd normals;             ///< outward unit normals, one per marker
  Eigen::VectorXd cone_half_angle_deg;  ///< one per marker, in [kMinConeHalfAngleDeg, 180]
  int min_visible = 3;                  ///< markers a tracked direction must see, >= 3
  /// The body mesh's path as the layout gives it (relative to the layout file), or empty.
  std::string body_path;
  std::optional<Mesh> body;  ///< the mesh read from body_path (when there is one)
};

/// The narrowest marker cone, degrees: the cone's cosine is still below 1 (1 - cos of 1e-3
/// degrees is 1.5e-10; a cone of 1e-300 degrees would have cosine 1 and see nothing).
inline constexpr double kMinConeHalfAngleDeg = 1e-3;

/// The narrowest workspace, degrees: its lattice (docs/math.md §20, "Coverage") is still inside
/// it after rounding (1 - cos of 1e-3 degrees is 1.5e-10; of 1e-6 degrees, one rounding).
inline constexpr double kMinWorkspaceHalfAngleDeg = 1e-3;

/// The directions a camera or tracker can take: {a : a.axis >= cos(half_angle)}.
struct LayoutWorkspace {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit (normalised on reading)
  double half_angle_deg = 180.0;                    ///< in [kMinWorkspaceHalfAngleDeg, 180]
};

/// Throws InvalidArgument naming the file's field for visibility of a layout with `markers`
/// points: "normals" (count, finite, unit within 1e-9: the reader normalises),
/// "visibility.cone_half_angle_deg[i]" in [0.001, 180], "visibility.min_visible" in [3, markers].
void validate_visibility(const MarkerVisibility& visibility, Eigen::Index markers);

/// Throws InvalidArgument for a workspace axis that is not unit or a half-angle outside (0, 180].
void validate_workspace(const LayoutWorkspace& workspace);

/// A normal as the readers keep it: v / |v|, except that a v already of unit length to
/// rounding (| |v| - 1 | <= 4 eps) is kept as given, so that a written layout reads back bit
/// for bit. The zero vector stays zero (the readers refuse it, naming the field).
Eigen::Vector3d unit_normal(const Eigen::Vector3d& v);

/// The outward normals of a convex body around the markers' centroid: unit(p_i - centroid)
/// (`--normals radial`). Throws InvalidArgument naming "points[i]" for a marker at the centroid.
Eigen::Matrix3Xd radial_normals(const Eigen::Matrix3Xd& points);

}  // namespace vantage
