#include "vantage/simulate/seed_scenes.h"

#include <Eigen/Geometry>
#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

constexpr double kDegToRad = 1.0 / kDegreesPerRadian;
constexpr double kMinDepth = 0.1;  // closest a point may come to camera 2 (object units)

void check_n(int n, int minimum, const char* where) {
  if (n < minimum) {
    throw InvalidArgument(std::string(where) + ": n must be >= " + std::to_string(minimum));
  }
}

Eigen::Matrix3Xd uniform_points(int n, double half_side, TrialRandom& random) {
  Eigen::Matrix3Xd points(3, n);
  for (int i = 0; i < n; ++i) {
    for (int r = 0; r < 3; ++r) points(r, i) = random.uniform(-half_side, half_side);
  }
  return points;
}

Eigen::Vector2d project(const Eigen::Vector3d& x) { return x.head<2>() / x.z(); }

}  // namespace

Scene make_planar_2d_scene(int n, NoiseKind noise, double sigma, TrialRandom& random) {
  check_n(n, 2, "make_planar_2d_scene");
  Scene scene;
  scene.kind = SceneKind::kPlanar2d;
  scene.model = Eigen::Matrix3Xd::Zero(3, n);
  for (int i = 0; i < n; ++i) {
    scene.model(0, i) = random.uniform(-2.0, 2.0);
    scene.model(1, i) = random.uniform(-2.0, 2.0);
  }
  const double theta = random.uniform(-15.0, 15.0) * kDegToRad;
  scene.R_true = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).matrix();
  scene.p_true = Eigen::Vector3d(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0), 0.0);
  scene.image_clean = ((scene.R_true * scene.model).colwise() + scene.p_true).topRows<2>();
  scene.image = scene.image_clean;
  scene.sigma = sigma;
  add_noise(scene.image, noise, sigma, random);
  return scene;
}

Scene make_points_3d_scene(int n, NoiseKind noise, double sigma, TrialRandom& random) {
  check_n(n, 3, "make_points_3d_scene");
  Scene scene;
  scene.kind = SceneKind::kPoints3d;
  scene.model = uniform_points(n, 2.0, random);
  scene.R_true = random.rotation();
  scene.p_true = Eigen::Vector3d(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0),
                                 random.uniform(-1.0, 1.0));
  scene.measured = (scene.R_true * scene.model).colwise() + scene.p_true;
  scene.sigma = sigma;
  add_noise(scene.measured, noise, sigma, random);
  return scene;
}

Scene make_two_view_scene(int n, const TwoViewScene& geometry, NoiseKind noise, double sigma,
                          TrialRandom& random) {
  check_n(n, 8, "make_two_view_scene");
  if (!(geometry.depth_min > 0.0 && geometry.depth_max >= geometry.depth_min &&
        geometry.translation >= 0.0 && geometry.euler_deg >= 0.0)) {
    throw InvalidArgument("make_two_view_scene: geometry must have 0 < depth_min <= depth_max");
  }
  Scene scene;
  scene.kind = SceneKind::kTwoView;
  const double e = geometry.euler_deg * kDegToRad;
  scene.R_true = (Eigen::AngleAxisd(random.uniform(-e, e), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(random.uniform(-e, e), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(random.uniform(-e, e), Eigen::Vector3d::UnitX()))
                     .matrix();
  const double t = geometry.translation;
  scene.p_true =
      Eigen::Vector3d(random.uniform(-t, t), random.uniform(-t, t), random.uniform(-t, t));
  scene.model.resize(3, n);
  scene.first_view.resize(2, n);
  scene.image_clean.resize(2, n);
  for (int i = 0; i < n; ++i) {
    for (;;) {
      const Eigen::Vector2d xy(random.uniform(-2.0, 2.0), random.uniform(-2.0, 2.0));
      const double z = random.uniform(geometry.depth_min, geometry.depth_max);
      const Eigen::Vector3d x1(xy.x() * z, xy.y() * z, z);
      const Eigen::Vector3d x2 = scene.R_true * x1 + scene.p_true;
      if (x2.z() < kMinDepth) continue;
      scene.model.col(i) = x1;
      scene.first_view.col(i) = xy;
      scene.image_clean.col(i) = project(x2);
      break;
    }
  }
  scene.image = scene.image_clean;
  scene.sigma = sigma;
  add_noise(scene.first_view, noise, sigma, random);
  add_noise(scene.image, noise, sigma, random);
  return scene;
}

Scene make_wu_scene(int n, double snr_db, TrialRandom& random) {
  check_n(n, 3, "make_wu_scene");
  Scene scene;
  scene.kind = SceneKind::kPinholeImage;
  scene.focal = kWuFocalPx;
  scene.model = uniform_points(n, 1.0, random);
  scene.R_true = random.rotation();
  scene.p_true = Eigen::Vector3d(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0),
                                 random.uniform(8.0, 12.0));
  const Eigen::Matrix3Xd camera = (scene.R_true * scene.model).colwise() + scene.p_true;
  scene.image_clean.resize(2, n);
  for (int i = 0; i < n; ++i) scene.image_clean.col(i) = kWuFocalPx * project(camera.col(i));
  scene.alpha_true = scene.p_true.z() / kWuFocalPx;
  scene.sigma = sigma_from_snr(snr_db, peak_to_peak(scene.image_clean));
  scene.image = scene.image_clean;
  add_noise(scene.image, NoiseKind::kGaussian, scene.sigma, random);
  scene.measured = camera;
  add_noise(scene.measured, NoiseKind::kGaussian, scene.sigma * scene.alpha_true, random);
  return scene;
}

}  // namespace vantage::simulate
