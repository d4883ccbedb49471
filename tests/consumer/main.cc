// Theorem 1 through the installed library: rotate a few vectors by a known rotation, scale them,
// and check that absolute_orientation() recovers rotation and scale. Exit status 0 only then.

#include <cmath>
#include <cstdio>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/quaternion.h"

int main() {
  // Noise-free data: the solver must return the truth up to rounding.
  constexpr double kToleranceRadians = 1e-9;
  const Eigen::Vector4d eps = Eigen::Vector4d(0.2, -0.4, 0.5, 0.7).normalized();  // [e; eps4]
  const Eigen::Matrix3d R_true = vantage::rotation_from_quaternion(eps);
  const double alpha_true = 2.5;

  Eigen::Matrix3Xd z_object(3, 4);
  z_object << 1.0, 0.0, 0.0, 0.3,  //
      0.0, 1.0, 0.0, -0.7,         //
      0.0, 0.0, 1.0, 0.2;
  const Eigen::Matrix3Xd v_camera = R_true * z_object / alpha_true;

  const vantage::OrientationResult result = vantage::absolute_orientation(z_object, v_camera);
  const double error = vantage::rotation_angle_between(result.R_camera_object, R_true);
  std::printf("status %s, rotation error %.3g rad, alpha %.12g (true %.12g)\n",
              vantage::to_string(result.status), error, result.alpha, alpha_true);
  const bool ok = result.status == vantage::OrientationStatus::kOk && error < kToleranceRadians &&
                  std::abs(result.alpha - alpha_true) < kToleranceRadians * alpha_true;
  return ok ? 0 : 1;
}
