#pragma once

/// Reading correspondence files (JSON) for `vantage orient` and `vantage pose`:
///
///   {"model":    [[x, y, z], ...],   object-frame points or vectors
///    "measured": [[x, y, z], ...],   3-D measurements in the camera frame (orient, full3d)
///    "image":    [[u, v], ...],      image points of the model (affine and perspective pose)
///    "image1":   [[u, v], ...],      two-view: the same points in the first image
///    "image2":   [[u, v], ...],      two-view: ... and in the second
///    "weights":  [w, ...],           optional, positive, one per correspondence
///    "camera":   {"focal": F, "principal_point": [cx, cy]}}   optional, pixels: image points
///                                    are pixels of a pinhole camera with focal length F > 0 and
///                                    principal point c (default [0, 0]); both keys optional
///
/// Every field is optional in the file; each command states which it needs through require().
/// Errors are one line "<source>: <field>[<index>]: <problem>" in a vantage::InvalidArgument.

#include <Eigen/Core>
#include <string>
#include <string_view>

#include "vantage/analysis/camera.h"

namespace vantage::io {

/// The parsed content of a correspondence file. Absent matrices have zero columns.
struct CorrespondenceFile {
  std::string source;
  Eigen::Matrix3Xd model;
  Eigen::Matrix3Xd measured;
  Eigen::Matrix2Xd image;
  Eigen::Matrix2Xd image1;
  Eigen::Matrix2Xd image2;
  Eigen::VectorXd weights;  ///< empty when absent (all weights 1)
  /// "camera" in pixels; focal_length 0 when the file gives none, principal point (0, 0) when
  /// absent.
  Camera camera;
  bool has_focal = false;            ///< "camera" has "focal"
  bool has_principal_point = false;  ///< "camera" has "principal_point"
  bool has_model = false;
  bool has_measured = false;
  bool has_image = false;
  bool has_image1 = false;
  bool has_image2 = false;

  /// Throws InvalidArgument "<source>: <field>: required by <purpose>" when a named field is
  /// absent. Fields: "model", "measured", "image", "image1", "image2".
  void require(std::initializer_list<const char*> fields, const std::string& purpose) const;
};

/// Parses correspondence JSON. Checks arity, finiteness, positive weights and that every present
/// list has as many entries as the model (image1 and image2 as each other, weights as the
/// correspondences). Unknown top-level fields are an error.
CorrespondenceFile parse_correspondences(std::string_view text, const std::string& source);

/// Reads and parses the correspondence file at `path`.
CorrespondenceFile read_correspondences(const std::string& path);

}  // namespace vantage::io
