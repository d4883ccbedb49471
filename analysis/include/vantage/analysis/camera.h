#pragma once

/// The camera of every pose estimator: image points in pixels, a focal length in pixels and the
/// principal point in pixels. A pinhole camera maps a camera-frame point x = (x, y, z), z > 0, to
///   q = c + f (x / z, y / z),
/// and the affine (scaled-orthographic) model of McInroy et al. (Eq. 14) to
///   alpha (q - c) = P x,   P = [I_2 0],   alpha = depth / f (object units per pixel, Eq. 37).
/// Image points already in normalised coordinates (x / z, y / z) are the case f = 1, c = 0.

#include <Eigen/Core>
#include <string>

namespace vantage {

/// Pinhole intrinsics, pixels.
struct Camera {
  /// Focal length, pixels per unit of normalised coordinate; > 0 and finite, or 0 = unknown
  /// (the affine estimators then leave the depth p_z undetermined; the perspective ones need it).
  double focal_length = 0.0;
  /// Principal point c, pixels; finite. Image points are measured from the image origin.
  Eigen::Vector2d principal_point = Eigen::Vector2d::Zero();

  bool has_focal_length() const { return focal_length > 0.0; }

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

}  // namespace vantage
