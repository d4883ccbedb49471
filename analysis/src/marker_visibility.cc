#include "vantage/analysis/marker_visibility.h"

#include <cmath>
#include <limits>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage {
namespace {

// | |v| - 1 | of a normal or axis that the reader normalised.
constexpr double kUnit = 1e-9;

}  // namespace

void validate_visibility(const MarkerVisibility& v, Eigen::Index markers) {
  internal::check_count_matches("normals", v.normals.cols(), markers, "points", "normals");
  for (Eigen::Index i = 0; i < markers; ++i) {
    if (!v.normals.col(i).allFinite()) {
      throw InvalidArgument("normals", static_cast<long>(i), "not finite");
    }
    if (!(std::abs(v.normals.col(i).norm() - 1.0) <= kUnit)) {
      throw InvalidArgument("normals", static_cast<long>(i),
                            "must be a unit vector (zero length?)");
    }
  }
  if (v.cone_half_angle_deg.size() != markers) {
    throw InvalidArgument("visibility.cone_half_angle_deg",
                          "has " + std::to_string(v.cone_half_angle_deg.size()) +
                              " entries, expected one per point (" + std::to_string(markers) +
                              ") or one number");
  }
  for (Eigen::Index i = 0; i < markers; ++i) {
    const double cone = v.cone_half_angle_deg(i);
    if (!(cone >= kMinConeHalfAngleDeg && cone <= 180.0)) {
      throw InvalidArgument("visibility.cone_half_angle_deg", static_cast<long>(i),
                            "must be in [0.001, 180] degrees");
    }
  }
  if (v.min_visible < 3 || v.min_visible > markers) {
    throw InvalidArgument("visibility.min_visible", "must be in [3, " + std::to_string(markers) +
                                                        "] (the markers), got " +
                                                        std::to_string(v.min_visible));
  }
  if (v.body) v.body->validate();
}

void validate_workspace(const LayoutWorkspace& w) {
  if (!w.axis.allFinite() || !(std::abs(w.axis.norm() - 1.0) <= kUnit)) {
    throw InvalidArgument("workspace.axis", "must be a non-zero vector");
  }
  if (!(w.half_angle_deg >= kMinWorkspaceHalfAngleDeg && w.half_angle_deg <= 180.0)) {
    throw InvalidArgument("workspace.half_angle_deg", "must be in [0.001, 180] degrees");
  }
}

Eigen::Vector3d unit_normal(const Eigen::Vector3d& v) {
  // stableNorm: |v| of a normal given as 1e300 or 1e-200 neither overflows nor underflows.
  if (!v.allFinite()) return Eigen::Vector3d::Zero();
  const double length = v.stableNorm();
  if (length == 0.0 || !std::isfinite(length)) return Eigen::Vector3d::Zero();
  if (std::abs(length - 1.0) <= 4.0 * std::numeric_limits<double>::epsilon()) return v;
  return v / length;
}

Eigen::Matrix3Xd radial_normals(const Eigen::Matrix3Xd& points) {
  const Eigen::Vector3d centroid = points.rowwise().mean();
  Eigen::Matrix3Xd out(3, points.cols());
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Vector3d d = points.col(i) - centroid;
    if (!(d.norm() > 0.0)) {
      throw InvalidArgument("points", static_cast<long>(i),
                            "is the centroid: --normals radial gives it no direction");
    }
    out.col(i) = d.normalized();
  }
  return out;
}

}  // namespace vantage
