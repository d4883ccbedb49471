// Test hooks of the sign-enumeration engine (vantage::internal in affine_pose.h).

#include <vector>

#include "affine_sign_enumeration.h"
#include "vantage/analysis/affine_pose.h"

namespace vantage {

namespace internal {

Eigen::Matrix4d affine_pattern_d(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_object,
                                 const Eigen::VectorXd& v_z, const Eigen::VectorXd& weights,
                                 std::uint64_t signs) {
  std::vector<int> order(z_object.cols());
  for (int i = 0; i < static_cast<int>(order.size()); ++i) order[i] = i;
  return pattern_d(z_object, d_object, v_z, weights, order, signs);
}

Eigen::Matrix4d affine_gray_code_d(const Eigen::Matrix3Xd& z_object,
                                   const Eigen::Matrix2Xd& d_object, const Eigen::VectorXd& v_z,
                                   const Eigen::VectorXd& weights, std::uint64_t steps,
                                   std::uint64_t* signs) {
  std::vector<int> order(z_object.cols());
  for (int i = 0; i < static_cast<int>(order.size()); ++i) order[i] = i;
  GrayCodeWalk walk(z_object, d_object, v_z, weights, order);
  Eigen::Matrix4d last;
  walk.run(steps, [&](const Eigen::Matrix4d& D, const Eigen::Vector3d&, std::uint64_t s) {
    last = D;
    *signs = s;
  });
  return last;
}

}  // namespace internal

}  // namespace vantage
