#pragma once

/// One simulated measurement: the truth and the noisy data every estimator of a trial sees.
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object; the camera looks along +z;
/// the viewpoint (optical axis in the object frame) is the third row of R (McInroy et al.,
/// Sec. III.D).
///
/// Cameras of a layout scene (make_layout_scene), with the object size s = max_i |z_i - g| (the
/// largest distance of a marker from the aim point g, by default the object origin) and g
/// placed at (offset_x s, offset_y s, range s) in the camera frame, so p = that - R g:
///  - scaled orthographic ("affine", McInroy et al. Eq. 14): q_i = P (R z_i + p) / alpha + c
///    with alpha = p_z / f (object units per pixel; Eq. 37's p_z = alpha f holds exactly);
///  - pinhole: q_i = f (x / z, y / z) + c of x = R z_i + p (every marker in front: range > 1).
/// c is the principal point; the estimators receive image points centred at it. Image noise is
/// added per coordinate in pixels. Direction layouts (data vectors z_i) give the affine images
/// d_i = P R z_i / alpha of Eq. (15) and no translation.
/// A 3-D sensor (the paper's "full 3-D" baseline, Sec. IV) measures R z_i + p with noise of
/// sigma_px * alpha object units per coordinate: the pixel footprint at the object's depth.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "vantage/simulate/noise.h"
#include "vantage/simulate/random.h"

namespace vantage::simulate {

/// What a scene holds, and so which estimators apply to it.
enum class SceneKind {
  kAffineVectors,  ///< data vectors z_i and their affine images d_i (Prop. 4, Lemma 7)
  kAffineImage,    ///< marker points and their scaled-orthographic image (+ 3-D measurements)
  kPinholeImage,   ///< marker points and their pinhole image (+ 3-D measurements)
  kPlanar2d,       ///< 2-D points (model z = 0) and a rigidly moved noisy copy ([H] Sec. 2)
  kPoints3d,       ///< 3-D points and a rigidly moved noisy copy ([H] Sec. 3)
  kTwoView,        ///< two perspective views of 3-D points ([H] Sec. 4)
};

/// "affine_vectors", "affine_image", "pinhole_image", "planar_2d", "points_3d", "two_view".
const char* to_string(SceneKind kind);

/// A simulated measurement with its truth.
struct Scene {
  SceneKind kind = SceneKind::kAffineImage;
  /// Object points (or data vectors for kAffineVectors), 3 x n. kPlanar2d: z = 0; kTwoView:
  /// the points in the frame of camera 1.
  Eigen::Matrix3Xd model;
  /// Noisy image, 2 x n: pixels (with the principal point) for the image kinds, d_i for
  /// kAffineVectors, the moved 2-D points for kPlanar2d, view 2 (normalised) for kTwoView.
  Eigen::Matrix2Xd image;
  Eigen::Matrix2Xd image_clean;  ///< `image` without noise
  Eigen::Matrix2Xd first_view;   ///< kTwoView: noisy view 1 (normalised coordinates)
  /// Noisy 3-D measurements R z_i + p (object units), 3 x n: the 3-D sensor of the image kinds
  /// and the moved copy of kPoints3d. Empty otherwise.
  Eigen::Matrix3Xd measured;
  Eigen::Vector2d principal_point = Eigen::Vector2d::Zero();  ///< pixels
  double focal = 1.0;  ///< pixels per unit of normalised coordinate (image kinds); 1 otherwise

  Eigen::Matrix3d R_true = Eigen::Matrix3d::Identity();  ///< R_camera_object (R_camera2_camera1)
  Eigen::Vector3d p_true = Eigen::Vector3d::Zero();      ///< p_camera_object (T of two views)
  bool has_translation = true;                           ///< false for kAffineVectors
  double alpha_true = 1.0;  ///< affine scale (object units per image unit); 1 otherwise
  double sigma = 0.0;       ///< noise standard deviation of `image`, its own units
};

/// Camera model of a layout scene.
enum class CameraModel {
  kAffine,   ///< scaled orthographic (McInroy et al. Eq. 14)
  kPinhole,  ///< perspective
};

/// "affine" or "pinhole".
const char* to_string(CameraModel camera);

/// How a layout scene is imaged (see the file comment).
struct LayoutSceneOptions {
  CameraModel camera = CameraModel::kAffine;
  double focal_px = 1000.0;  ///< focal length, pixels, > 0
  /// Depth of the object origin in object sizes s, > 0; > 1 for the pinhole camera (every
  /// marker in front of it).
  double range = 10.0;
  Eigen::Vector2d principal_point = Eigen::Vector2d::Zero();  ///< pixels, finite
  Eigen::Vector2d lateral_offset = Eigen::Vector2d::Zero();   ///< p_x, p_y in object sizes
  NoiseKind noise = NoiseKind::kGaussian;
  double noise_px = 0.0;  ///< image noise standard deviation, pixels, >= 0
  /// When set, sigma = peak_to_peak(noise-free image) / 10^(snr_db / 20) per trial (the [H]
  /// definition, noise.h) and noise_px is ignored. Finite.
  std::optional<double> snr_db;
  /// When set, the camera looks along this object-frame direction (unit length; the third row
  /// of R) with a uniformly random roll about it; otherwise R is uniformly random.
  std::optional<Eigen::Vector3d> viewpoint;
  /// The object-frame point g the camera is aimed at, finite (see the file comment): sizes are
  /// measured about it and it sits at (offset s, range s) in the camera frame. The pose the
  /// estimators return is still the object frame's (p = R_camera_object applied to the origin).
  Eigen::Vector3d aim = Eigen::Vector3d::Zero();

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// A rotation whose third row is the unit vector `axis`, with roll angle `roll` (radians) about
/// it.
Eigen::Matrix3d rotation_with_viewpoint(const Eigen::Vector3d& axis, double roll);

/// One trial's scene of a layout: `entries` are marker points (vectors = false) or data vectors
/// (vectors = true), 3 x n with n >= 2 non-zero columns. Draws R (or the roll), then the noise,
/// from `random`. Throws InvalidArgument on invalid options or entries.
Scene make_layout_scene(const Eigen::Matrix3Xd& entries, bool vectors,
                        const LayoutSceneOptions& options, TrialRandom& random);

/// Adds noise of the kind and standard deviation to every entry of `data` (column by column).
void add_noise(Eigen::Ref<Eigen::MatrixXd> data, NoiseKind kind, double sigma, TrialRandom& random);

}  // namespace vantage::simulate
