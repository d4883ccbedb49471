// The visibility problem's checks and the exact visibility of one direction (docs/math.md §20).

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/marker_visibility.h"
#include "vantage/sdp/layout_analysis.h"
#include "vantage/visibility/visibility.h"

namespace vantage::visibility {
namespace {

// | |nu| - 1 | above which a normal is not unit.
constexpr double kUnitNormal = 1e-9;

}  // namespace

void VisibilityProblem::validate() const {
  const Eigen::Index n = points.cols();
  vantage::internal::check_min_count("points", n, 3, "markers");
  vantage::internal::check_finite_columns("points", points);
  vantage::internal::check_count_matches("normals", normals.cols(), n, "points");
  vantage::internal::check_unit_columns("normals", normals, kUnitNormal);
  if (cos_cone.size() != n) {
    throw InvalidArgument("visibility.cone_half_angle_deg",
                          "has " + std::to_string(cos_cone.size()) + " entries, expected " +
                              std::to_string(n) + " (one per marker)");
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(cos_cone(i) >= -1.0 && cos_cone(i) < 1.0)) {
      throw InvalidArgument("visibility.cone_half_angle_deg", static_cast<long>(i),
                            "must be in [0.001, 180] degrees");
    }
  }
  if (min_visible < 3 || min_visible > n) {
    throw InvalidArgument("visibility.min_visible", "must be in [3, " + std::to_string(n) +
                                                        "] (the markers), got " +
                                                        std::to_string(min_visible));
  }
  if (workspace) {
    vantage::internal::check_unit_vector("workspace.axis", workspace->axis, kUnitNormal);
    static const double narrowest = std::cos(kMinWorkspaceHalfAngleDeg / kDegreesPerRadian);
    if (!(workspace->cos_half_angle >= -1.0 && workspace->cos_half_angle <= narrowest)) {
      throw InvalidArgument("workspace.half_angle_deg", "must be in [0.001, 180] degrees");
    }
  }
  if (!occlusion_markers.empty()) {
    if (occlusion == nullptr || static_cast<Eigen::Index>(occlusion_markers.size()) != n) {
      throw InvalidArgument("body", "occlusion_markers needs a grid and one entry per point");
    }
    for (int m : occlusion_markers) {
      if (m < 0 || m >= occlusion->markers()) {
        throw InvalidArgument("body", "occlusion marker " + std::to_string(m) +
                                          " is not in the grid's " +
                                          std::to_string(occlusion->markers()));
      }
    }
  } else if (occlusion != nullptr && occlusion->markers() != n) {
    throw InvalidArgument("body", "the occlusion grid has " + std::to_string(occlusion->markers()) +
                                      " markers, expected " + std::to_string(n));
  }
}

DirectionVisibility direction_visibility(const VisibilityProblem& problem,
                                         const Eigen::Vector3d& a) {
  std::vector<int> visible;
  for (Eigen::Index i = 0; i < problem.points.cols(); ++i) {
    if (problem.normals.col(i).dot(a) < problem.cos_cone(i)) continue;
    if (problem.occlusion != nullptr &&
        problem.occlusion->blocked(problem.occlusion_marker(static_cast<int>(i)), a)) {
      continue;
    }
    visible.push_back(static_cast<int>(i));
  }
  return seen_set(problem, a, std::move(visible));
}

DirectionVisibility seen_set(const VisibilityProblem& problem, const Eigen::Vector3d& a,
                             std::vector<int> visible) {
  DirectionVisibility out;
  out.visible = std::move(visible);
  const std::size_t k = out.visible.size();
  bool collinear = true;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  for (std::size_t x = 0; x < k; ++x) {
    for (std::size_t y = x + 1; y < k; ++y) {
      const Eigen::Vector3d u =
          (problem.points.col(out.visible[y]) - problem.points.col(out.visible[x])).normalized();
      out.t = std::min(out.t, std::abs(a.dot(u)));
      if (x == 0 && y == 1) first = u;
      if (x == 0 && y > 1 && u.cross(first).norm() > sdp::kParallelTolerance) collinear = false;
    }
  }
  const bool inside =
      !problem.workspace || a.dot(problem.workspace->axis) >= problem.workspace->cos_half_angle;
  out.trackable = inside && static_cast<int>(k) >= problem.min_visible && !collinear;
  return out;
}

}  // namespace vantage::visibility
