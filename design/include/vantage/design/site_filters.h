#pragma once

/// Where markers may go on a body (docs/math.md §21, "Where markers may go"): site normals turned
/// outward one site at a time by rays, and keep-out volumes (propellers, a battery, connectors).

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "vantage/analysis/mesh.h"
#include "vantage/design/placement.h"

namespace vantage::body {
class RayCaster;
}

namespace vantage::design {

/// `normals` (one per column of `points`, unit) turned outward one by one: of the rays from
/// p_s within 60 degrees of +n_s and of -n_s (the same 16 directions about each), the side from
/// which more of them leave `body` without meeting it is outside; a tie keeps n_s. Needs no
/// consistent winding, and works on open and non-manifold meshes (docs/math.md §21, "Sites").
/// Throws InvalidArgument ("body: ...") for a bad mesh, "normals" when the sizes differ.
Eigen::Matrix3Xd outward_normals(const Mesh& body, const Eigen::Matrix3Xd& points,
                                 const Eigen::Matrix3Xd& normals);

/// The same, with the triangle of `body` that each point lies on (or -1): a site on a patch that
/// holds a volume (closed, or open but cup-like: a pod without a bottom) is turned out by the sign
/// of the patch's volume in its propagated winding, whatever blocks its rays; the rays decide the
/// others (and a normal that is not its triangle's, up to sign and 60 degrees) (docs/math.md §21,
/// "Sites"). Throws as above, and "triangles" for an index outside the body.
Eigen::Matrix3Xd outward_normals(const Mesh& body, const Eigen::Matrix3Xd& points,
                                 const Eigen::Matrix3Xd& normals,
                                 const std::vector<int>& triangles);

/// A keep-out volume: a closed mesh, and a clearance about it.
class KeepOut {
 public:
  /// Throws InvalidArgument ("body: ...") for a bad mesh, "clearance" unless finite and >= 0.
  KeepOut(const Mesh& volume, double clearance);
  ~KeepOut();
  KeepOut(KeepOut&&) noexcept;
  KeepOut& operator=(KeepOut&&) noexcept;

  /// p is inside the volume (none of 26 rays from p, in the directions of a cube's faces, edges
  /// and corners turned off the axes, leaves it) or at most `clearance` from its surface.
  bool excludes(const Eigen::Vector3d& p) const;

  const Mesh& volume() const { return volume_; }

 private:
  Mesh volume_;
  double clearance_ = 0.0;
  std::unique_ptr<body::RayCaster> caster_;
};

/// Drops the sites that any of `volumes` excludes, keeping the others in their order; returns
/// how many were dropped.
int drop_excluded_sites(const std::vector<KeepOut>& volumes, SurfaceSites* sites);

}  // namespace vantage::design
