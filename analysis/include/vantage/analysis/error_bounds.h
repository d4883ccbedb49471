#pragma once

/// Angular errors caused by a wrong scale estimate (McInroy et al., Sec. III.B-D).
///
/// With the true scale alpha and an estimate alpha_e = beta * alpha, the missing depth component
/// of a measured vector is reconstructed from Eqs. (21)-(22),
///   v   = [d; +-sqrt(||z||^2 / alpha^2   - ||d||^2)],
///   v_e = [d; +-sqrt(||z||^2 / alpha_e^2 - ||d||^2)],
/// and the angle between them depends only on beta and p = alpha ||d|| / ||z|| (Eq. 19), the
/// fraction of the vector's norm that survives the projection. Angles are in radians unless the
/// name says _deg.

#include <Eigen/Core>

namespace vantage {

/// Prop. 5, Eq. (18): theta = acos[beta p^2 + sqrt((1 - p^2)(1 - beta^2 p^2))].
/// Preconditions: p in [0, 1], beta > 0, beta p <= 1 (otherwise v_e of Eq. 22 does not exist).
/// Throws InvalidArgument naming the argument otherwise.
double scale_error_angle(double beta, double p);

/// Eq. (26): the error of the least-upper-bound scale (Eq. 23), i.e. Eq. (18) with
/// beta = 1 / p_bar (Eq. 25): acos[p^2 / p_bar + sqrt((1 - p^2)(1 - p^2 / p_bar^2))].
/// Preconditions: 0 <= p <= p_bar <= 1. p = 0 gives 0 (also for p_bar = 0).
double lub_scale_error_angle(double p, double pbar);

/// p_i = sqrt(1 - (a.n_i)^2) (Eq. 19 at viewpoint a for noise-free data): the fraction of each
/// data vector's norm in the image plane. vectors: 3 x m non-zero columns; a: unit vector.
Eigen::VectorXd projected_fractions(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a);

/// p_bar(a) = max_i p_i = sqrt(1 - min_i (a.n_i)^2) at each viewpoint a (a column of
/// viewpoints, unit length), n_i = z_i / ||z_i||. arccos p_bar(a) is the largest per-vector
/// worst-case error (Eq. 26) when the camera looks along a (docs/math.md §11); its minimum over
/// the sphere is p_bar_min of Theorem 6. vectors: 3 x m, m >= 1, non-zero finite columns.
/// Throws InvalidArgument on bad vectors or a viewpoint column that is not a finite unit vector.
Eigen::VectorXd pbar_at_viewpoints(const Eigen::Matrix3Xd& vectors,
                                   const Eigen::Matrix3Xd& viewpoints);

/// Eq. (30), in degrees: the worst-case angular error of each data vector at the worst viewpoint
/// a with p_bar_min = max_i p_i (Theorem 6): Eq. (26) with p_i = projected_fractions(vectors, a)
/// and p_bar = max_i p_i. Throws InvalidArgument on zero or non-finite columns or a non-unit a.
Eigen::VectorXd worst_case_errors_deg(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a);

}  // namespace vantage
