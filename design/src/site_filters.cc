// Site normals oriented by rays and keep-out volumes (docs/math.md §21, "Where markers may go").

#include "vantage/design/site_filters.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/analysis/mesh_report.h"
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

// A patch whose signed volume about its own centroid, in its propagated winding, is at least
// this times its area^(3/2) holds a volume even when it is open (a pod without a bottom: about
// 0.08; a sphere 0.094, a cube 0.068; a flat panel 0): docs/math.md §21, "Sites".
constexpr double kCupLike = 0.02;
// A site's normal is its triangle's (up to sign) when their cosine is at least this.
constexpr double kSameFace = 0.5;

// Per patch of `body`: +1 when its propagated winding faces out, -1 when in, 0 when it holds no
// volume (open and flatter than kCupLike).
std::vector<int> patch_orientations(const Mesh& body, const MeshPatches& patches) {
  const std::size_t count = static_cast<std::size_t>(patches.count);
  std::vector<Eigen::Vector3d> centroid(count, Eigen::Vector3d::Zero());
  std::vector<double> triangles(count, 0.0);
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
    const int p = patches.patch[static_cast<std::size_t>(t)];
    if (p < 0) continue;
    for (int c = 0; c < 3; ++c) centroid[p] += body.vertices.col(body.triangles(c, t)) / 3.0;
    triangles[p] += 1.0;
  }
  std::vector<double> volume(count, 0.0), area(count, 0.0);
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
    const int p = patches.patch[static_cast<std::size_t>(t)];
    if (p < 0) continue;
    const Eigen::Vector3d o = centroid[p] / triangles[p];
    const Eigen::Vector3d a = body.vertices.col(body.triangles(0, t)) - o;
    const Eigen::Vector3d b = body.vertices.col(body.triangles(1, t)) - o;
    const Eigen::Vector3d c = body.vertices.col(body.triangles(2, t)) - o;
    const double sign = patches.flipped[static_cast<std::size_t>(t)] ? -1.0 : 1.0;
    volume[p] += sign * a.dot(b.cross(c)) / 6.0;
    area[p] += 0.5 * (b - a).cross(c - a).norm();
  }
  std::vector<int> out(count, 0);
  for (std::size_t p = 0; p < count; ++p) {
    const bool holds =
        patches.closed[p] || std::abs(volume[p]) >= kCupLike * std::pow(area[p], 1.5);
    if (holds && volume[p] != 0.0) out[p] = volume[p] > 0.0 ? 1 : -1;
  }
  return out;
}

}  // namespace

Eigen::Matrix3Xd outward_normals(const Mesh& body, const Eigen::Matrix3Xd& points,
                                 const Eigen::Matrix3Xd& normals,
                                 const std::vector<int>& triangles) {
  if (normals.cols() != points.cols() ||
      triangles.size() != static_cast<std::size_t>(points.cols())) {
    throw InvalidArgument("normals", "expected one normal and one triangle per point (" +
                                         std::to_string(points.cols()) + ")");
  }
  body.validate();
  const MeshPatches patches = mesh_patches(body);
  const std::vector<int> orientation = patch_orientations(body, patches);
  Eigen::Matrix3Xd out = normals;
  std::vector<Eigen::Index> by_rays;  // the sites no patch decides
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const int t = triangles[static_cast<std::size_t>(i)];
    if (t < -1 || t >= body.triangles.cols()) {
      throw InvalidArgument("triangles", static_cast<long>(i), "not a triangle of the body");
    }
    const int p = t < 0 ? -1 : patches.patch[static_cast<std::size_t>(t)];
    if (p < 0 || orientation[static_cast<std::size_t>(p)] == 0) {
      by_rays.push_back(i);
      continue;
    }
    const Eigen::Vector3d a = body.vertices.col(body.triangles(0, t));
    const Eigen::Vector3d b = body.vertices.col(body.triangles(1, t));
    const Eigen::Vector3d c = body.vertices.col(body.triangles(2, t));
    // The triangle's normal in its patch's winding, turned out by the patch's volume.
    const double sign = (patches.flipped[static_cast<std::size_t>(t)] ? -1.0 : 1.0) *
                        orientation[static_cast<std::size_t>(p)];
    const Eigen::Vector3d outward = sign * (b - a).cross(c - a).normalized();
    const Eigen::Vector3d n = normals.col(i);
    // A normal across the triangle's (a site at an edge, on another face): the rays decide.
    if (std::abs(n.dot(outward)) < kSameFace * n.norm()) {
      by_rays.push_back(i);
      continue;
    }
    out.col(i) = n.dot(outward) < 0.0 ? Eigen::Vector3d(-n) : n;
  }
  if (by_rays.empty()) return out;
  const Eigen::Index m = static_cast<Eigen::Index>(by_rays.size());
  Eigen::Matrix3Xd at(3, m), given(3, m);
  for (Eigen::Index k = 0; k < m; ++k) {
    at.col(k) = points.col(by_rays[static_cast<std::size_t>(k)]);
    given.col(k) = normals.col(by_rays[static_cast<std::size_t>(k)]);
  }
  const Eigen::Matrix3Xd turned = outward_normals(body, at, given);
  for (Eigen::Index k = 0; k < m; ++k)
    out.col(by_rays[static_cast<std::size_t>(k)]) = turned.col(k);
  return out;
}

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
