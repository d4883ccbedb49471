// Site normals oriented by rays and keep-out volumes (docs/math.md §21, "Where markers may go").

#include "vantage/design/site_filters.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/body/ray_caster.h"
#include "vantage/visibility/visibility.h"

namespace vantage::design {
namespace {

// The rays of the orientation test: the directions of a Fibonacci lattice within kRayConeDeg of
// +z (16 of 64), turned about each site normal. Away from grazing, so that a ray does not skim
// the face it leaves.
constexpr int kLatticeDirections = 64;
constexpr double kRayConeDeg = 60.0;

Eigen::Matrix3Xd ray_pattern() {
  const Eigen::Matrix3Xd all = visibility::fibonacci_directions(kLatticeDirections);
  const double cos_cone = std::cos(kRayConeDeg * kPi / 180.0);
  Eigen::Matrix3Xd out(3, all.cols());
  Eigen::Index n = 0;
  for (Eigen::Index k = 0; k < all.cols(); ++k) {
    if (all(2, k) >= cos_cone) out.col(n++) = all.col(k);
  }
  out.conservativeResize(3, n);
  return out;
}

// How many rays of `pattern`, turned from +z to `axis`, leave the body from `origin`.
int escaping(const body::RayCaster& caster, const Eigen::Matrix3Xd& pattern,
             const Eigen::Vector3d& origin, const Eigen::Vector3d& axis) {
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  int out = 0;
  for (Eigen::Index k = 0; k < pattern.cols(); ++k) {
    if (!caster.occluded(origin, turn * pattern.col(k))) ++out;
  }
  return out;
}

// The rays of the inside test: the 26 directions of a cube's faces, edges and corners, turned by a
// fixed rotation away from the axes (a box-shaped volume's edges and corners would otherwise lie
// on them, where a ray may slip between two triangles).
Eigen::Matrix3Xd make_inside_rays() {
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  Eigen::Matrix3Xd out(3, 26);
  int k = 0;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        out.col(k++) = turn * Eigen::Vector3d(x, y, z).normalized();
      }
    }
  }
  return out;
}

const Eigen::Matrix3Xd& inside_rays() {
  static const Eigen::Matrix3Xd rays = make_inside_rays();
  return rays;
}

}  // namespace

Eigen::Matrix3Xd outward_normals(const Mesh& body, const Eigen::Matrix3Xd& points,
                                 const Eigen::Matrix3Xd& normals) {
  if (normals.cols() != points.cols()) {
    throw InvalidArgument("normals",
                          "expected one per point (" + std::to_string(points.cols()) + ")");
  }
  const body::RayCaster caster(body);
  const Eigen::Matrix3Xd pattern = ray_pattern();
  const double offset = body::kSurfaceOffset * std::max(body.size(), 1e-300);
  Eigen::Matrix3Xd out = normals;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Vector3d n = normals.col(i);
    const int along = escaping(caster, pattern, points.col(i) + offset * n, n);
    const int against = escaping(caster, pattern, points.col(i) - offset * n, -n);
    if (against > along) out.col(i) = -n;
  }
  return out;
}

KeepOut::KeepOut(const Mesh& volume, double clearance) : volume_(volume), clearance_(clearance) {
  volume_.validate();
  if (!(clearance >= 0.0) || !std::isfinite(clearance)) {
    throw InvalidArgument("clearance", "must be a finite number >= 0");
  }
  caster_ = std::make_unique<body::RayCaster>(volume_);
}

KeepOut::~KeepOut() = default;
KeepOut::KeepOut(KeepOut&&) noexcept = default;
KeepOut& KeepOut::operator=(KeepOut&&) noexcept = default;

bool KeepOut::excludes(const Eigen::Vector3d& p) const {
  if (distance_to_mesh(volume_, p) <= clearance_) return true;
  const Eigen::Matrix3Xd& rays = inside_rays();
  for (Eigen::Index k = 0; k < rays.cols(); ++k) {
    if (!caster_->occluded(p, rays.col(k))) return false;
  }
  return true;
}

int drop_excluded_sites(const std::vector<KeepOut>& volumes, SurfaceSites* sites) {
  Eigen::Index kept = 0;
  std::vector<int> triangles;
  for (Eigen::Index i = 0; i < sites->points.cols(); ++i) {
    const Eigen::Vector3d p = sites->points.col(i);
    const bool dropped = std::any_of(volumes.begin(), volumes.end(),
                                     [&](const KeepOut& volume) { return volume.excludes(p); });
    if (dropped) continue;
    sites->points.col(kept) = p;
    sites->normals.col(kept) = sites->normals.col(i);
    triangles.push_back(sites->triangles[static_cast<std::size_t>(i)]);
    ++kept;
  }
  const int dropped = static_cast<int>(sites->points.cols() - kept);
  sites->points.conservativeResize(3, kept);
  sites->normals.conservativeResize(3, kept);
  sites->triangles = std::move(triangles);
  return dropped;
}

}  // namespace vantage::design
