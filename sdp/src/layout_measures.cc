#include "vantage/sdp/layout_measures.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {

double pbar_ceiling(long m) {
  vantage::internal::check_min_count("m", m, 1, "data vector");
  return std::cos(kPi / (2.0 * static_cast<double>(m)));
}

Coplanarity coplanarity(const Eigen::Matrix3Xd& vectors, double threshold) {
  if (!(threshold >= 0.0)) vantage::internal::fail("threshold", "must be >= 0");
  vantage::internal::check_min_count("vectors", vectors.cols(), 1, "column");
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "vectors");
  // Singular values of N / sqrt(m) are the square roots of the eigenvalues of N N^T / m.
  const Eigen::Matrix3d scatter = n * n.transpose() / static_cast<double>(n.cols());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  Coplanarity out;
  out.smallest_singular_value = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
  out.normal = eig.eigenvectors().col(0);
  out.threshold = threshold;
  out.nearly_coplanar = out.smallest_singular_value < threshold;
  return out;
}

}  // namespace vantage::sdp
