#include "vantage/analysis/absolute_orientation.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/scaling.h"

namespace vantage {

const char* to_string(OrientationMethod method) {
  switch (method) {
    case OrientationMethod::kQMethod:
      return "qmethod";
    case OrientationMethod::kSvd:
      return "svd";
    case OrientationMethod::kFoam:
      return "foam";
  }
  return "unknown";
}

std::optional<OrientationMethod> parse_orientation_method(std::string_view name) {
  for (const OrientationMethod method :
       {OrientationMethod::kQMethod, OrientationMethod::kSvd, OrientationMethod::kFoam}) {
    if (name == to_string(method)) return method;
  }
  return std::nullopt;
}

const char* to_string(OrientationStatus status) {
  switch (status) {
    case OrientationStatus::kOk:
      return "ok";
    case OrientationStatus::kDegenerate:
      return "degenerate";
    case OrientationStatus::kNotCentred:
      return "not_centred";
  }
  return "unknown";
}

bool OrientationOptions::is_valid(std::string* why) const {
  using internal::invalid_option;
  if (!(degenerate_gap >= 0.0 && degenerate_gap < 1.0)) {
    return invalid_option(why, "degenerate_gap", "must be in [0, 1)");
  }
  if (!(centred_tolerance >= 0.0)) return invalid_option(why, "centred_tolerance", "must be >= 0");
  if (!(eigen.fallback_relative_gap >= 0.0 && eigen.fallback_relative_gap < 1.0)) {
    return invalid_option(why, "eigen.fallback_relative_gap", "must be in [0, 1)");
  }
  return true;
}

namespace {

/// Weighted sufficient statistics of a correspondence set: every solver below needs only these.
struct Moments {
  double weight_sum = 0.0;
  Eigen::Vector3d z_sum = Eigen::Vector3d::Zero();  // sum w z
  Eigen::Vector3d v_sum = Eigen::Vector3d::Zero();  // sum w v
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();      // sum w z v^T
  double zz = 0.0;                                  // sum w |z|^2
  double vv = 0.0;                                  // sum w |v|^2
};

/// Throws InvalidArgument naming the first non-finite column, if any.
void check_finite_columns(const Eigen::Matrix3Xd& z, const Eigen::Matrix3Xd& v) {
  internal::check_finite_columns("z_object", z);
  internal::check_finite_columns("measured", v);
}

/// Options, sizes and weights. The finiteness of z and v is checked by moments(), in the same
/// pass over the data.
void validate_shapes(const Eigen::Matrix3Xd& z, const Eigen::Matrix3Xd& v, const Eigen::VectorXd& w,
                     const OrientationOptions& options) {
  internal::check_options("options", options);
  internal::check_count_matches("measured", v.cols(), z.cols(), "z_object");
  internal::check_min_count("z_object", z.cols(), 1, "correspondence");
  internal::check_weights("weights", w, z.cols(), "z_object");
}

void validate(const Eigen::Matrix3Xd& z, const Eigen::Matrix3Xd& v, const Eigen::VectorXd& w,
              const OrientationOptions& options) {
  validate_shapes(z, v, w, options);
  check_finite_columns(z, v);
}

/// One pass over the data, the 21 sums in scalar locals (unrolled by hand: kept in registers,
/// where sums stored in a Moments or in arrays would go through memory on every column).
template <bool kWeighted>
Moments accumulate_moments(const Eigen::Matrix3Xd& z, const Eigen::Matrix3Xd& v,
                           const Eigen::VectorXd& w) {
  const double* zp = z.data();
  const double* vp = v.data();
  double zz = 0.0, vv = 0.0;
  double sz0 = 0.0, sz1 = 0.0, sz2 = 0.0, sv0 = 0.0, sv1 = 0.0, sv2 = 0.0;
  double h00 = 0.0, h01 = 0.0, h02 = 0.0, h10 = 0.0, h11 = 0.0, h12 = 0.0, h20 = 0.0, h21 = 0.0,
         h22 = 0.0;
  const Eigen::Index n = z.cols();
  for (Eigen::Index i = 0; i < n; ++i, zp += 3, vp += 3) {
    const double wi = kWeighted ? w(i) : 1.0;
    const double z0 = zp[0], z1 = zp[1], z2 = zp[2];
    const double wv0 = wi * vp[0], wv1 = wi * vp[1], wv2 = wi * vp[2];
    sz0 += kWeighted ? wi * z0 : z0;
    sz1 += kWeighted ? wi * z1 : z1;
    sz2 += kWeighted ? wi * z2 : z2;
    sv0 += wv0;
    sv1 += wv1;
    sv2 += wv2;
    h00 += z0 * wv0;
    h01 += z0 * wv1;
    h02 += z0 * wv2;
    h10 += z1 * wv0;
    h11 += z1 * wv1;
    h12 += z1 * wv2;
    h20 += z2 * wv0;
    h21 += z2 * wv1;
    h22 += z2 * wv2;
    const double z_norm2 = z0 * z0 + z1 * z1 + z2 * z2;
    zz += kWeighted ? wi * z_norm2 : z_norm2;
    vv += wv0 * vp[0] + wv1 * vp[1] + wv2 * vp[2];
  }
  Moments m;
  m.weight_sum = kWeighted ? w.sum() : static_cast<double>(n);
  m.z_sum << sz0, sz1, sz2;
  m.v_sum << sv0, sv1, sv2;
  m.H << h00, h01, h02, h10, h11, h12, h20, h21, h22;
  m.zz = zz;
  m.vv = vv;
  return m;
}

/// The moments of validated shapes (validate_shapes()), checking that z and v are finite on the
/// way: with positive finite weights, sum w |z|^2 and sum w |v|^2 are finite unless an entry is
/// not (or the sums overflow, which the column check then lets through as before).
Moments moments(const Eigen::Matrix3Xd& z, const Eigen::Matrix3Xd& v, const Eigen::VectorXd& w) {
  const Moments m =
      w.size() == 0 ? accumulate_moments<false>(z, v, w) : accumulate_moments<true>(z, v, w);
  if (!(std::isfinite(m.zz) && std::isfinite(m.vv))) check_finite_columns(z, v);
  return m;
}

/// Moments of the data centred at their weighted centroids.
Moments centred(const Moments& m) {
  Moments c = m;
  const Eigen::Vector3d z_bar = m.z_sum / m.weight_sum;
  const Eigen::Vector3d v_bar = m.v_sum / m.weight_sum;
  c.z_sum.setZero();
  c.v_sum.setZero();
  c.H -= m.weight_sum * z_bar * v_bar.transpose();
  c.zz = std::max(0.0, m.zz - m.weight_sum * z_bar.squaredNorm());
  c.vv = std::max(0.0, m.vv - m.weight_sum * v_bar.squaredNorm());
  return c;
}

/// Upper bound of lambda_max = max_R trace(R H) from the moments: trace(R H) = sum w v^T R z <=
/// sum w |v||z| <= sqrt(zz vv) (Cauchy-Schwarz), equal to lambda_max for noise-free data, so the
/// root iteration starts at the root. (The iteration itself falls back to a bound from H alone
/// when this one is looser or spoilt by rounding.)
double lambda_upper_from_moments(const Moments& m) {
  return std::sqrt(m.zz * m.vv) * (1.0 + 1e-12);
}

/// trace(A B) = sum_ij A_ij B_ji, without forming the product.
double trace_of_product(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  return A.cwiseProduct(B.transpose()).sum();
}

/// adj(M) = cofactor(M)^T; its rows are cross products of M's columns.
Eigen::Matrix3d adjugate(const Eigen::Matrix3d& M) {
  Eigen::Matrix3d adj;
  adj.row(0) = M.col(1).cross(M.col(2)).transpose();
  adj.row(1) = M.col(2).cross(M.col(0)).transpose();
  adj.row(2) = M.col(0).cross(M.col(1)).transpose();
  return adj;
}

struct RotationSolve {
  Eigen::Matrix3d R;
  double gap = 0.0;
  bool used_fallback = false;
};

/// Maximises trace(R H) over SO(3) with Haralick's SVD and the reflection guard.
RotationSolve rotation_svd(const Eigen::Matrix3d& H) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d& U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  const double d = (V * U.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  S(2, 2) = d;
  const Eigen::Vector3d s = svd.singularValues();
  // Eigenvalues of Davenport's matrix are +-s1 +-s2 +-d s3; the top two differ by 2 (s2 + d s3).
  return {V * S * U.transpose(), std::max(0.0, 2.0 * (s(1) + d * s(2))), false};
}

/// Theorem 1 through Davenport's K = D + trace(H) I (docs/math.md §2): traceless, with the same
/// eigenvectors and gaps as D, and with FOAM's quartic (docs/math.md §5) as characteristic
/// polynomial, which costs a few 3x3 products instead of a 4x4 one.
RotationSolve rotation_qmethod(const Eigen::Matrix3d& H, double lambda_upper,
                               const TopEigenOptions& eigen) {
  const double trace = H.trace();
  Eigen::Matrix4d K;
  K.topLeftCorner<3, 3>() = H + H.transpose() - trace * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d zxv(H(1, 2) - H(2, 1), H(2, 0) - H(0, 2), H(0, 1) - H(1, 0));
  K.topRightCorner<3, 1>() = zxv;
  K.bottomLeftCorner<1, 3>() = zxv.transpose();
  K(3, 3) = trace;
  const double f2 = H.squaredNorm();
  const double c0 = f2 * f2 - 4.0 * adjugate(H).squaredNorm();
  const TopEigenpair top = internal::top_eigenpair_traceless(K, -2.0 * f2, -8.0 * H.determinant(),
                                                             c0, lambda_upper, eigen);
  return {rotation_from_quaternion(top.vector), top.gap, top.used_fallback};
}

/// FOAM (docs/math.md §5) with B = sum w b r^T = H^T (b = v measured, r = z reference).
/// Like the q-method's eigensolver, the root iteration is not trusted when the top two roots
/// nearly coincide (it converges only linearly there): the SVD solution, exact in that case, is
/// used instead.
RotationSolve rotation_foam(const Eigen::Matrix3d& H, double lambda_start,
                            double fallback_relative_gap) {
  const Eigen::Matrix3d B = H.transpose();
  const double f2 = B.squaredNorm();
  const double det_b = B.determinant();
  const Eigen::Matrix3d adj_b = adjugate(B);
  const double adj2 = adj_b.squaredNorm();
  // (lambda^2 - |B|^2)^2 - 8 lambda det B - 4 |adj B|^2 = 0, written as a depressed quartic.
  const Eigen::Vector2d roots = internal::largest_two_quartic_roots(
      -2.0 * f2, -8.0 * det_b, f2 * f2 - 4.0 * adj2, lambda_start);
  const double lambda = roots(0);
  const double kappa = 0.5 * (lambda * lambda - f2);
  const double zeta = kappa * lambda - det_b;
  // zeta vanishes when B has rank <= 1; the attitude formula then divides by ~0.
  const double gap = roots(0) - roots(1);
  if (!(gap > fallback_relative_gap * 2.0 * std::sqrt(f2)) || !(std::abs(zeta) > 0.0)) {
    RotationSolve fallback = rotation_svd(H);
    fallback.used_fallback = true;
    return fallback;
  }
  const Eigen::Matrix3d A =
      ((kappa + f2) * B + lambda * adj_b.transpose() - B * B.transpose() * B) / zeta;
  return {A, gap, false};
}

/// lambda_upper: an upper bound of max_R trace(R H), the root iteration's start for q-method
/// and FOAM.
RotationSolve solve_rotation(const Eigen::Matrix3d& H, double lambda_upper,
                             const OrientationOptions& options) {
  switch (options.method) {
    case OrientationMethod::kSvd:
      return rotation_svd(H);
    case OrientationMethod::kFoam:
      return rotation_foam(H, lambda_upper, options.eigen.fallback_relative_gap);
    case OrientationMethod::kQMethod:
      break;
  }
  return rotation_qmethod(H, lambda_upper, options.eigen);
}

OrientationStatus classify(const RotationSolve& solve, const Eigen::Matrix3d& H,
                           const OrientationOptions& options, std::string* message) {
  const double scale = 2.0 * H.norm();
  if (!(solve.gap > options.degenerate_gap * scale) || !(scale > 0.0)) {
    *message =
        "the data do not determine the rotation: the vectors are all parallel (collinear "
        "points) or too few";
    return OrientationStatus::kDegenerate;
  }
  return OrientationStatus::kOk;
}

// Data whose largest magnitude is beyond 2^+-kSafeExponent are rescaled (by powers of two, so
// exactly) before the moments are formed: their sums of squares would over- or underflow (a
// point at 1e308, or data in units of 1e-200) and fake coincident points.
constexpr int kSafeExponent = 256;

bool needs_rescaling(int ez, int ev) {
  return std::abs(ez) > kSafeExponent || std::abs(ev) > kSafeExponent;
}

}  // namespace

Eigen::Matrix4d orientation_matrix_d(const Eigen::Matrix3Xd& z_object,
                                     const Eigen::Matrix3Xd& v_camera,
                                     const Eigen::VectorXd& weights) {
  validate(z_object, v_camera, weights, OrientationOptions{});
  Eigen::Matrix4d D = Eigen::Matrix4d::Zero();
  for (Eigen::Index i = 0; i < z_object.cols(); ++i) {
    const double wi = weights.size() == 0 ? 1.0 : weights(i);
    D += wi * quaternion_k(v_camera.col(i), z_object.col(i));
  }
  return D;
}

OrientationResult absolute_orientation(const Eigen::Matrix3Xd& z_object,
                                       const Eigen::Matrix3Xd& v_camera,
                                       const Eigen::VectorXd& weights,
                                       const OrientationOptions& options) {
  validate_shapes(z_object, v_camera, weights, options);
  const int ez = binary_exponent(z_object), ev = binary_exponent(v_camera);
  if (needs_rescaling(ez, ev)) {
    // alpha' v' = R z' with z' = z 2^-ez, v' = v 2^-ev.
    OrientationResult r =
        absolute_orientation(scaled_by_power_of_two(z_object, ez),
                             scaled_by_power_of_two(v_camera, ev), weights, options);
    r.alpha = std::ldexp(r.alpha, ez - ev);
    r.residual = std::ldexp(r.residual, 2 * ez);
    r.eigen_gap = std::ldexp(r.eigen_gap, ez + ev);
    return r;
  }
  const Moments m = moments(z_object, v_camera, weights);
  if (!(m.vv > 0.0)) internal::fail("measured", "every measured vector is zero");

  const RotationSolve solve = solve_rotation(m.H, lambda_upper_from_moments(m), options);
  OrientationResult result;
  result.R_camera_object = solve.R;
  result.quaternion = quaternion_from_rotation(solve.R);
  result.eigen_gap = solve.gap;
  result.used_fallback = solve.used_fallback;
  const double correlation = trace_of_product(solve.R, m.H);  // sum w v^T R z
  result.alpha = std::max(0.0, correlation) / m.vv;           // Eq. (4)
  result.residual =
      std::max(0.0, m.zz - 2.0 * result.alpha * correlation + result.alpha * result.alpha * m.vv);
  result.status = classify(solve, m.H, options, &result.message);
  return result;
}

PoseResult absolute_pose(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix3Xd& q_camera,
                         const Eigen::VectorXd& weights, const OrientationOptions& options) {
  validate_shapes(z_object, q_camera, weights, options);
  const int ez = binary_exponent(z_object), eq = binary_exponent(q_camera);
  if (needs_rescaling(ez, eq)) {
    // alpha' q' = R z' + p' with z' = z 2^-ez, q' = q 2^-eq.
    PoseResult r = absolute_pose(scaled_by_power_of_two(z_object, ez),
                                 scaled_by_power_of_two(q_camera, eq), weights, options);
    r.alpha = std::ldexp(r.alpha, ez - eq);
    r.p_camera_object *= std::ldexp(1.0, ez / 2);
    r.p_camera_object *= std::ldexp(1.0, ez - ez / 2);
    r.residual = std::ldexp(r.residual, 2 * ez);
    r.eigen_gap = std::ldexp(r.eigen_gap, ez + eq);
    return r;
  }
  const Moments m = moments(z_object, q_camera, weights);
  const Moments c = centred(m);
  if (!(c.vv > 0.0))
    internal::fail("measured", "all measured points coincide, the scale is undefined");
  const RotationSolve solve = solve_rotation(c.H, lambda_upper_from_moments(c), options);
  PoseResult result;
  result.R_camera_object = solve.R;
  result.eigen_gap = solve.gap;
  result.used_fallback = solve.used_fallback;
  const double correlation = trace_of_product(solve.R, c.H);
  result.alpha = std::max(0.0, correlation) / c.vv;
  // Eq. (13): p = (alpha sum w q - sum w R z) / sum w.
  result.p_camera_object = (result.alpha * m.v_sum - solve.R * m.z_sum) / m.weight_sum;
  result.residual =
      std::max(0.0, c.zz - 2.0 * result.alpha * correlation + result.alpha * result.alpha * c.vv);
  result.status = classify(solve, c.H, options, &result.message);
  return result;
}

PoseResult decoupled_pose(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix3Xd& q_camera,
                          double alpha, const Eigen::VectorXd& weights,
                          const OrientationOptions& options) {
  validate_shapes(z_object, q_camera, weights, options);
  const Moments m = moments(z_object, q_camera, weights);
  internal::check_positive_finite("alpha", alpha);
  PoseResult result;
  result.alpha = alpha;
  double z_abs_sum = 0.0;
  for (Eigen::Index i = 0; i < z_object.cols(); ++i)
    z_abs_sum += (weights.size() == 0 ? 1.0 : weights(i)) * z_object.col(i).norm();
  if (m.z_sum.norm() > options.centred_tolerance * std::max(z_abs_sum, 1e-300)) {
    result.status = OrientationStatus::kNotCentred;
    result.message =
        "sum w_i z_i != 0 (Eq. 11): Prop. 3 does not apply; choose weights with "
        "`vantage weights` or use absolute_pose(), which centres the data";
    return result;
  }
  const RotationSolve solve = solve_rotation(m.H, lambda_upper_from_moments(m), options);
  result.R_camera_object = solve.R;
  result.eigen_gap = solve.gap;
  result.used_fallback = solve.used_fallback;
  result.p_camera_object = (alpha * m.v_sum - solve.R * m.z_sum) / m.weight_sum;  // Eq. (13)
  // J of Eq. (12) expanded with sum w z = 0.
  const Eigen::Vector3d p = result.p_camera_object;
  result.residual =
      std::max(0.0, m.zz - 2.0 * alpha * trace_of_product(solve.R, m.H) + alpha * alpha * m.vv +
                        m.weight_sum * p.squaredNorm() - 2.0 * alpha * p.dot(m.v_sum));
  result.status = classify(solve, m.H, options, &result.message);
  return result;
}

Eigen::Matrix4d swap_delta_d(const Eigen::Vector3d& v_j, const Eigen::Vector3d& v_k,
                             const Eigen::Vector3d& z_j, const Eigen::Vector3d& z_k, double w_j,
                             double w_k) {
  return quaternion_k(v_k - v_j, w_j * z_j - w_k * z_k);
}

Eigen::Matrix3d optimal_rotation(const Eigen::Matrix3d& H, const OrientationOptions& options,
                                 double* eigen_gap) {
  const RotationSolve solve = solve_rotation(H, std::numeric_limits<double>::infinity(), options);
  if (eigen_gap) *eigen_gap = solve.gap;
  return solve.R;
}

Eigen::Matrix3d rotation_from_d(const Eigen::Matrix4d& D, const TopEigenOptions& options) {
  return rotation_from_quaternion(top_eigenpair(D, options).vector);
}

double rotation_angle_between(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  // 2 atan2(|e|, |eps4|) of the relative quaternion keeps full precision near 0 (acos does not).
  const Eigen::Quaterniond q(A.transpose() * B);
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

}  // namespace vantage
