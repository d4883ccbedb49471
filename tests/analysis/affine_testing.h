#pragma once

/// Affine test data shared by affine_orientation_test.cc and affine_pose_test.cc.

#include <Eigen/Core>
#include <random>

#include "support/eigen_testing.h"

namespace vantage::testing {

/// A rotation whose viewpoint (third row) is perpendicular to u: R u lies in the image plane, so
/// the LUB scale of Eq. (23) is exact for data containing u.
inline Eigen::Matrix3d rotation_with_in_plane(std::mt19937& rng, const Eigen::Vector3d& u) {
  const Eigen::Vector3d n = u.normalized();
  Eigen::Vector3d a = random_unit_vector(rng);
  a = (a - a.dot(n) * n).normalized();
  Eigen::Vector3d r1 = random_unit_vector(rng);
  r1 = (r1 - r1.dot(a) * a).normalized();
  Eigen::Matrix3d R;
  R.row(0) = r1.transpose();
  R.row(1) = a.cross(r1).transpose();
  R.row(2) = a.transpose();
  return R;
}

/// Noise-free affine image of free vectors: alpha d_i = P R z_i (Eq. 14).
inline Eigen::Matrix2Xd affine_image(const Eigen::Matrix3d& R, const Eigen::Matrix3Xd& z,
                                     double alpha) {
  return (R * z).topRows<2>() / alpha;
}

/// Indices (i, j) of the two points farthest apart.
inline std::pair<int, int> farthest_pair(const Eigen::Matrix3Xd& points) {
  std::pair<int, int> best{0, 1};
  double best_distance = -1.0;
  for (int i = 0; i < points.cols(); ++i) {
    for (int j = i + 1; j < points.cols(); ++j) {
      const double distance = (points.col(i) - points.col(j)).norm();
      if (distance > best_distance) {
        best_distance = distance;
        best = {i, j};
      }
    }
  }
  return best;
}

}  // namespace vantage::testing
