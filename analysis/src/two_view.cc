#include "vantage/analysis/two_view.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <sstream>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/quaternion.h"

namespace vantage {

const char* to_string(TwoViewStatus status) {
  switch (status) {
    case TwoViewStatus::kOk:
      return "ok";
    case TwoViewStatus::kDegenerate:
      return "degenerate";
    case TwoViewStatus::kNoPointsInFront:
      return "no_points_in_front";
  }
  return "unknown";
}

bool TwoViewOptions::is_valid(std::string* why) const {
  using internal::invalid_option;
  if (!(focal_length > 0.0 && std::isfinite(focal_length))) {
    return invalid_option(why, "focal_length", "must be positive and finite");
  }
  if (!(degenerate_tolerance >= 0.0 && degenerate_tolerance < 1.0)) {
    return invalid_option(why, "degenerate_tolerance", "must be in [0, 1)");
  }
  return true;
}

namespace {

constexpr Eigen::Index kMinPoints = 8;

void validate(const Eigen::Matrix2Xd& image1, const Eigen::Matrix2Xd& image2,
              const TwoViewOptions& options) {
  internal::check_options("options", options);
  internal::check_count_matches("image2", image2.cols(), image1.cols(), "image1");
  internal::check_min_count("image1", image1.cols(), kMinPoints, "correspondences");
  internal::check_finite_columns("image1", image1);
  internal::check_finite_columns("image2", image2);
}

/// Columns E_2 x E_3, E_3 x E_1, E_1 x E_2 (the cofactor matrix of E).
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& E) {
  Eigen::Matrix3d C;
  C.col(0) = E.col(1).cross(E.col(2));
  C.col(1) = E.col(2).cross(E.col(0));
  C.col(2) = E.col(0).cross(E.col(1));
  return C;
}

struct Candidate {
  Eigen::Matrix3d R;
  Eigen::Vector3d T;
  int in_front = 0;
  double depth_score = 0.0;  // min of Haralick's two depth sums
};

Candidate score(const Eigen::Matrix3d& E, const Eigen::Vector3d& T, const Eigen::Matrix3Xd& m1,
                const Eigen::Matrix3Xd& m2) {
  Candidate c;
  c.R = cofactor(E) - hat(T) * E;
  c.T = T;
  double sum1 = 0.0;
  double sum2 = 0.0;
  for (Eigen::Index i = 0; i < m1.cols(); ++i) {
    const Eigen::Vector3d r = c.R * m1.col(i);
    const Eigen::Vector3d normal = m2.col(i).cross(r);
    // z1 |m2 x R m1|^2 and z2 |m2 x R m1|^2 (see the header).
    const double depth1 = -m2.col(i).cross(T).dot(normal);
    const double depth2 = T.cross(r).dot(normal);
    sum1 += depth1;
    sum2 += depth2;
    if (depth1 > 0.0 && depth2 > 0.0) ++c.in_front;
  }
  c.depth_score = std::min(sum1, sum2);
  return c;
}

}  // namespace

TwoViewResult two_view_pose(const Eigen::Matrix2Xd& image1, const Eigen::Matrix2Xd& image2,
                            const TwoViewOptions& options) {
  validate(image1, image2, options);
  const Eigen::Index n = image1.cols();
  const double inverse_focal = 1.0 / options.focal_length;
  Eigen::Matrix3Xd m1(3, n);
  Eigen::Matrix3Xd m2(3, n);
  m1.topRows<2>() = image1 * inverse_focal;
  m2.topRows<2>() = image2 * inverse_focal;
  m1.row(2).setOnes();
  m2.row(2).setOnes();

  // Eq. (c): m2^T E m1 = sum_jk m1_k m2_j E_jk = (m1 kron m2) . vec(E), vec column-major.
  Eigen::MatrixXd A(n, 9);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) A.block<1, 3>(i, 3 * k) = m1(k, i) * m2.col(i).transpose();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd_a(A, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd_a.singularValues();
  const double sigma8 = sigma(7);
  const double sigma9 = sigma.size() > 8 ? sigma(8) : 0.0;
  const Eigen::Matrix<double, 9, 1> e = svd_a.matrixV().col(8);
  const Eigen::Matrix3d E_linear = Eigen::Map<const Eigen::Matrix3d>(e.data());

  // Rank 2 with equal singular values: E = U diag(1, 1, 0) V^T; T spans the left null space.
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd_e(E_linear,
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d E =
      svd_e.matrixU() * Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal() * svd_e.matrixV().transpose();
  const Eigen::Vector3d T = svd_e.matrixU().col(2);

  Candidate best;
  best.in_front = -1;
  for (const double e_sign : {1.0, -1.0}) {
    for (const double t_sign : {1.0, -1.0}) {
      const Candidate c = score(e_sign * E, t_sign * T, m1, m2);
      if (c.in_front > best.in_front ||
          (c.in_front == best.in_front && c.depth_score > best.depth_score)) {
        best = c;
      }
    }
  }

  TwoViewResult result;
  result.R_camera2_camera1 = best.R;
  result.t_camera2_camera1 = best.T;
  result.essential = hat(best.T) * best.R;
  result.points_in_front = best.in_front;
  result.null_space_ratio = sigma8 > 0.0 ? sigma9 / sigma8 : 1.0;
  double sum_squares = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = m2.col(i).dot(result.essential * m1.col(i));
    sum_squares += r * r;
  }
  result.residual = std::sqrt(sum_squares / static_cast<double>(n));

  if (!(sigma8 > options.degenerate_tolerance * sigma(0))) {
    result.status = TwoViewStatus::kDegenerate;
    result.message =
        "the two-view motion equation has more than one independent solution: pure rotation "
        "(T = 0) or points on a critical surface (e.g. a plane)";
  } else if (2 * best.in_front <= n) {
    result.status = TwoViewStatus::kNoPointsInFront;
    std::ostringstream out;
    out << "the best decomposition places only " << best.in_front << " of " << n
        << " points in front of both cameras";
    result.message = out.str();
  }
  return result;
}

}  // namespace vantage
