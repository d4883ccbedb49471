#include "vantage/analysis/error_bounds.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/scaling.h"

namespace vantage {
namespace {

using internal::fail;

// Rounding slack on the preconditions beta p <= 1 and p <= p_bar (values computed from data).
constexpr double kSlack = 1e-12;

// The unit directions of finite, non-zero columns, each normalised on its own scale (any length
// from the smallest subnormal to the largest double); "vectors[i]: ..." otherwise.
Eigen::Matrix3Xd checked_directions(const Eigen::Matrix3Xd& vectors) {
  internal::check_finite_columns("vectors", vectors);
  Eigen::Matrix3Xd normals = unit_directions(vectors);
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    if (normals.col(i).isZero(0.0)) internal::fail_at("vectors", i, "zero length");
  }
  return normals;
}

// sqrt(1 - x^2) without forming x^2: (1 - x) is exact for x in [0.5, 1].
double cofactor(double x) { return std::sqrt((1.0 - x) * (1.0 + x)); }

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
  // The angle between the unit vectors (p, c1) and (beta p, c2) of Eq. (18), as atan2 of their
  // cross and dot products, each a sum of non-negative terms (docs/math.md, "Eq. (26) without
  // cancellation"): beta^2 c1^2 - c2^2 = beta^2 - 1 gives the cross product
  // p |beta^2 - 1| / (beta c1 + c2). The acos form loses half the digits when cos -> 1.
  if (beta == 1.0) return 0.0;  // the true scale (and 0/0 below at p = 1)
  const double c1 = cofactor(p);
  const double c2 = std::sqrt(std::max(0.0, std::fma(-beta, p, 1.0) * (1.0 + std::min(1.0, bp))));
  const double cross = p * std::abs((beta - 1.0) * (beta + 1.0)) / (beta * c1 + c2);
  return std::atan2(cross, bp * p + c1 * c2);
}

double lub_scale_error_angle(double p, double pbar) {
  if (!(pbar >= 0.0 && pbar <= 1.0)) fail("pbar", "must be in [0, 1]" + got(pbar));
  if (!(p >= 0.0 && p <= pbar + kSlack)) fail("p", "must be in [0, pbar]" + got(p));
  if (p == 0.0) return 0.0;
  if (pbar == 1.0) return 0.0;  // beta = 1: the true scale (and 0/0 below at p = 1)
  p = std::min(p, pbar);
  // Eq. (18) at beta = 1 / p_bar, multiplied through by p_bar so that 1 / p_bar is never rounded:
  // with c1 = sqrt(1 - p^2) and s2 = sqrt(p_bar^2 - p^2) (= p_bar c2, from p_bar - p, exact when
  // p is near p_bar), cos = (p^2 + c1 s2) / p_bar and sin = p (1 - p_bar^2) / (p_bar (c1 + s2)).
  // At p = p_bar this is atan2(c1, p) = arccos p, 90 degrees as p_bar -> 0.
  const double c1 = cofactor(p);
  const double s2 = std::sqrt((pbar - p) * (pbar + p));
  const double cross = p * ((1.0 - pbar) * (1.0 + pbar)) / (c1 + s2);
  return std::atan2(cross, p * p + c1 * s2);
}

Eigen::VectorXd projected_fractions(const Eigen::Matrix3Xd& vectors, const Eigen::Vector3d& a) {
  internal::check_unit_vector("a", a);
  const Eigen::Matrix3Xd normals = checked_directions(vectors);
  Eigen::VectorXd p(vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    // |a x n_i| = sin of the angle to the line of sight: its digits survive where
    // sqrt(1 - (a.n_i)^2) has none left (a.n_i rounds to 1 within 1e-8 rad of a).
    p(i) = std::min(1.0, a.cross(normals.col(i)).norm());
  }
  return p;
}

Eigen::VectorXd pbar_at_viewpoints(const Eigen::Matrix3Xd& vectors,
                                   const Eigen::Matrix3Xd& viewpoints) {
  internal::check_min_count("vectors", vectors.cols(), 1, "column");
  const Eigen::Matrix3Xd normals = checked_directions(vectors);
  internal::check_unit_columns("viewpoints", viewpoints);
  Eigen::VectorXd pbar(viewpoints.cols());
  for (Eigen::Index k = 0; k < viewpoints.cols(); ++k) {
    const Eigen::Vector3d a = viewpoints.col(k);
    double largest = 0.0;
    for (Eigen::Index i = 0; i < normals.cols(); ++i) {
      largest = std::max(largest, a.cross(normals.col(i)).norm());
    }
    pbar(k) = std::min(1.0, largest);
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
