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
  // 2 [(0.5 - e^T e) I + e e^T + eps4 hat(e)], entry by entry.
  const double e0 = eps(0), e1 = eps(1), e2 = eps(2), w = eps(3);
  const double d = 0.5 - (e0 * e0 + e1 * e1 + e2 * e2);
  Eigen::Matrix3d R;
  R << 2.0 * (d + e0 * e0), 2.0 * (e0 * e1 - w * e2), 2.0 * (e0 * e2 + w * e1),
      2.0 * (e1 * e0 + w * e2), 2.0 * (d + e1 * e1), 2.0 * (e1 * e2 - w * e0),
      2.0 * (e2 * e0 - w * e1), 2.0 * (e2 * e1 + w * e0), 2.0 * (d + e2 * e2);
  return R;
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

constexpr int kMaxIterations = 100;
// For a traceless symmetric 4x4 matrix, lambda_max <= sqrt(3/4) ||M||_F (Laguerre-Samuelson);
// the factor's last digits keep the start above the root despite rounding.
constexpr double kUpperBound = 0.86602540378443865 * (1.0 + 1e-12);  // sqrt(3/4)
// Iteration stops once a step is below this fraction of ||M||_F (a few ulps of the roots).
constexpr double kRelativeStep = 4.0 * std::numeric_limits<double>::epsilon();

/// One step from above the largest root r of a polynomial of degree kDegree whose roots are all
/// real, by Laguerre's method or by Halley's. Both decrease monotonically to r (neither
/// overshoots: with a_i = 1/(x - r_i), Cauchy-Schwarz bounds Laguerre's step, and Halley's step
/// 2 G / (G^2 + sum a_i^2), G = sum a_i, is at most 1/a_1 because G^2 + a_1^2 >= 2 a_1 G), both
/// cubically near a simple root. Far from r Laguerre's step is much longer (exact when the other
/// roots coincide, where Halley's covers 2/(kDegree + 1) of the way), so it is taken first;
/// near r Halley's is as good and cheaper (no square root on the iteration's critical path).
/// Above r, p'/p = sum a_i <= kDegree / (x - r), so x - r <= kDegree p / p': no step is taken
/// once that bound is below tolerance. Returns true when the iteration is finished (that bound
/// or the step taken is below tolerance, or x is at, or by rounding below, the root).
/// eval(x, &p, &p', &p'') evaluates the polynomial and its derivatives.
template <int kDegree, typename Eval>
bool step_from_above(double* x, double tolerance, bool laguerre, Eval eval) {
  constexpr double n = kDegree;
  double p, d1, d2;
  eval(*x, &p, &d1, &d2);
  if (!(p > 0.0) || !(d1 > 0.0)) return true;
  if (n * p <= tolerance * d1) return true;
  // Laguerre: x - n / (G + sqrt((n - 1)(n H - G^2))) with G = p'/p, H = G^2 - p''/p; Halley:
  // x - 2 p p' / (2 p'^2 - p p''); both multiplied out.
  const double step =
      laguerre
          ? n * p / (d1 + std::sqrt(std::max(0.0, (n - 1.0) * ((n - 1.0) * d1 * d1 - n * p * d2))))
          : 2.0 * p * d1 / (2.0 * d1 * d1 - p * d2);
  *x -= step;
  return !(step > tolerance);
}

/// True when no root of the polynomial exceeds x (Budan-Fourier): it and all its derivatives
/// are >= 0 there.
template <typename Eval>
bool above_all_roots(double x, Eval eval) {
  double p, d1, d2;
  eval(x, &p, &d1, &d2);
  return p >= 0.0 && d1 >= 0.0 && d2 >= 0.0;
}

}  // namespace

