#include "pose_refinement.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "vantage/analysis/internal/checks.h"

namespace vantage::internal {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

/// exp([omega]x) R: the left perturbation used by both models (dX/domega = -[R z]x).
inline Eigen::Matrix3d rotate_left(const Eigen::Vector3d& omega, const Eigen::Matrix3d& R) {
  const double angle = omega.norm();
  if (angle == 0.0) return R;
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix() * R;
}

/// Normal equations J^T W J, J^T W r and sse of one model at one state.
struct Normal {
  Matrix6d jtj;
  Vector6d jtr;
  double sse;
};

/// The singular-direction test: the smallest eigenvalue of the diagonally scaled J^T J is at
/// most kSingular, i.e. (scaled - kSingular I) is not positive definite, which Cholesky decides
/// (backward stable: rounding moves the threshold by ~1e-15, far below kSingular).
bool singular(const Matrix6d& jtj) {
  const Vector6d d = jtj.diagonal();
  if (!(d.minCoeff() > 0.0)) return true;
  const Vector6d s = d.cwiseSqrt().cwiseInverse();
  constexpr double kSingular = 1e-12;  // relative to the unit diagonal of the scaled matrix
  Matrix6d shifted = s.asDiagonal() * jtj * s.asDiagonal();
  shifted.diagonal().array() -= kSingular;
  return Eigen::LLT<Matrix6d>(shifted).info() != Eigen::Success;
}

/// Generic Levenberg-Marquardt with Marquardt's diagonal scaling. Model provides
/// normal(state) -> Normal and step(state, delta) -> state and sse(state) (+inf: infeasible).
template <typename State, typename Model>
State levenberg_marquardt(const Model& model, State state, const LmSettings& settings,
                          int* iterations, bool* converged, bool* degenerate) {
  Normal n = model.normal(state);
  double lambda = 1e-6;
  *converged = false;
  *iterations = 0;
  while (*iterations < settings.max_iterations) {
    ++*iterations;
    if (n.sse == 0.0) {
      *converged = true;
      break;
    }
    Matrix6d a = n.jtj;
    a.diagonal() += lambda * n.jtj.diagonal().cwiseMax(1e-300);
    const Vector6d delta = -a.llt().solve(n.jtr);
    const State next = model.step(state, delta);
    const double sse = model.sse(next);
    if (sse <= n.sse) {
      const double decrease = n.sse - sse;
      const bool small_step = delta.head<3>().norm() <= settings.step_tolerance &&
                              model.relative_step(state, delta) <= settings.step_tolerance;
      state = next;
      n = model.normal(state);
      lambda = std::max(lambda * 0.1, 1e-12);
      if (small_step || decrease <= settings.relative_tolerance * sse) {
        *converged = true;
        break;
      }
    } else {
      lambda *= 10.0;
      if (lambda > 1e12) {  // no descent along any damped direction: a (numerical) minimum
        *converged = true;
        break;
      }
    }
  }
  *degenerate = singular(n.jtj);
  return state;
}

struct OrthoState {
  Eigen::Matrix3d R;
  double s;
  Eigen::Vector2d t;
};

struct OrthoModel {
  const Eigen::Matrix3Xd& z;
  const Eigen::Matrix2Xd& q;
  const Eigen::VectorXd& w;

  double sse(const OrthoState& x) const {
    double e = 0.0;
    for (Eigen::Index i = 0; i < z.cols(); ++i) {
      e += weight_at(w, i) * (x.s * (x.R.topRows<2>() * z.col(i)) + x.t - q.col(i)).squaredNorm();
    }
    return e;
  }
  Normal normal(const OrthoState& x) const {
    Normal n{Matrix6d::Zero(), Vector6d::Zero(), 0.0};
    Eigen::Matrix<double, 2, 6> J;
    J.rightCols<2>().setIdentity();
    for (Eigen::Index i = 0; i < z.cols(); ++i) {
      const double wi = weight_at(w, i);
      const Eigen::Vector3d rz = x.R * z.col(i);
      const Eigen::Vector2d r = x.s * rz.head<2>() + x.t - q.col(i);
      J.leftCols<3>() = -x.s * skew(rz).topRows<2>();
      J.col(3) = rz.head<2>();
      n.jtj.noalias() += wi * J.transpose() * J;
      n.jtr.noalias() += wi * J.transpose() * r;
      n.sse += wi * r.squaredNorm();
    }
    return n;
  }
  OrthoState step(const OrthoState& x, const Vector6d& d) const {
    return {rotate_left(d.head<3>(), x.R), x.s + d(3), x.t + d.tail<2>()};
  }
  double relative_step(const OrthoState& x, const Vector6d& d) const {
    return std::abs(d(3)) / std::abs(x.s) +
           d.tail<2>().norm() / (x.t.norm() + std::abs(x.s) * z.norm() + 1e-300);
  }
};

struct PinholeState {
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
};

struct PinholeModel {
  const Eigen::Matrix3Xd& z;
  const Eigen::Matrix2Xd& q;
  const Eigen::VectorXd& w;
  double f;

