#include "vantage/simulate/scene.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

// ||viewpoint|| may differ from 1 by this much (rounding of a file or of the SDP answer).
constexpr double kUnitTolerance = 1e-9;

bool fail(std::string* why, const std::string& message) {
  if (why) *why = message;
  return false;
}

}  // namespace

const char* to_string(SceneKind kind) {
  switch (kind) {
    case SceneKind::kAffineVectors:
      return "affine_vectors";
    case SceneKind::kAffineImage:
      return "affine_image";
    case SceneKind::kPinholeImage:
      return "pinhole_image";
    case SceneKind::kPlanar2d:
      return "planar_2d";
    case SceneKind::kPoints3d:
      return "points_3d";
    case SceneKind::kTwoView:
      return "two_view";
  }
  return "unknown";
}

const char* to_string(CameraModel camera) {
  return camera == CameraModel::kAffine ? "affine" : "pinhole";
}

bool LayoutSceneOptions::is_valid(std::string* why) const {
  if (!(focal_px > 0.0 && std::isfinite(focal_px))) {
    return fail(why, "focal_px: must be finite and > 0");
  }
  if (!(range > 0.0 && std::isfinite(range))) return fail(why, "range: must be finite and > 0");
  if (camera == CameraModel::kPinhole && !(range > 1.0)) {
    return fail(why, "range: must be > 1 object size for the pinhole camera (markers in front)");
  }
  if (!principal_point.allFinite()) return fail(why, "principal_point: must be finite");
  if (!lateral_offset.allFinite()) return fail(why, "lateral_offset: must be finite");
  if (!(noise_px >= 0.0 && std::isfinite(noise_px))) {
    return fail(why, "noise_px: must be finite and >= 0");
  }
  if (snr_db && !std::isfinite(*snr_db)) return fail(why, "snr_db: must be finite");
  if (!aim.allFinite()) return fail(why, "aim: must be finite");
  if (viewpoint &&
      (!viewpoint->allFinite() || std::abs(viewpoint->norm() - 1.0) > kUnitTolerance)) {
    return fail(why, "viewpoint: must be a finite unit vector");
  }
  return true;
}

Eigen::Matrix3d rotation_with_viewpoint(const Eigen::Vector3d& axis, double roll) {
  const Eigen::Vector3d a = axis.normalized();
  // Any unit vector orthogonal to a, then the roll about a.
  const Eigen::Vector3d helper =
      std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (helper - helper.dot(a) * a).normalized();
  const Eigen::Vector3d e2 = a.cross(e1);
  Eigen::Matrix3d R;
  R.row(0) = (std::cos(roll) * e1 + std::sin(roll) * e2).transpose();
  R.row(1) = (-std::sin(roll) * e1 + std::cos(roll) * e2).transpose();
  R.row(2) = a.transpose();
  return R;
}

void add_noise(Eigen::Ref<Eigen::MatrixXd> data, NoiseKind kind, double sigma,
               TrialRandom& random) {
  for (Eigen::Index j = 0; j < data.cols(); ++j) {
    for (Eigen::Index i = 0; i < data.rows(); ++i) data(i, j) += noise_sample(kind, sigma, random);
  }
}

Scene make_layout_scene(const Eigen::Matrix3Xd& entries, bool vectors,
                        const LayoutSceneOptions& options, TrialRandom& random) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("make_layout_scene: " + why);
  if (entries.cols() < 2 || !entries.allFinite()) {
    throw InvalidArgument("make_layout_scene: entries must be 3 x n, n >= 2, finite");
  }
  const Eigen::Vector3d aim = vectors ? Eigen::Vector3d::Zero() : options.aim;
  const double size = (entries.colwise() - aim).colwise().norm().maxCoeff();
  if (!(size > 0.0)) {
    throw InvalidArgument("make_layout_scene: entries are all zero (all at the aim point)");
  }
  if (vectors && options.camera == CameraModel::kPinhole) {
    throw InvalidArgument(
        "make_layout_scene: a direction layout has no pinhole image (points only)");
  }

  Scene scene;
  scene.model = entries;
  scene.focal = options.focal_px;
  scene.principal_point = options.principal_point;
  scene.R_true = options.viewpoint
                     ? rotation_with_viewpoint(*options.viewpoint, random.uniform(0.0, 2.0 * kPi))
                     : random.rotation();
  const double depth = options.range * size;
  scene.p_true =
      Eigen::Vector3d(options.lateral_offset.x() * size, options.lateral_offset.y() * size, depth) -
      scene.R_true * aim;
  scene.alpha_true = depth / options.focal_px;

  const Eigen::Matrix3Xd camera_points =
      vectors ? Eigen::Matrix3Xd(scene.R_true * entries)
              : Eigen::Matrix3Xd((scene.R_true * entries).colwise() + scene.p_true);
  if (vectors) {
    scene.kind = SceneKind::kAffineVectors;
    scene.has_translation = false;
    scene.image_clean = camera_points.topRows<2>() / scene.alpha_true;
  } else if (options.camera == CameraModel::kAffine) {
    scene.kind = SceneKind::kAffineImage;
    scene.image_clean =
        (camera_points.topRows<2>() / scene.alpha_true).colwise() + options.principal_point;
  } else {
    scene.kind = SceneKind::kPinholeImage;
    scene.image_clean.resize(2, entries.cols());
    for (Eigen::Index i = 0; i < entries.cols(); ++i) {
      scene.image_clean.col(i) =
          options.focal_px * camera_points.col(i).head<2>() / camera_points(2, i) +
          options.principal_point;
    }
  }
  scene.sigma = options.snr_db ? sigma_from_snr(*options.snr_db, peak_to_peak(scene.image_clean))
                               : options.noise_px;
  scene.image = scene.image_clean;
  add_noise(scene.image, options.noise, scene.sigma, random);
  if (!vectors) {
    scene.measured = camera_points;
    add_noise(scene.measured, options.noise, scene.sigma * scene.alpha_true, random);
  }
  return scene;
}

}  // namespace vantage::simulate
