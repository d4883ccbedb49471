#pragma once

// The body inset of vantage-viewer's 3-D view, for markers on a body (docs/math.md §20): the
// layout as a camera at viewpoint a sees it (the affine image, along -a), with the body mesh
// translucent, each marker's normal as a short line, and the markers hidden from a grey. Without
// visibility it is the plain image of the entries, as before.

#include <Eigen/Core>

#include "vantage/viewer/viewer_session.h"

namespace vantage::viewer::app {

/// Which viewpoint the inset shows, for its title.
enum class InsetViewpoint { kCamera, kHovered, kPinned };

/// Draws the inset in the top-right corner of `viewport` (background draw list) for the unit
/// viewpoint `a` (body -> camera).
void draw_body_inset(const ViewerSession& session, const OrbitCamera& camera,
                     const Viewport& viewport, const Eigen::Vector3d& a, InsetViewpoint which);

}  // namespace vantage::viewer::app
