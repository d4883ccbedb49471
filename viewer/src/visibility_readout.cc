#include "vantage/viewer/visibility_readout.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::viewer {
namespace {

// asin t in degrees, well conditioned near t = 1 (docs/math.md §20: the error of Eq. 30).
double error_of_t_deg(double t) {
  return kDegreesPerRadian * std::atan2(t, std::sqrt(std::max(0.0, (1.0 - t) * (1.0 + t))));
}

ViewpointState state_of(const visibility::VisibilityProblem& problem, const Eigen::Vector3d& a,
                        bool trackable) {
  if (trackable) return ViewpointState::kTrackable;
  if (problem.workspace && a.dot(problem.workspace->axis) < problem.workspace->cos_half_angle) {
    return ViewpointState::kOutsideWorkspace;
  }
  return ViewpointState::kLost;
}

}  // namespace

VisibilityReadout read_visibility(const visibility::VisibilityModel& model,
                                  const Eigen::Vector3d& a) {
  const double norm = a.norm();
  if (!(norm > 0.0) || !std::isfinite(norm)) {
    throw InvalidArgument("viewpoint", "must be a non-zero finite direction");
  }
  VisibilityReadout readout;
  readout.viewpoint = a / norm;
  const visibility::DirectionVisibility seen = model.at(readout.viewpoint);
  readout.visible = seen.visible;
  std::size_t next = 0;
  for (int i = 0; i < static_cast<int>(model.problem().points.cols()); ++i) {
    if (next < seen.visible.size() && seen.visible[next] == i) {
      ++next;
    } else {
      readout.hidden.push_back(i);
    }
  }
  readout.state = state_of(model.problem(), readout.viewpoint, seen.trackable);
  readout.t = seen.t;
  readout.error_deg = error_of_t_deg(seen.t);
  return readout;
}

VisibilityShading shade_visibility(const visibility::VisibilityModel& model,
                                   const Eigen::Matrix3Xd& vertices) {
  VisibilityShading shading;
  shading.error_deg.resize(vertices.cols());
  shading.states.resize(static_cast<std::size_t>(vertices.cols()));
  for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
    const Eigen::Vector3d a = vertices.col(v);
    const visibility::DirectionVisibility seen = model.at(a);
    const ViewpointState state = state_of(model.problem(), a, seen.trackable);
    shading.states[static_cast<std::size_t>(v)] = state;
    shading.error_deg(v) = state == ViewpointState::kTrackable ? error_of_t_deg(seen.t) : 90.0;
    shading.trackable_vertices += state == ViewpointState::kTrackable;
  }
  return shading;
}

}  // namespace vantage::viewer
