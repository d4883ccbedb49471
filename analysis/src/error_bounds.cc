#include "vantage/analysis/error_bounds.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "vantage/analysis/common.h"

namespace vantage {
namespace {

// Rounding slack on the preconditions beta p <= 1 and p <= p_bar (values computed from data).
constexpr double kSlack = 1e-12;
// Tolerance on ||a|| = 1.
constexpr double kUnitTolerance = 1e-9;
constexpr double kRadToDeg = 180.0 / M_PI;

double clamped_acos(double c) { return std::acos(std::clamp(c, -1.0, 1.0)); }

}  // namespace

double scale_error_angle(double beta, double p) {
  if (!(p >= 0.0 && p <= 1.0)) {
    throw InvalidArgument("scale_error_angle: p must be in [0, 1], got " + std::to_string(p));
  }
  if (!(beta > 0.0) || !std::isfinite(beta)) {
    throw InvalidArgument("scale_error_angle: beta must be positive and finite");
  }
  const double bp = beta * p;
  if (bp > 1.0 + kSlack) {
    throw InvalidArgument("scale_error_angle: beta * p must be <= 1 (Eq. 22 has no real depth)");
  }
  const double b2p2 = std::min(1.0, bp * bp);
  return clamped_acos(beta * p * p + std::sqrt((1.0 - p * p) * (1.0 - b2p2)));
}

double lub_scale_error_angle(double p, double pbar) {
  if (!(pbar >= 0.0 && pbar <= 1.0)) {
    throw InvalidArgument("lub_scale_error_angle: pbar must be in [0, 1]");
  }
  if (!(p >= 0.0 && p <= pbar + kSlack)) {
    throw InvalidArgument("lub_scale_error_angle: p must be in [0, pbar]");
  }
  if (p == 0.0) return 0.0;
  return scale_error_angle(1.0 / pbar, std::min(p, pbar));
}

Eigen::VectorXd projected_fractions(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a) {
  if (!a.allFinite() || std::abs(a.norm() - 1.0) > kUnitTolerance) {
    throw InvalidArgument("projected_fractions: a must be a finite unit vector");
  }
  Eigen::VectorXd p(vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const double norm = vectors.col(i).norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw InvalidArgument("projected_fractions: vectors column " + std::to_string(i) +
                            " is zero or not finite");
    }
    const double c = std::clamp(a.dot(vectors.col(i)) / norm, -1.0, 1.0);
    p(i) = std::sqrt((1.0 - c) * (1.0 + c));
  }
  return p;
}

Eigen::VectorXd pbar_at_viewpoints(const Eigen::Matrix3Xd& vectors,
                                   const Eigen::Matrix3Xd& viewpoints) {
  if (vectors.cols() == 0) throw InvalidArgument("pbar_at_viewpoints: vectors is empty");
  Eigen::Matrix3Xd normals(3, vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const double norm = vectors.col(i).norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw InvalidArgument("pbar_at_viewpoints: vectors column " + std::to_string(i) +
                            " is zero or not finite");
    }
    normals.col(i) = vectors.col(i) / norm;
  }
  Eigen::VectorXd pbar(viewpoints.cols());
  for (Eigen::Index k = 0; k < viewpoints.cols(); ++k) {
    const Eigen::Vector3d a = viewpoints.col(k);
    if (!a.allFinite() || std::abs(a.norm() - 1.0) > kUnitTolerance) {
      throw InvalidArgument("pbar_at_viewpoints: viewpoints column " + std::to_string(k) +
                            " is not a finite unit vector");
    }
    double c = 1.0;
    for (Eigen::Index i = 0; i < normals.cols(); ++i) {
      c = std::min(c, std::abs(normals.col(i).dot(a)));
    }
    pbar(k) = std::sqrt((1.0 - c) * (1.0 + c));
  }
  return pbar;
}

Eigen::VectorXd worst_case_errors_deg(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a) {
  const Eigen::VectorXd p = projected_fractions(vectors, a);
  Eigen::VectorXd errors = Eigen::VectorXd::Zero(p.size());
  if (p.size() == 0) return errors;
  const double pbar = p.maxCoeff();
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    errors(i) = kRadToDeg * lub_scale_error_angle(p(i), pbar);
  }
  return errors;
}

}  // namespace vantage