Eigen::Vector2d largest_two_quartic_roots(double c2, double c1, double c0, double x0) {
  const double scale2 = std::max(0.0, -2.0 * c2);  // ||M||_F^2 = sum of the squared roots
  const double scale = std::sqrt(scale2);
  const double tolerance = kRelativeStep * scale;
  auto quartic = [&](double x, double* p, double* d1, double* d2) {
    const double x2 = x * x;
    *p = ((x2 + c2) * x + c1) * x + c0;
    *d1 = (4.0 * x2 + 2.0 * c2) * x + c1;
    *d2 = 12.0 * x2 + 2.0 * c2;
  };
  // The hint is used only when it is provably above every root, otherwise (a hint spoilt by
  // rounding or wrong) start from the Laguerre-Samuelson bound, which needs only the
  // coefficients.
  const double safe_start = kUpperBound * scale;
  if (!(x0 <= safe_start && x0 >= 0.0 && above_all_roots(x0, quartic))) x0 = safe_start;
  // lambda_2 without deflating by lambda_1, so that both iterations run side by side: for roots
  // r1 >= r2 >= r3 >= r4 summing to 0, the resolvent cubic u^3 + 2 c2 u^2 + (c2^2 - 4 c0) u - c1^2
  // has the roots (r1 + r_k)^2, k = 2, 3, 4, the largest (r1 + r2)^2 >= -2 c2 / 3 (their sum is
  // -2 c2), so r2 = sqrt(u1) - r1 loses nothing to the square root. Its roots are >= 0, so u1 is
  // at most their sum; the Laguerre-Samuelson bound mean + sqrt(2 variance) is closer.
  const double e2 = 2.0 * c2;
  const double e1 = c2 * c2 - 4.0 * c0;
  const double e0 = -c1 * c1;
  auto resolvent = [&](double u, double* p, double* d1, double* d2) {
    *p = ((u + e2) * u + e1) * u + e0;
    *d1 = (3.0 * u + 2.0 * e2) * u + e1;
    *d2 = 6.0 * u + 2.0 * e2;
  };
  const double mean = -e2 / 3.0;
  const double variance = std::max(0.0, (e2 * e2 - 2.0 * e1) / 3.0 - mean * mean);
  double u = std::min(scale2, mean + std::sqrt(2.0 * variance));
  if (!above_all_roots(u, resolvent)) u = scale2 * (1.0 + 1e-12);
  // A step of u below kRelativeStep ||M||_F^2 moves sqrt(u1) >= sqrt(2/3) ||M||_F by less than
  // a step of the quartic's iteration.
  const double tolerance_u = kRelativeStep * scale2;
  double x = x0;
  bool x_done = false, u_done = false;
  for (int it = 0; it < kMaxIterations && !(x_done && u_done); ++it) {
    const bool laguerre = it == 0;
    if (!x_done) x_done = step_from_above<4>(&x, tolerance, laguerre, quartic);
    if (!u_done) u_done = step_from_above<3>(&u, tolerance_u, laguerre, resolvent);
  }
  const double r2 = std::sqrt(std::max(0.0, u)) - x;
  return {x, std::min(x, r2)};
}

}  // namespace internal