  double sse(const PinholeState& x) const { return pinhole_sse(z, q, w, f, x.R, x.p); }
  Normal normal(const PinholeState& x) const {
    Normal n{Matrix6d::Zero(), Vector6d::Zero(), 0.0};
    Eigen::Matrix<double, 2, 6> J;
    for (Eigen::Index i = 0; i < z.cols(); ++i) {
      const double wi = weight_at(w, i);
      const Eigen::Vector3d rz = x.R * z.col(i);
      const Eigen::Vector3d X = rz + x.p;
      const double inv_z = 1.0 / X.z();
      const Eigen::Vector2d r = f * inv_z * X.head<2>() - q.col(i);
      Eigen::Matrix<double, 2, 3> dr_dx;
      dr_dx << f * inv_z, 0.0, -f * X.x() * inv_z * inv_z, 0.0, f * inv_z,
          -f * X.y() * inv_z * inv_z;
      J.leftCols<3>() = -dr_dx * skew(rz);
      J.rightCols<3>() = dr_dx;
      n.jtj.noalias() += wi * J.transpose() * J;
      n.jtr.noalias() += wi * J.transpose() * r;
      n.sse += wi * r.squaredNorm();
    }
    return n;
  }
  PinholeState step(const PinholeState& x, const Vector6d& d) const {
    return {rotate_left(d.head<3>(), x.R), x.p + d.tail<3>()};
  }
  double relative_step(const PinholeState& x, const Vector6d& d) const {
    return d.tail<3>().norm() / (x.p.norm() + 1e-300);
  }
};

}  // namespace

double pinhole_sse(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                   const Eigen::VectorXd& weights, double focal_length, const Eigen::Matrix3d& R,
                   const Eigen::Vector3d& p) {
  double e = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const Eigen::Vector3d X = R * model.col(i) + p;
    if (!(X.z() > 0.0)) return std::numeric_limits<double>::infinity();
    e +=
        weight_at(weights, i) * (focal_length / X.z() * X.head<2>() - centred.col(i)).squaredNorm();
  }
  return e;
}

LmPose refine_scaled_orthographic(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                                  const Eigen::VectorXd& weights, const LmPose& start,
                                  const LmSettings& settings) {
  const OrthoModel m{model, centred, weights};
  OrthoState x{start.R, start.inverse_alpha, start.inverse_alpha * start.p.head<2>()};
  LmPose out;
  x = levenberg_marquardt(m, x, settings, &out.iterations, &out.converged, &out.degenerate);
  out.R = x.R;
  out.inverse_alpha = x.s;
  out.p << x.t / x.s, start.p.z();
  out.sse = m.sse(x);
  return out;
}

LmPose refine_pinhole(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                      const Eigen::VectorXd& weights, double focal_length, const LmPose& start,
                      const LmSettings& settings) {
  const PinholeModel m{model, centred, weights, focal_length};
  PinholeState x{start.R, start.p};
  LmPose out;
  x = levenberg_marquardt(m, x, settings, &out.iterations, &out.converged, &out.degenerate);
  out.R = x.R;
  out.p = x.p;
  out.sse = m.sse(x);
  return out;
}

PlaneFit fit_plane(const Eigen::Matrix3Xd& model, const Eigen::VectorXd& weights) {
  PlaneFit plane;
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    plane.centroid += weight_at(weights, i) * model.col(i);
    weight_sum += weight_at(weights, i);
  }
  plane.centroid /= weight_sum;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const Eigen::Vector3d c = model.col(i) - plane.centroid;
    scatter.noalias() += weight_at(weights, i) * c * c.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  plane.normal = eigen.eigenvectors().col(0);
  const double largest = eigen.eigenvalues()(2);
  plane.planarity =
      largest > 0.0 ? std::sqrt(std::max(0.0, eigen.eigenvalues()(0)) / largest) : 0.0;
  return plane;
}

void necker_mirror(const PlaneFit& plane, const Eigen::Matrix3d& R, const Eigen::Vector3d& p,
                   Eigen::Matrix3d* R_mirror, Eigen::Vector3d* p_mirror) {
  const Eigen::Matrix3d householder =
      Eigen::Matrix3d::Identity() - 2.0 * plane.normal * plane.normal.transpose();
  *R_mirror = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal() * R * householder;
  *p_mirror = R * plane.centroid + p - *R_mirror * plane.centroid;
}

}  // namespace vantage::internal
