#include "vantage/body/occlusion.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/analysis/cube_sphere.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/parallel.h"
#include "vantage/body/ray_caster.h"

namespace vantage::body {
namespace {

constexpr double kMinResolution = 0.45 * kPi / 180.0;
constexpr double kMaxResolution = 30.0 * kPi / 180.0;

/// d turned toward the unit normal by `by` radians (0 <= by <= angle(d, normal)), in their plane.
Eigen::Vector3d toward(const Eigen::Vector3d& d, const Eigen::Vector3d& normal, double by) {
  const Eigen::Vector3d axis = d.cross(normal);
  const double length = axis.norm();
  if (length == 0.0) return d;  // d is along +-normal: the cone is all or nothing there
  const Eigen::Vector3d k = axis / length;
  return (d * std::cos(by) + k.cross(d) * std::sin(by)).normalized();
}

/// The cells one marker casts: those that may meet its cone (within a cell's radius of it).
void cast_marker(const RayCaster& caster, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& normal, double cos_cone, int marker, int n,
                 OcclusionGrid* grid) {
  const double cone = std::acos(std::clamp(cos_cone, -1.0, 1.0));
  std::vector<int> cells;
  Eigen::Matrix3Xd directions(3, 6 * n * n);
  int count = 0;
  for (int face = 0; face < 6; ++face) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double u = -1.0 + (2.0 * i + 1.0) / n;
        const double v = -1.0 + (2.0 * j + 1.0) / n;
        const Eigen::Vector3d d = cube_face_direction(face, u, v);
        const double radius = cube_patch_radius(u, v, 1.0 / n);
        const double angle = std::atan2(d.cross(normal).norm(), d.dot(normal));
        if (angle > cone + radius) continue;
        // The cell's sample: its centre, or when the centre lies outside the cone the nearest
        // direction of the cone (the part of the cell where the marker can be seen at all).
        directions.col(count++) = angle <= cone ? d : toward(d, normal, angle - cone);
        cells.push_back((face * n + i) * n + j);
      }
    }
  }
  const Eigen::Matrix3Xd origins = origin.replicate(1, count);
  std::vector<char> blocked;
  caster.occluded(origins, directions.leftCols(count),
                  Eigen::VectorXd::Constant(count, std::numeric_limits<double>::infinity()),
                  &blocked);
  for (int k = 0; k < count; ++k) {
    const int cell = cells[static_cast<std::size_t>(k)];
    grid->set_blocked(marker, cell / (n * n), (cell / n) % n, cell % n,
                      blocked[static_cast<std::size_t>(k)] != 0);
  }
}

}  // namespace

bool OcclusionOptions::is_valid(std::string* why) const {
  if (!(resolution >= kMinResolution && resolution <= kMaxResolution)) {
    return internal::invalid_option(why, "resolution", "must be in [0.45, 30] degrees");
  }
  if (threads < 0) return internal::invalid_option(why, "threads", "must be >= 0");
  return true;
}

OcclusionGrid build_occlusion_grid(const Mesh& mesh, const Eigen::Matrix3Xd& points,
                                   const Eigen::Matrix3Xd& normals, const Eigen::VectorXd& cos_cone,
                                   const OcclusionOptions& options) {
  internal::check_options("options", options);
  internal::check_count_matches("normals", normals.cols(), points.cols(), "points");
  internal::check_count_matches("cos_cone", cos_cone.size(), points.cols(), "points", "entries");
  const RayCaster caster(mesh);
  const int n = OcclusionGrid::cells_per_edge_for(options.resolution);
  const int markers = static_cast<int>(points.cols());
  OcclusionGrid grid(markers, n);
  const double offset = kSurfaceOffset * std::max(mesh.size(), 1e-300);
  parallel_blocks(markers, options.threads, [&](long begin, long end) {
    for (long i = begin; i < end; ++i) {
      const Eigen::Vector3d normal = normals.col(i).normalized();
      cast_marker(caster, points.col(i) + offset * normal, normal, cos_cone(i), static_cast<int>(i),
                  n, &grid);
    }
  });
  grid.finish();
  return grid;
}

}  // namespace vantage::body
