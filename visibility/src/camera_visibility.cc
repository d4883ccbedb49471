// Visibility from a camera centre (camera_visibility.h, docs/math.md §22).

#include "vantage/visibility/camera_visibility.h"

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/body/ray_caster.h"

namespace vantage::visibility {

CameraVisibility::CameraVisibility(const Layout& layout) : points_(layout.entries) {
  if (!layout.visibility) return;
  const MarkerVisibility& v = *layout.visibility;
  with_normals_ = true;
  normals_ = v.normals;
  cos_cone_ = (v.cone_half_angle_deg / kDegreesPerRadian).array().cos().matrix();
  // A 90-degree cone is the half-space in front of the face exactly (docs/math.md §20).
  for (Eigen::Index i = 0; i < cos_cone_.size(); ++i) {
    if (v.cone_half_angle_deg(i) == 90.0) cos_cone_(i) = 0.0;
  }
  min_visible_ = v.min_visible;
  if (v.body) {
    caster_ = std::make_unique<body::RayCaster>(*v.body);
    // The segment starts off the face, so that the face the marker sits on does not hide it.
    surface_offset_ = body::kSurfaceOffset * v.body->size();
  }
}

CameraVisibility::~CameraVisibility() = default;
CameraVisibility::CameraVisibility(CameraVisibility&&) noexcept = default;
CameraVisibility& CameraVisibility::operator=(CameraVisibility&&) noexcept = default;

bool CameraVisibility::visible(int i, const Eigen::Vector3d& c) const {
  if (!with_normals_) return true;
  const Eigen::Vector3d to_camera = c - points_.col(i);
  const double length = to_camera.norm();
  if (normals_.col(i).dot(to_camera) < cos_cone_(i) * length) return false;
  if (!caster_) return true;
  const Eigen::Vector3d origin = points_.col(i) + surface_offset_ * normals_.col(i);
  const Eigen::Vector3d segment = c - origin;
  return !caster_->occluded(origin, segment / segment.norm(), segment.norm());
}

std::vector<int> CameraVisibility::visible_from(const Eigen::Vector3d& c) const {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(points_.cols()); ++i) {
    if (visible(i, c)) out.push_back(i);
  }
  return out;
}

}  // namespace vantage::visibility
