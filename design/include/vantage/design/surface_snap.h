#pragma once

/// Markers moved onto a body's surface (`vantage layout snap`; docs/math.md §21, "Snapping a
/// layout to its body"): a layout measured or typed by hand sits a little off the mesh, or
/// inside it, and the visibility model needs each marker on the surface with its outward normal.

#include <Eigen/Core>
#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"

namespace vantage::design {

/// A marker moved farther than this fraction of the body's size (Mesh::size()) is named in a
/// warning: the mesh may not be its body, or not in its units and frame.
inline constexpr double kFarSnap = 0.05;

/// Where snap_to_surface() puts the markers, one column (or row) per marker.
struct SurfaceSnap {
  Eigen::Matrix3Xd surface;  ///< the nearest point of the surface (nearest_mesh_point())
  Eigen::Matrix3Xd normals;  ///< the outward unit normal there (outward_normals())
  Eigen::Matrix3Xd centres;  ///< surface + diameter / 2 * normal: where each marker goes
  Eigen::VectorXd moved;     ///< |centre - marker|
};

/// Each of `points` moved to the nearest point of `body` on a triangle with a normal, that
/// triangle's normal turned outward at that point (outward_normals(): rays, so open meshes and
/// any winding work), then `diameter` / 2 along it: the centre of a sphere of that diameter
/// resting on the surface (0: the surface point). Throws InvalidArgument ("body: ...") for a bad
/// mesh or one whose triangles are all slivers, "marker_diameter" unless finite and >= 0.
SurfaceSnap snap_to_surface(const Mesh& body, const Eigen::Matrix3Xd& points, double diameter);

/// `layout` (point mode, one marker per column of snap) with its markers at snap.centres and
/// their normals snap.normals, on `body` read from `body_path`. Names, weights, cones,
/// min_visible and the workspace are kept (a layout without visibility gets the default cone and
/// min_visible); the placement record is dropped (the markers moved). Throws InvalidArgument
/// ("points") for a direction layout or a column count that differs, and as Layout::validate()
/// does when two markers meet at one surface point.
Layout snapped_layout(Layout layout, const SurfaceSnap& snap, const Mesh& body,
                      const std::string& body_path);

}  // namespace vantage::design
