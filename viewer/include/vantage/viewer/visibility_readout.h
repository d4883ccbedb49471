#pragma once

/// What the viewer shows of markers on a body (docs/math.md §20): the markers a viewpoint sees,
/// the error they leave, and which viewpoints of the sphere are lost. Thin wrappers over
/// visibility::VisibilityModel::at (the exact visibility: cone test and occlusion grid).
///
/// A viewpoint a is a unit vector in the object frame from the body toward the camera: the point
/// of the viewer's sphere under the mouse is the camera's place, so a is that point itself (not
/// its antipode, which sees other markers).

#include <Eigen/Core>
#include <vector>

#include "vantage/visibility/visibility_model.h"

namespace vantage::viewer {

/// Whether a viewpoint can track the body.
enum class ViewpointState : char {
  kTrackable,         ///< at least min_visible markers seen, not collinear, in the workspace
  kLost,              ///< in the workspace, but too few markers seen (or only collinear ones)
  kOutsideWorkspace,  ///< outside the layout's workspace cap
};

/// The markers seen from viewpoint a.
struct VisibilityReadout {
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();  ///< unit, body -> camera
  std::vector<int> visible;                              ///< markers visible from a, increasing
  std::vector<int> hidden;                               ///< the other markers, increasing
  ViewpointState state = ViewpointState::kLost;
  /// t(a) = min |a.u_ij| over the visible pairs (1 with fewer than two visible markers).
  double t = 1.0;
  /// The worst-case error of Eq. (30) with the visible markers' free vectors, asin t(a), in
  /// degrees (atan2(t, sqrt(1 - t^2))): meaningful when the state is kTrackable.
  double error_deg = 90.0;
};

/// The readout at unit viewpoint a (finite, non-zero; normalised here). Throws InvalidArgument
/// for a zero or non-finite a.
VisibilityReadout read_visibility(const visibility::VisibilityModel& model,
                                  const Eigen::Vector3d& a);

/// The sphere of viewpoints under visibility: at each vertex (unit vectors, 3 x v) the error
/// asin t(a) with the markers visible from it, and its state.
struct VisibilityShading {
  Eigen::VectorXd error_deg;           ///< asin t(a), degrees (90 where not trackable)
  std::vector<ViewpointState> states;  ///< one per vertex
  int trackable_vertices = 0;          ///< vertices whose state is kTrackable
};

VisibilityShading shade_visibility(const visibility::VisibilityModel& model,
                                   const Eigen::Matrix3Xd& vertices);

}  // namespace vantage::viewer
