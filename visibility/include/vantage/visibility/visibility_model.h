#pragma once

/// A point layout on its body, ready to answer "what does direction a see?" (docs/math.md §20):
/// the visibility problem of the layout's normals, cones, min_visible and workspace, and, when
/// the layout has a body mesh, the markers' occlusion grid cast on it (owned here). The report,
/// the figures, the viewer and the simulation all start from one.

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/occlusion_grid.h"
#include "vantage/visibility/visibility.h"

namespace vantage::visibility {

class VisibilityModel {
 public:
  /// The default occlusion grid cell size, degrees (docs/math.md §20).
  static constexpr double kDefaultResolutionDeg = 1.0;

  /// For a point layout with visibility (throws InvalidArgument naming "normals" otherwise, or
  /// "occlusion_resolution_deg" outside [0.45, 30]). With a body, casts the grid (Embree) at
  /// `resolution_deg` on `threads` threads (0: all cores).
  static VisibilityModel of(const Layout& layout, double resolution_deg = kDefaultResolutionDeg,
                            int threads = 0);

  /// The problem; its occlusion pointer is this model's grid (valid while the model lives).
  const VisibilityProblem& problem() const { return problem_; }
  bool has_body() const { return grid_ != nullptr; }
  /// The grid's cell size in degrees, with a body.
  std::optional<double> resolution_deg() const;
  /// The exact visibility of unit direction a (direction_visibility()).
  DirectionVisibility at(const Eigen::Vector3d& a) const;

 private:
  VisibilityProblem problem_;
  std::shared_ptr<const OcclusionGrid> grid_;
};

}  // namespace vantage::visibility
