// Markers moved onto a body's surface (docs/math.md §21, "Snapping a layout to its body").

#include "vantage/design/surface_snap.h"

#include <string>
#include <utility>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/design/placement_layout.h"
#include "vantage/design/site_filters.h"

namespace vantage::design {

SurfaceSnap snap_to_surface(const Mesh& body, const Eigen::Matrix3Xd& points, double diameter) {
  body.validate();
  const Eigen::Index n = points.cols();
  SurfaceSnap snap;
  snap.surface.resize(3, n);
  Eigen::Matrix3Xd wound(3, n);
  std::vector<int> triangles(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    const MeshPoint nearest = nearest_mesh_point(body, points.col(i));
    if (nearest.triangle < 0) {
      throw InvalidArgument("body", "every triangle is a sliver: no surface to snap to");
    }
    snap.surface.col(i) = nearest.point;
    wound.col(i) = nearest.normal;
    triangles[static_cast<std::size_t>(i)] = static_cast<int>(nearest.triangle);
  }
  snap.normals = outward_normals(body, snap.surface, wound, triangles);
  snap.centres = sphere_centres(snap.surface, snap.normals, diameter);
  snap.moved = (snap.centres - points).colwise().norm().transpose();
  return snap;
}

Layout snapped_layout(Layout layout, const SurfaceSnap& snap, const Mesh& body,
                      const std::string& body_path) {
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument("points", "snapping needs marker positions, not data vectors");
  }
  const Eigen::Index n = layout.entries.cols();
  if (snap.centres.cols() != n || snap.normals.cols() != n) {
    throw InvalidArgument("points",
                          "expected one snapped marker per point (" + std::to_string(n) + ")");
  }
  layout.entries = snap.centres;
  if (!layout.visibility) {
    MarkerVisibility visibility;
    visibility.cone_half_angle_deg =
        Eigen::VectorXd::Constant(n, MarkerVisibility::kDefaultConeDeg);
    layout.visibility = std::move(visibility);
  }
  layout.visibility->normals = snap.normals;
  layout.visibility->body = body;
  layout.visibility->body_path = body_path;
  layout.placement.reset();
  layout.validate();
  return layout;
}

}  // namespace vantage::design
