#pragma once

/// Rays against a body mesh, cast by Embree (a real ray tracer: BVH build and traversal are
/// Embree's). Single precision inside Embree; origins should be offset from the surface they
/// start on (occlusion_grid.h does).

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <vector>

#include "vantage/analysis/mesh.h"

namespace vantage::body {

/// A ray that starts on the mesh's surface starts this fraction of the mesh's size off it, along
/// the surface's normal: far above float rounding of the hit distance (~1e-7 relative, Embree
/// works in single precision), far below any feature worth resolving. The occlusion grids, the
/// exact visibility of a direction, a camera's lines of sight and the site filters share it.
inline constexpr double kSurfaceOffset = 1e-6;

/// An Embree scene of one mesh. Thread-safe for queries once built.
class RayCaster {
 public:
  /// Builds the BVH of `mesh` (validated). Throws InvalidArgument for a bad mesh,
  /// std::runtime_error when Embree fails.
  explicit RayCaster(const Mesh& mesh);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  /// True when the segment origin + s direction, 0 < s < max_distance (direction need not be
  /// unit; s in its units), meets a triangle.
  bool occluded(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                double max_distance = std::numeric_limits<double>::infinity()) const;

  /// occluded() for many rays at once (one per column), into `blocked` (resized).
  void occluded(const Eigen::Matrix3Xd& origins, const Eigen::Matrix3Xd& directions,
                const Eigen::VectorXd& max_distances, std::vector<char>* blocked) const;

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
};

}  // namespace vantage::body
