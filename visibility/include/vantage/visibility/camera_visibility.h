#pragma once

/// What a camera at a finite distance sees of a point layout on its body (docs/math.md §22,
/// "Visibility"): each marker by its own line of sight to the camera centre c, not by a common
/// direction. Marker i is visible from c iff n_i . unit(c - p_i) >= cos(cone_i) and, with a body,
/// the segment from p_i + eps n_i to c (eps = 1e-6 of the mesh's size) meets no triangle
/// (Embree). A layout without visibility sees every marker. `vantage crb` and the pinhole camera
/// of `vantage simulate` share it.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "vantage/analysis/layout.h"

namespace vantage::body {
class RayCaster;
}

namespace vantage::visibility {

class CameraVisibility {
 public:
  /// For a point layout (validated by the caller); with a body, builds its ray caster.
  explicit CameraVisibility(const Layout& layout);
  ~CameraVisibility();
  CameraVisibility(CameraVisibility&&) noexcept;
  CameraVisibility& operator=(CameraVisibility&&) noexcept;

  /// Whether marker i is visible from the camera centre c (object frame).
  bool visible(int i, const Eigen::Vector3d& c) const;
  /// The markers visible from c, increasing.
  std::vector<int> visible_from(const Eigen::Vector3d& c) const;
  /// The layout's min_visible (3 without visibility).
  int min_visible() const { return min_visible_; }
  bool with_body() const { return caster_ != nullptr; }

 private:
  Eigen::Matrix3Xd points_;
  bool with_normals_ = false;
  Eigen::Matrix3Xd normals_;
  Eigen::VectorXd cos_cone_;
  int min_visible_ = 3;
  std::unique_ptr<body::RayCaster> caster_;
  double surface_offset_ = 0.0;
};

}  // namespace vantage::visibility
