#include "vantage/plot/sphere_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/parallel.h"
#include "vantage/plot/viewpoint_map.h"

namespace vantage::plot {

SphereMapPoint sphere_map_from_direction(const Eigen::Vector3d& a) {
  SphereMapPoint p;
  p.disc = a.z() >= 0.0 ? 0 : 1;
  const Eigen::Vector3d up = p.disc == 0 ? a : Eigen::Vector3d(-a.x(), a.y(), -a.z());
  const double s = std::sqrt(std::max(0.0, 1.0 + up.z()));
  p.xy = s == 0.0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(up.x() / s, up.y() / s);
  return p;
}

Eigen::Vector3d direction_from_sphere_map(int disc, const Eigen::Vector2d& xy) {
  const Eigen::Vector3d up = viewpoint_from_lambert(xy);
  return disc == 0 ? up : Eigen::Vector3d(-up.x(), up.y(), -up.z());
}

Eigen::Vector3d SphereSamples::direction(int d, int row, int column) const {
  const int n = samples_per_axis;
  return direction_from_sphere_map(d, {cell_centre(column, n), cell_centre(n - 1 - row, n)});
}

long SphereSamples::inside_count() const {
  return inside[0].cast<long>().sum() + inside[1].cast<long>().sum();
}

double SphereSamples::trackable_fraction() const {
  long workspace = 0, trackable_cells = 0;
  for (int d = 0; d < 2; ++d) {
    workspace += (inside[d].cast<long>().array() * in_workspace[d].cast<long>().array()).sum();
    trackable_cells += (inside[d].cast<long>().array() * trackable[d].cast<long>().array()).sum();
  }
  return workspace == 0 ? 0.0 : static_cast<double>(trackable_cells) / workspace;
}

SphereSamples sample_sphere(const visibility::VisibilityModel& model, int samples_per_axis,
                            int threads) {
  if (samples_per_axis < kMinMapSamples || samples_per_axis > kMaxMapSamples) {
    throw InvalidArgument("sample_sphere: samples_per_axis must be in [" +
                          std::to_string(kMinMapSamples) + ", " + std::to_string(kMaxMapSamples) +
                          "], got " + std::to_string(samples_per_axis));
  }
  const int n = samples_per_axis;
  SphereSamples s;
  s.samples_per_axis = n;
  for (int d = 0; d < 2; ++d) {
    s.visible[d].resize(n, n);
    s.t[d].resize(n, n);
    s.trackable[d].resize(n, n);
    s.in_workspace[d].resize(n, n);
    s.inside[d].resize(n, n);
  }
  const auto& workspace = model.problem().workspace;
  // Rows of both discs, disc 0 first: row k of disc k / n.
  parallel_blocks(2L * n, threads, [&](long begin, long end) {
    for (long k = begin; k < end; ++k) {
      const int d = static_cast<int>(k / n), r = static_cast<int>(k % n);
      for (int c = 0; c < n; ++c) {
        const Eigen::Vector3d a = s.direction(d, r, c);
        const visibility::DirectionVisibility v = model.at(a);
        s.visible[d](r, c) = static_cast<int>(v.visible.size());
        s.t[d](r, c) = v.t;
        s.trackable[d](r, c) = v.trackable ? 1 : 0;
        s.in_workspace[d](r, c) =
            !workspace || a.dot(workspace->axis) >= workspace->cos_half_angle ? 1 : 0;
        const double x = SphereSamples::cell_centre(c, n);
        const double y = SphereSamples::cell_centre(n - 1 - r, n);
        s.inside[d](r, c) = x * x + y * y <= 1.0 ? 1 : 0;
      }
    }
  });
  return s;
}

}  // namespace vantage::plot
