#include "vantage/analysis/error_bounds.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage {
namespace {

using internal::fail;

// Rounding slack on the preconditions beta p <= 1 and p <= p_bar (values computed from data).
constexpr double kSlack = 1e-12;

double clamped_acos(double c) { return std::acos(std::clamp(c, -1.0, 1.0)); }

std::string got(double value) {
  std::ostringstream out;
  out << ", got " << value;
  return out.str();
}

}  // namespace

double scale_error_angle(double beta, double p) {
  if (!(p >= 0.0 && p <= 1.0)) fail("p", "must be in [0, 1]" + got(p));
  internal::check_positive_finite("beta", beta);
  const double bp = beta * p;
  if (bp > 1.0 + kSlack) fail("beta", "beta * p must be <= 1 (Eq. 22 has no real depth)" + got(bp));
  const double b2p2 = std::min(1.0, bp * bp);
  return clamped_acos(beta * p * p + std::sqrt((1.0 - p * p) * (1.0 - b2p2)));
}

double lub_scale_error_angle(double p, double pbar) {
  if (!(pbar >= 0.0 && pbar <= 1.0)) fail("pbar", "must be in [0, 1]" + got(pbar));
  if (!(p >= 0.0 && p <= pbar + kSlack)) fail("p", "must be in [0, pbar]" + got(p));
  if (p == 0.0) return 0.0;
  return scale_error_angle(1.0 / pbar, std::min(p, pbar));
}

Eigen::VectorXd projected_fractions(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a) {
  internal::check_unit_vector("a", a);
  internal::check_nonzero_finite_columns("vectors", vectors);
  Eigen::VectorXd p(vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const double norm = vectors.col(i).norm();
    if (!std::isfinite(norm)) internal::fail_at("vectors", i, "length overflows");
    const double c = std::clamp(a.dot(vectors.col(i)) / norm, -1.0, 1.0);
    p(i) = std::sqrt((1.0 - c) * (1.0 + c));
  }
  return p;
}

Eigen::VectorXd pbar_at_viewpoints(const Eigen::Matrix3Xd& vectors,
                                   const Eigen::Matrix3Xd& viewpoints) {
  internal::check_min_count("vectors", vectors.cols(), 1, "column");
  internal::check_nonzero_finite_columns("vectors", vectors);
  internal::check_unit_columns("viewpoints", viewpoints);
  Eigen::Matrix3Xd normals(3, vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const double norm = vectors.col(i).norm();
    if (!std::isfinite(norm)) internal::fail_at("vectors", i, "length overflows");
    normals.col(i) = vectors.col(i) / norm;
  }
  Eigen::VectorXd pbar(viewpoints.cols());
  for (Eigen::Index k = 0; k < viewpoints.cols(); ++k) {
    const Eigen::Vector3d a = viewpoints.col(k);
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
    errors(i) = kDegreesPerRadian * lub_scale_error_angle(p(i), pbar);
  }
  return errors;
}

}  // namespace vantage
