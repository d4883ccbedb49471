// The RMS residual of the best rigid fit by a rotation or an improper orthogonal transform
// (docs/math.md §24), on §3's optimal rotation.

#include "orthogonal_fit.h"

#include <cmath>

#include "vantage/analysis/absolute_orientation.h"

namespace vantage::internal {

double orthogonal_fit_rms(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y, bool improper) {
  const Eigen::Index n = x.cols();
  Eigen::Matrix3Xd z = x.colwise() - x.rowwise().mean();
  const Eigen::Matrix3Xd v = y.colwise() - y.rowwise().mean();
  if (improper) z.row(0) = -z.row(0);
  // optimal_rotation maximises trace(R H) = sum v_i^T R z_i for H = sum z_i v_i^T.
  const Eigen::Matrix3d H = z * v.transpose();
  const Eigen::Matrix3d R = optimal_rotation(H);
  const double sum = ((R * z) - v).colwise().squaredNorm().sum();
  return std::sqrt(sum / static_cast<double>(n));
}

double rms_radius(const Eigen::Matrix3Xd& x) {
  const Eigen::Matrix3Xd c = x.colwise() - x.rowwise().mean();
  return std::sqrt(c.colwise().squaredNorm().sum() / static_cast<double>(x.cols()));
}

}  // namespace vantage::internal
