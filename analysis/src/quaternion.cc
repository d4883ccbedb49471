#include "vantage/analysis/quaternion.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vantage {

Eigen::Matrix3d hat(const Eigen::Vector3d& z) {
  Eigen::Matrix3d h;
  h << 0.0, -z.z(), z.y(), z.z(), 0.0, -z.x(), -z.y(), z.x(), 0.0;
  return h;
}

Eigen::Matrix4d quaternion_k(const Eigen::Vector3d& v, const Eigen::Vector3d& z) {
  Eigen::Matrix4d K;
  K.topLeftCorner<3, 3>() =
      v * z.transpose() + z * v.transpose() - 2.0 * v.dot(z) * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d zxv = z.cross(v);
  K.topRightCorner<3, 1>() = zxv;
  K.bottomLeftCorner<1, 3>() = zxv.transpose();
  K(3, 3) = 0.0;
  return K;
}

Eigen::Matrix3d rotation_from_quaternion(const Eigen::Vector4d& eps) {
  const Eigen::Vector3d e = eps.head<3>();
  return 2.0 * ((0.5 - e.squaredNorm()) * Eigen::Matrix3d::Identity() + e * e.transpose() +
                eps(3) * hat(e));
}

Eigen::Vector4d quaternion_from_rotation(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  q.normalize();
  Eigen::Vector4d eps(q.x(), q.y(), q.z(), q.w());
  if (eps(3) < 0.0) eps = -eps;
  return eps;
}

namespace internal {

namespace {

constexpr int kMaxNewtonIterations = 100;
// Newton stops once a step is below this fraction of the iterate's magnitude (a few ulps).
constexpr double kNewtonRelativeStep = 4.0 * std::numeric_limits<double>::epsilon();

template <typename Poly, typename Derivative>
double newton_from_above(double x, double floor, Poly p, Derivative dp) {
  for (int it = 0; it < kMaxNewtonIterations; ++it) {
    const double slope = dp(x);
    if (!(slope > 0.0)) break;
    const double step = p(x) / slope;
    if (!(step > 0.0)) break;  // at or below the root: monotone convergence is over
    x -= step;
    if (x <= floor) return floor;
    if (step <= kNewtonRelativeStep * std::max(1.0, std::abs(x))) break;
  }
  return x;
}

}  // namespace

Eigen::Vector2d largest_two_quartic_roots(double c2, double c1, double c0, double x0) {
  const double lowest = -std::numeric_limits<double>::infinity();
  const double r1 = newton_from_above(
      x0, lowest, [&](double x) { return ((x * x + c2) * x + c1) * x + c0; },
      [&](double x) { return (4.0 * x * x + 2.0 * c2) * x + c1; });
  // Deflate: p(x) = (x - r1) (x^3 + r1 x^2 + b x + c).
  const double b = c2 + r1 * r1;
  const double c = c1 + r1 * b;
  const double r2 = newton_from_above(
      r1, lowest, [&](double x) { return ((x + r1) * x + b) * x + c; },
      [&](double x) { return (3.0 * x + 2.0 * r1) * x + b; });
  return {r1, std::min(r1, r2)};
}

}  // namespace internal

namespace {

double minor3(const Eigen::Matrix4d& A, int skip_row, int skip_col) {
  int r[3], c[3];
  for (int i = 0, k = 0; i < 4; ++i)
    if (i != skip_row) r[k++] = i;
  for (int j = 0, k = 0; j < 4; ++j)
    if (j != skip_col) c[k++] = j;
  return A(r[0], c[0]) * (A(r[1], c[1]) * A(r[2], c[2]) - A(r[1], c[2]) * A(r[2], c[1])) -
         A(r[0], c[1]) * (A(r[1], c[0]) * A(r[2], c[2]) - A(r[1], c[2]) * A(r[2], c[0])) +
         A(r[0], c[2]) * (A(r[1], c[0]) * A(r[2], c[1]) - A(r[1], c[1]) * A(r[2], c[0]));
}

TopEigenpair full_solver(const Eigen::Matrix4d& M, double shift) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(M);
  TopEigenpair out;
  out.lambda = solver.eigenvalues()(3) + shift;
  out.gap = std::max(0.0, solver.eigenvalues()(3) - solver.eigenvalues()(2));
  out.vector = solver.eigenvectors().col(3).normalized();
  out.used_fallback = true;
  return out;
}

}  // namespace

TopEigenpair top_eigenpair(const Eigen::Matrix4d& D, const TopEigenOptions& options) {
  const double shift = D.trace() / 4.0;
  Eigen::Matrix4d M = D.selfadjointView<Eigen::Lower>();
  M.diagonal().array() -= shift;

  TopEigenpair out;
  if (options.force_full_solver) {
    out = full_solver(M, shift);
  } else {
    const Eigen::Matrix4d M2 = M * M;
    const double frobenius2 = M2.trace();
    const double scale = std::sqrt(frobenius2);
    if (!(scale > 0.0)) {
      out = full_solver(M, shift);
    } else {
      const double c2 = -0.5 * frobenius2;
      const double c1 = -M2.cwiseProduct(M).sum() / 3.0;
      const double c0 = M.determinant();
      // For a traceless symmetric 4x4 matrix, lambda_max <= sqrt(3/4) ||M||_F.
      const Eigen::Vector2d roots =
          internal::largest_two_quartic_roots(c2, c1, c0, std::sqrt(0.75) * scale * (1.0 + 1e-12));
      const double gap = roots(0) - roots(1);
      if (!(gap > options.fallback_relative_gap * scale)) {
        out = full_solver(M, shift);
      } else {
        Eigen::Matrix4d A = M;
        A.diagonal().array() -= roots(0);
        // Each column of adj(A) is parallel to the top eigenvector; take the largest one.
        Eigen::Vector4d best = Eigen::Vector4d::Zero();
        double best_norm = -1.0;
        for (int j = 0; j < 4; ++j) {
          Eigen::Vector4d col;
          for (int i = 0; i < 4; ++i) col(i) = ((i + j) % 2 == 0 ? 1.0 : -1.0) * minor3(A, j, i);
          const double norm = col.squaredNorm();
          if (norm > best_norm) {
            best_norm = norm;
            best = col;
          }
        }
        if (!(best_norm > 0.0) || !std::isfinite(best_norm)) {
          out = full_solver(M, shift);
        } else {
          out.lambda = roots(0) + shift;
          out.gap = gap;
          out.vector = best / std::sqrt(best_norm);
          out.used_fallback = false;
        }
      }
    }
  }
  if (out.vector(3) < 0.0) out.vector = -out.vector;
  return out;
}

}  // namespace vantage
