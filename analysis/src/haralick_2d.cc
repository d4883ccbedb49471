#include "vantage/analysis/haralick_2d.h"

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage {

const char* to_string(Pose2dStatus status) {
  switch (status) {
    case Pose2dStatus::kOk:
      return "ok";
    case Pose2dStatus::kDegenerate:
      return "degenerate";
  }
  return "unknown";
}

bool Pose2dOptions::is_valid(std::string* why) const {
  if (!(degenerate_tolerance >= 0.0 && degenerate_tolerance < 1.0)) {
    return internal::invalid_option(why, "degenerate_tolerance", "must be in [0, 1)");
  }
  return true;
}

namespace {

void validate(const Eigen::Matrix2Xd& from, const Eigen::Matrix2Xd& to, const Eigen::VectorXd& w,
              const Pose2dOptions& options) {
  internal::check_options("options", options);
  internal::check_count_matches("to", to.cols(), from.cols(), "from");
  internal::check_min_count("from", from.cols(), 1, "correspondence");
  internal::check_weights("weights", w, from.cols(), "from", internal::WeightRule::kNonNegative);
  internal::check_finite_columns("from", from);
  internal::check_finite_columns("to", to);
}

double weight(const Eigen::VectorXd& w, Eigen::Index i) { return w.size() == 0 ? 1.0 : w(i); }

/// eps^2 = sum w ||to - (R from + t)||^2 for R = [[c, -s], [s, c]] and the optimal t(R).
double residual_at(const Eigen::Matrix2Xd& from, const Eigen::Matrix2Xd& to,
                   const Eigen::VectorXd& w, const Eigen::Vector2d& from_bar,
                   const Eigen::Vector2d& to_bar, double c, double s) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < from.cols(); ++i) {
    const Eigen::Vector2d x = from.col(i) - from_bar;
    const Eigen::Vector2d y = to.col(i) - to_bar;
    const Eigen::Vector2d e(y.x() - (c * x.x() - s * x.y()), y.y() - (s * x.x() + c * x.y()));
    sum += weight(w, i) * e.squaredNorm();
  }
  return sum;
}

}  // namespace

Pose2dResult pose_2d(const Eigen::Matrix2Xd& from, const Eigen::Matrix2Xd& to,
                     const Eigen::VectorXd& weights, const Pose2dOptions& options) {
  validate(from, to, weights, options);
  double weight_sum = 0.0;
  Eigen::Vector2d from_sum = Eigen::Vector2d::Zero();
  Eigen::Vector2d to_sum = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < from.cols(); ++i) {
    const double wi = weight(weights, i);
    weight_sum += wi;
    from_sum += wi * from.col(i);
    to_sum += wi * to.col(i);
  }
  const Eigen::Vector2d from_bar = from_sum / weight_sum;  // x_bar
  const Eigen::Vector2d to_bar = to_sum / weight_sum;      // y_bar

  // A and B of Sec. 2.2 and the spreads, all from centred data (no cancellation of big sums).
  double a = 0.0, b = 0.0, spread_from = 0.0, spread_to = 0.0;
  for (Eigen::Index i = 0; i < from.cols(); ++i) {
    const double wi = weight(weights, i);
    const Eigen::Vector2d x = from.col(i) - from_bar;
    const Eigen::Vector2d y = to.col(i) - to_bar;
    a += wi * (y.x() * x.x() + y.y() * x.y());
    b += wi * (y.x() * x.y() - y.y() * x.x());
    spread_from += wi * x.squaredNorm();
    spread_to += wi * y.squaredNorm();
  }

  // The two stationary angles of A sin + B cos = 0: (cos, sin) = +-(A, -B) / sqrt(A^2 + B^2).
  const double norm = std::hypot(a, b);
  const double c = norm > 0.0 ? a / norm : 1.0;
  const double s = norm > 0.0 ? -b / norm : 0.0;
  const double residual_plus = residual_at(from, to, weights, from_bar, to_bar, c, s);
  const double residual_minus = residual_at(from, to, weights, from_bar, to_bar, -c, -s);
  const bool plus = residual_plus <= residual_minus;

  Pose2dResult result;
  const double cos_theta = plus ? c : -c;
  const double sin_theta = plus ? s : -s;
  result.R_to_from << cos_theta, -sin_theta, sin_theta, cos_theta;
  result.t_to_from = to_bar - result.R_to_from * from_bar;  // y_bar = R x_bar + t
  result.theta = std::atan2(sin_theta, cos_theta);
  if (result.theta <= -kPi) result.theta += 2.0 * kPi;  // atan2(-0, -1) = -pi
  result.residual = plus ? residual_plus : residual_minus;
  result.rejected_residual = plus ? residual_minus : residual_plus;
  result.correlation_a = a;
  result.correlation_b = b;
  if (!(norm > options.degenerate_tolerance * std::sqrt(spread_from * spread_to))) {
    result.status = Pose2dStatus::kDegenerate;
    result.message =
        "the data do not determine the rotation (A and B of Haralick Sec. 2.2 vanish): fewer "
        "than two distinct points, or no correlation between the sets";
  }
  return result;
}

}  // namespace vantage
