// Candidate sites drawn area-uniformly on a body mesh, thinned to a separation
// (docs/math.md §21, "Sites").

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

#include "placement_random.h"
#include "vantage/analysis/common.h"
#include "vantage/design/placement.h"
#include "vantage/design/site_filters.h"

namespace vantage::design {
namespace {

// A triangle whose doubled area is below this fraction of the mesh's squared size is a sliver
// with no usable normal: never drawn.
constexpr double kDegenerateArea = 1e-14;

// Buckets of a uniform grid of cell `cell` for the thinning's neighbour queries.
class SeparationGrid {
 public:
  explicit SeparationGrid(double cell) : cell_(cell) {}

  bool far_from_all(const Eigen::Vector3d& p, const Eigen::Matrix3Xd& kept) const {
    const Eigen::Vector3i c = cell_of(p);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = buckets_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == buckets_.end()) continue;
          for (int k : it->second) {
            if ((kept.col(k) - p).norm() < cell_) return false;
          }
        }
      }
    }
    return true;
  }

  void add(const Eigen::Vector3d& p, int index) { buckets_[key(cell_of(p))].push_back(index); }

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    return (p / cell_).array().floor().cast<int>();
  }
  static long long key(const Eigen::Vector3i& c) {
    return ((static_cast<long long>(c.x()) & 0x1fffff) << 42) |
           ((static_cast<long long>(c.y()) & 0x1fffff) << 21) |
           (static_cast<long long>(c.z()) & 0x1fffff);
  }

  double cell_;
  std::unordered_map<long long, std::vector<int>> buckets_;
};

}  // namespace

SurfaceSites sample_surface_sites(const Mesh& mesh, int count, double min_separation,
                                  std::uint64_t seed) {
  mesh.validate();
  if (count < 1) throw InvalidArgument("candidates", "must be >= 1, got " + std::to_string(count));
  if (!(min_separation >= 0.0) || !std::isfinite(min_separation)) {
    throw InvalidArgument("min_separation", "must be a finite number >= 0");
  }
  const double floor_area = kDegenerateArea * mesh.size() * mesh.size();
  const Eigen::Index n_triangles = mesh.triangles.cols();
  std::vector<double> cumulative(static_cast<std::size_t>(n_triangles), 0.0);
  Eigen::Matrix3Xd normals(3, n_triangles);
  double total = 0.0;
  double signed_volume = 0.0;
  for (Eigen::Index k = 0; k < n_triangles; ++k) {
    const Eigen::Vector3d v0 = mesh.vertices.col(mesh.triangles(0, k));
    const Eigen::Vector3d v1 = mesh.vertices.col(mesh.triangles(1, k));
    const Eigen::Vector3d v2 = mesh.vertices.col(mesh.triangles(2, k));
    const Eigen::Vector3d cross = (v1 - v0).cross(v2 - v0);
    const double doubled = cross.norm();
    signed_volume += v0.dot(v1.cross(v2)) / 6.0;
    if (doubled > floor_area) {
      total += 0.5 * doubled;
      normals.col(k) = cross / doubled;
    } else {
      normals.col(k).setZero();
    }
    cumulative[static_cast<std::size_t>(k)] = total;
  }
  if (!(total > 0.0)) throw InvalidArgument("body", "the mesh has no area to place markers on");
  const double orientation = signed_volume < 0.0 ? -1.0 : 1.0;

  internal::PlacementRandom random(seed);
  SurfaceSites out;
  out.points.resize(3, count);
  out.normals.resize(3, count);
  SeparationGrid grid(min_separation > 0.0 ? min_separation : 1.0);
  int kept = 0;
  for (int draw = 0; draw < count; ++draw) {
    const double r = random.uniform() * total;
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), r);
    const Eigen::Index k =
        std::min<Eigen::Index>(n_triangles - 1, static_cast<Eigen::Index>(it - cumulative.begin()));
    const double s = std::sqrt(random.uniform());
    const double r2 = random.uniform();
    const Eigen::Vector3d p = (1.0 - s) * mesh.vertices.col(mesh.triangles(0, k)) +
                              s * (1.0 - r2) * mesh.vertices.col(mesh.triangles(1, k)) +
                              s * r2 * mesh.vertices.col(mesh.triangles(2, k));
    ++out.drawn;
    if (min_separation > 0.0 && !grid.far_from_all(p, out.points.leftCols(kept))) continue;
    out.points.col(kept) = p;
    out.normals.col(kept) = orientation * normals.col(k);
    out.triangles.push_back(static_cast<int>(k));
    if (min_separation > 0.0) grid.add(p, kept);
    ++kept;
  }
  out.points.conservativeResize(3, kept);
  out.normals.conservativeResize(3, kept);
  out.normals = outward_normals(mesh, out.points, out.normals, out.triangles);
  return out;
}

}  // namespace vantage::design
