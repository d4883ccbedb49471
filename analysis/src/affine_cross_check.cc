// A direct NLopt minimisation of J_2d over SO(3): the independent cross-check of Prop. 4. Built
// without NLopt (VANTAGE_WITH_NLOPT=0) it checks its input and reports that it did not run.

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "affine_sign_enumeration.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/build_options.h"
#include "vantage/analysis/common.h"

#if VANTAGE_WITH_NLOPT
#include <nlopt.hpp>
#endif

namespace vantage {

using internal::residual_direct;

bool AffineCrossCheckOptions::is_valid(std::string* why) const {
  if (!(starts >= 1)) return internal::invalid_option(why, "starts", "must be >= 1");
  if (!(x_tolerance > 0.0)) return internal::invalid_option(why, "x_tolerance", "must be > 0");
  if (!(max_evaluations >= 1))
    return internal::invalid_option(why, "max_evaluations", "must be >= 1");
  return true;
}

#if VANTAGE_WITH_NLOPT
namespace {

struct CrossCheckData {
  const Eigen::Matrix3Xd* z;
  const Eigen::Matrix2Xd* d_object;
  const Eigen::VectorXd* w;
  Eigen::Matrix3d start;
  int evaluations = 0;
};

Eigen::Matrix3d rotation_at(const Eigen::Matrix3d& start, const double* x) {
  const Eigen::Vector3d omega(x[0], x[1], x[2]);
  const double angle = omega.norm();
  if (angle == 0.0) return start;
  return start * Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

double cross_check_objective(unsigned, const double* x, double*, void* data) {
  auto* c = static_cast<CrossCheckData*>(data);
  ++c->evaluations;
  return residual_direct(*c->z, *c->d_object, *c->w, rotation_at(c->start, x));
}

}  // namespace
#endif

AffineCrossCheckResult minimize_affine_residual(const Eigen::Matrix3Xd& z_object,
                                                const Eigen::Matrix2Xd& d_image, double alpha,
                                                const Eigen::VectorXd& weights,
                                                const AffineCrossCheckOptions& options) {
  internal::check_options("options", options);
  internal::validate_vectors<2>(z_object, d_image, weights, 2, "d_image");
  internal::check_positive_finite("alpha", alpha);
  AffineCrossCheckResult result;
#if !VANTAGE_WITH_NLOPT
  result.residual = std::numeric_limits<double>::quiet_NaN();
  result.skipped = kWithoutNlopt;
  return result;
#else
  const Eigen::Matrix2Xd d_object = alpha * d_image;
  const Eigen::VectorXd w = weights.size() == 0 ? Eigen::VectorXd::Ones(z_object.cols()) : weights;
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal;
  result.residual = std::numeric_limits<double>::infinity();
  for (int s = 0; s < options.starts; ++s) {
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    CrossCheckData data{&z_object, &d_object, &w, q.normalized().toRotationMatrix()};
    nlopt::opt opt(nlopt::LN_BOBYQA, 3);
    opt.set_lower_bounds(std::vector<double>(3, -kPi));
    opt.set_upper_bounds(std::vector<double>(3, kPi));
    opt.set_min_objective(cross_check_objective, &data);
    opt.set_xtol_abs(options.x_tolerance);
    opt.set_maxeval(options.max_evaluations);
    opt.set_initial_step(0.5);
    std::vector<double> x(3, 0.0);
    double f = std::numeric_limits<double>::infinity();
    try {
      opt.optimize(x, f);
    } catch (const nlopt::roundoff_limited&) {
      // x and f hold the best point found: converged to rounding, an acceptable outcome.
    } catch (const std::exception&) {
      ++result.failed_starts;
    }
    result.evaluations += data.evaluations;
    const Eigen::Matrix3d R = rotation_at(data.start, x.data());
    const double j = residual_direct(z_object, d_object, w, R);
    if (j < result.residual) {
      result.residual = j;
      result.R_camera_object = R;
    }
  }
  return result;
#endif
}

}  // namespace vantage
