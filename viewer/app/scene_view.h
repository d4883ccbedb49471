#pragma once

// The 3-D view of vantage-viewer: the sphere of viewpoints shaded by arccos p_bar(a), the data
// vectors (or the free-vector directions of the markers), the global worst viewpoints as red axes
// with their a-perp great circles, the paper's single-LMI viewpoint in magenta, the probe, and
// an inset with the layout as the camera sees it. Mouse: drag orbits, wheel zooms, a click on the
// sphere pins the probe, a vector tip (direction mode) or the pinned probe can be dragged.

#include <imgui.h>
#include <Eigen/Core>
#include <optional>

#include "vantage/viewer/viewer_session.h"

namespace vantage::viewer::app {

class SceneView {
 public:
  /// Draws into `viewport` (pixels) on the background draw list. With `interactive` the mouse is
  /// handled (screenshots pass false so that the pointer position cannot change the picture).
  /// Returns the viewpoint under the mouse, if it is over the sphere.
  std::optional<Eigen::Vector3d> draw(ViewerSession& session, const Viewport& viewport,
                                      bool interactive);

 private:
  enum class Drag { kNone, kOrbit, kVector, kProbe };

  std::optional<Eigen::Vector3d> handle_mouse(ViewerSession& session, const Viewport& viewport);

  Drag drag_ = Drag::kNone;
  int drag_index_ = -1;
  ImVec2 press_{0, 0};
  bool moved_ = false;
  bool moved_continue_ = false;  // a vector drag has made its first (undoable) edit
};

}  // namespace vantage::viewer::app