namespace {

// kOthers[i]: the indices 0..3 without i.
constexpr int kOthers[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

/// The 3x3 minors of a 4x4 matrix from its twelve 2x2 minors (Laplace expansion): pairs[0] holds
/// the 2x2 minors of rows {2, 3}, pairs[1] those of rows {0, 1}, indexed by column pair. Row and
/// column are template arguments so that every index is resolved at compile time.
class Minors3 {
 public:
  explicit Minors3(const Eigen::Matrix4d& A) : A_(A) {
    for (int k = 0; k < 4; ++k)
      for (int l = k + 1; l < 4; ++l) {
        pairs_[0][k][l] = A(2, k) * A(3, l) - A(2, l) * A(3, k);
        pairs_[1][k][l] = A(0, k) * A(1, l) - A(0, l) * A(1, k);
      }
  }

  /// Determinant of A without row kSkipRow and column kSkipCol: expanded along the remaining row
  /// of the pair {0, 1} or {2, 3} that contains kSkipRow, times 2x2 minors of the other pair.
  template <int kSkipRow, int kSkipCol>
  double minor() const {
    // The lead row is first (kSkipRow 0, 1) or last (kSkipRow 2, 3) of the three remaining
    // rows; either way its cofactor signs are + - +.
    constexpr int kLead = kSkipRow ^ 1;
    constexpr int c0 = kOthers[kSkipCol][0], c1 = kOthers[kSkipCol][1], c2 = kOthers[kSkipCol][2];
    const auto& m = pairs_[kSkipRow < 2 ? 0 : 1];
    return A_(kLead, c0) * m[c1][c2] - A_(kLead, c1) * m[c0][c2] + A_(kLead, c2) * m[c0][c1];
  }

  /// Column kCol of adj(A) for symmetric A (cofactors of row kCol), given its diagonal entry.
  template <int kCol>
  Eigen::Vector4d adjugate_column(double diagonal) const {
    Eigen::Vector4d column;
    column(0) = kCol == 0 ? diagonal : cofactor<kCol, 0>();
    column(1) = kCol == 1 ? diagonal : cofactor<kCol, 1>();
    column(2) = kCol == 2 ? diagonal : cofactor<kCol, 2>();
    column(3) = kCol == 3 ? diagonal : cofactor<kCol, 3>();
    return column;
  }

 private:
  template <int kRow, int kCol>
  double cofactor() const {
    return (kRow + kCol) % 2 == 0 ? minor<kRow, kCol>() : -minor<kRow, kCol>();
  }

  const Eigen::Matrix4d& A_;
  double pairs_[2][4][4];
};

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

namespace internal {

TopEigenpair top_eigenpair_traceless(const Eigen::Matrix4d& M, double c2, double c1, double c0,
                                     double lambda_upper, const TopEigenOptions& options) {
  const double scale = std::sqrt(-2.0 * c2);  // ||M||_F
  if (options.force_full_solver || !(scale > 0.0)) return full_solver(M, 0.0);
  const Eigen::Vector2d roots = largest_two_quartic_roots(c2, c1, c0, lambda_upper);
  const double gap = roots(0) - roots(1);
  if (!(gap > options.fallback_relative_gap * scale)) return full_solver(M, 0.0);
  Eigen::Matrix4d A = M;
  A.diagonal().array() -= roots(0);
  // A has rank 3, so adj(A) = c q q^T for the top eigenvector q: its diagonal c q_i^2 names the
  // best-conditioned column (largest |q_i|), and that column is c q_i q.
  const Minors3 minor3(A);
  const double diagonal[4] = {minor3.minor<0, 0>(), minor3.minor<1, 1>(), minor3.minor<2, 2>(),
                              minor3.minor<3, 3>()};
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (std::abs(diagonal[i]) > std::abs(diagonal[best])) best = i;
  Eigen::Vector4d column;
  switch (best) {
    case 0:
      column = minor3.adjugate_column<0>(diagonal[0]);
      break;
    case 1:
      column = minor3.adjugate_column<1>(diagonal[1]);
      break;
    case 2:
      column = minor3.adjugate_column<2>(diagonal[2]);
      break;
    default:
      column = minor3.adjugate_column<3>(diagonal[3]);
      break;
  }
  const double norm2 = column.squaredNorm();
  if (!(norm2 > 0.0) || !std::isfinite(norm2)) return full_solver(M, 0.0);
  TopEigenpair out;
  out.lambda = roots(0);
  out.gap = gap;
  out.vector = column / std::sqrt(norm2);
  out.used_fallback = false;
  return out;
}

}  // namespace internal

TopEigenpair top_eigenpair(const Eigen::Matrix4d& D, const TopEigenOptions& options) {
  const double shift = D.trace() / 4.0;
  Eigen::Matrix4d M = D.selfadjointView<Eigen::Lower>();
  M.diagonal().array() -= shift;
  const Eigen::Matrix4d M2 = M * M;
  const double c2 = -0.5 * M2.trace();
  const double c1 = -M2.cwiseProduct(M).sum() / 3.0;
  const double c0 = M.determinant();
  TopEigenpair out = internal::top_eigenpair_traceless(
      M, c2, c1, c0, std::numeric_limits<double>::infinity(), options);
  out.lambda += shift;
  if (out.vector(3) < 0.0) out.vector = -out.vector;
  return out;
}

}  // namespace vantage
