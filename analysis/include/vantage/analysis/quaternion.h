#pragma once

/// Quaternion machinery of Theorem 1 (McInroy et al.): the bilinear matrix K(v, z) of Eq. (3),
/// the rotation of Eq. (5), and a fast, allocation-free top eigenpair of a symmetric 4x4 matrix.
///
/// Quaternions are stored as eps = [e; eps4] with the vector part e first and the scalar part
/// eps4 last, as in the paper. R(eps) of Eq. (5) is the active rotation: for a unit quaternion
/// with axis u and angle theta, e = sin(theta/2) u and eps4 = cos(theta/2).

#include <Eigen/Core>

namespace vantage {

/// Paper's K(v, z), Eq. (3):
///   K = [[v z^T + z v^T - 2 (v^T z) I,  hat(z) v], [(hat(z) v)^T, 0]].
/// Bilinear and symmetric; it is Davenport's K shifted by -(v^T z) I (docs/math.md §2), so for a
/// unit quaternion eps, eps^T K eps = v^T R(eps) z - v^T z.
Eigen::Matrix4d quaternion_k(const Eigen::Vector3d& v, const Eigen::Vector3d& z);

/// The cross-product ("hat") matrix: hat(z) y = z x y.
Eigen::Matrix3d hat(const Eigen::Vector3d& z);

/// R(eps) of Eq. (5): R = 2[(0.5 - e^T e) I + e e^T + eps4 hat(e)]. eps must be unit length.
Eigen::Matrix3d rotation_from_quaternion(const Eigen::Vector4d& eps);

/// Inverse of Eq. (5): the unit quaternion [e; eps4] with eps4 >= 0 whose R(eps) is R.
/// R must be a rotation matrix.
Eigen::Vector4d quaternion_from_rotation(const Eigen::Matrix3d& R);

/// Largest eigenvalue of a symmetric 4x4 matrix, its unit eigenvector and the gap to the second
/// largest eigenvalue (the conditioning of the orientation problem: a small gap means the data
/// barely determine the rotation).
struct TopEigenpair {
  double lambda = 0.0;         ///< largest eigenvalue
  double gap = 0.0;            ///< lambda_1 - lambda_2 >= 0
  Eigen::Vector4d vector;      ///< unit eigenvector of lambda_1, sign chosen so that vector(3) >= 0
  bool used_fallback = false;  ///< true when the full symmetric eigensolver was used
};

/// Options of top_eigenpair().
struct TopEigenOptions {
  /// Relative gap (lambda_1 - lambda_2) / ||D - trace(D)/4 I||_F below which the fast method
  /// (root iteration on the characteristic polynomial plus an adjugate eigenvector) is not
  /// trusted and the full symmetric eigensolver is used instead. Dimensionless.
  double fallback_relative_gap = 1e-3;
  /// Set to force the full symmetric eigensolver (the reference path in tests and benchmarks).
  bool force_full_solver = false;
};

/// Top eigenpair of the symmetric 4x4 matrix D (only the lower triangle is read). Fast path:
/// Laguerre's then Halley's method on the characteristic polynomial of the traceless part from an
/// upper bound, lambda_2 from the largest root of its resolvent cubic (iterated alongside),
/// eigenvector from the best-conditioned column of adj(D - lambda_1 I).
/// Falls back to Eigen::SelfAdjointEigenSolver when the relative gap is below
/// options.fallback_relative_gap. Allocates nothing.
TopEigenpair top_eigenpair(const Eigen::Matrix4d& D, const TopEigenOptions& options = {});

namespace internal {
/// Largest two real roots of the depressed quartic x^4 + c2 x^2 + c1 x + c0 whose roots are all
/// real (a characteristic polynomial of a symmetric traceless matrix). The largest, r1, by one
/// Laguerre step then Halley steps, which decrease monotonically from above; the second as
/// sqrt(u1) - r1, where u1 = (r1 + r2)^2 is the largest root of the resolvent cubic
/// u^3 + 2 c2 u^2 + (c2^2 - 4 c0) u - c1^2, found the same way in the same loop. x0 is a hint (an
/// upper bound of the largest root, or +inf): it is used when it is below the Laguerre-Samuelson
/// bound sqrt(-3 c2 / 2) and the quartic and all its derivatives are >= 0 there (Budan-Fourier: no
/// root exceeds it), otherwise the iteration starts from that bound. Returns {root1, root2} with
/// root1 >= root2.
Eigen::Vector2d largest_two_quartic_roots(double c2, double c1, double c0, double x0);

/// top_eigenpair() of a traceless symmetric 4x4 matrix M (full, both triangles) whose
/// characteristic polynomial x^4 + c2 x^2 + c1 x + c0 the caller already knows, e.g. Davenport's
/// K of a cross-covariance H (docs/math.md §5). lambda_upper is any upper bound of lambda_max(M)
/// (or +inf); a tight one saves iterations. The eigenvector's sign is not normalised.
TopEigenpair top_eigenpair_traceless(const Eigen::Matrix4d& M, double c2, double c1, double c0,
                                     double lambda_upper, const TopEigenOptions& options);
}  // namespace internal

}  // namespace vantage
