// Prop. 4 and Lemma 7 (orientation from free vectors), the LUB scale and its fractions.

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "affine_sign_enumeration.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"

namespace vantage {

using internal::AffineProblem;
using internal::check_count;
using internal::validate_vectors;

const char* to_string(SignEnumeration enumeration) {
  switch (enumeration) {
    case SignEnumeration::kGrayCode:
      return "gray_code";
    case SignEnumeration::kGrayCodeEigen:
      return "gray_code_eigen";
    case SignEnumeration::kNaive:
      return "naive";
  }
  return "unknown";
}

bool AffineOrientationOptions::is_valid(std::string* why) const {
  if (!(max_vectors >= 1 && max_vectors <= kMaxAffineVectorsCeiling))
    return internal::invalid_option(why, "max_vectors", "must be in [1, 30]");
  if (!(in_plane_tolerance >= 0.0 && in_plane_tolerance < 1.0))
    return internal::invalid_option(why, "in_plane_tolerance", "must be in [0, 1)");
  if (!(ambiguity_tolerance >= 0.0))
    return internal::invalid_option(why, "ambiguity_tolerance", "must be >= 0");
  if (!(distinct_rotation_angle >= 0.0))
    return internal::invalid_option(why, "distinct_rotation_angle", "must be >= 0");
  if (!(degenerate_gap >= 0.0 && degenerate_gap < 1.0))
    return internal::invalid_option(why, "degenerate_gap", "must be in [0, 1)");
  if (!(eigen.fallback_relative_gap >= 0.0 && eigen.fallback_relative_gap < 1.0))
    return internal::invalid_option(why, "eigen.fallback_relative_gap", "must be in [0, 1)");
  return true;
}

namespace {

using internal::enumerate_gray_code;
using internal::enumerate_naive;
using internal::Podium;
using internal::prepare;
using internal::residual_direct;

/// Theorem 1 on one sign pattern, from scratch.
OrientationResult solve_pattern(const Eigen::Matrix3Xd& z, const AffineProblem& problem,
                                std::uint64_t signs, const AffineOrientationOptions& options,
                                Eigen::VectorXd* signed_v_z) {
  Eigen::VectorXd v_z = problem.v_z;
  for (std::size_t b = 0; b < problem.free.size(); ++b) {
    if ((signs >> b) & 1u) v_z(problem.free[b]) = -v_z(problem.free[b]);
  }
  Eigen::Matrix3Xd v(3, z.cols());
  v.topRows<2>() = problem.d;
  v.row(2) = v_z.transpose();
  OrientationOptions theorem1;
  theorem1.eigen = options.eigen;
  theorem1.degenerate_gap = options.degenerate_gap;
  if (signed_v_z) *signed_v_z = v_z;
  return absolute_orientation(z, v, problem.w, theorem1);
}

AffineOrientationResult solve_affine(const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& d,
                                     double alpha, const Eigen::VectorXd& weights,
                                     const AffineOrientationOptions& options) {
  const AffineProblem problem = prepare(z, d, alpha, weights, options);
  Podium podium;
  AffineOrientationResult result;
  result.alpha = alpha;
  switch (options.enumeration) {
    case SignEnumeration::kGrayCode:
      enumerate_gray_code(z, problem, options, true, &podium, &result.eigen_fallbacks);
      break;
    case SignEnumeration::kGrayCodeEigen:
      enumerate_gray_code(z, problem, options, false, &podium, &result.eigen_fallbacks);
      break;
    case SignEnumeration::kNaive:
      enumerate_naive(z, problem, &podium);
      break;
  }
  result.sign_patterns = std::uint64_t{1} << problem.free.size();
  result.clamped = problem.clamped;
  result.in_plane = problem.in_plane;

  // Re-solve the winner (and runner-up) from scratch: exact R, free of update rounding, and the
  // eigen gap for the degeneracy test.
  Eigen::VectorXd v_z;
  const OrientationResult winner = solve_pattern(z, problem, podium.signs[0], options, &v_z);
  result.R_camera_object = winner.R_camera_object;
  result.eigen_gap = winner.eigen_gap;
  result.v_z = v_z / alpha;
  result.residual = residual_direct(z, problem.d, problem.w, result.R_camera_object);

  if (podium.count > 1) {
    // The runner-up is the best pattern whose rotation differs from the winner's by more than
    // distinct_rotation_angle (near-copies of the winner are skipped); when every kept pattern
    // is a near-copy, the second best is reported.
    for (int k = 1; k < podium.count; ++k) {
      const OrientationResult other = solve_pattern(z, problem, podium.signs[k], options, nullptr);
      const double angle = rotation_angle_between(result.R_camera_object, other.R_camera_object);
      if (k == 1 || angle > options.distinct_rotation_angle) {
        result.runner_up_R_camera_object = other.R_camera_object;
        result.runner_up_residual = residual_direct(z, problem.d, problem.w, other.R_camera_object);
        result.ambiguity_margin = std::max(0.0, result.runner_up_residual - result.residual);
        result.runner_up_angle = angle;
      }
      if (angle > options.distinct_rotation_angle) break;
    }
  } else {
    result.runner_up_residual = std::numeric_limits<double>::infinity();
    result.ambiguity_margin = std::numeric_limits<double>::infinity();
  }

  if (winner.status == OrientationStatus::kDegenerate) {
    result.status = PoseStatus::kDegenerate;
    result.message = winner.message;
  } else if (result.ambiguity_margin <= options.ambiguity_tolerance * problem.energy &&
             result.runner_up_angle > options.distinct_rotation_angle) {
    std::ostringstream out;
    out << "two poses fit equally well (runner-up " << result.runner_up_angle
        << " rad away, margin " << result.ambiguity_margin
        << "): coplanar vectors give the two-fold affine ambiguity";
    result.ambiguous = true;
    result.message = out.str();
  }
  return result;
}

}  // namespace

AffineOrientationResult affine_orientation(const Eigen::Matrix3Xd& z_object,
                                           const Eigen::Matrix2Xd& d_image, double alpha,
                                           const Eigen::VectorXd& weights,
                                           const AffineOrientationOptions& options) {
  internal::check_options("options", options);
  validate_vectors<2>(z_object, d_image, weights, 2, "d_image");
  internal::check_positive_finite("alpha", alpha);
  check_count(z_object.cols(), options, "");
  return solve_affine(z_object, d_image, alpha, weights, options);
}

LubScale lub_scale(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image) {
  validate_vectors<2>(z_object, d_image, {}, 1, "d_image");
  LubScale lub;
  for (Eigen::Index i = 0; i < z_object.cols(); ++i) {
    const double ratio = d_image.col(i).norm() / z_object.col(i).norm();
    if (ratio > lub.max_ratio) {
      lub.max_ratio = ratio;
      lub.limiting = i;
    }
  }
  if (!(lub.max_ratio > 0.0)) {
    throw InvalidArgument("d_image: every image vector is zero, the scale is unbounded (Eq. 23)");
  }
  lub.alpha = 1.0 / lub.max_ratio;
  return lub;
}

ProjectionFractions projection_fractions(const Eigen::Matrix3Xd& z_object,
                                         const Eigen::Matrix2Xd& d_image, double alpha) {
  validate_vectors<2>(z_object, d_image, {}, 1, "d_image");
  internal::check_positive_finite("alpha", alpha);
  ProjectionFractions out;
  out.p.resize(z_object.cols());
  for (Eigen::Index i = 0; i < z_object.cols(); ++i) {
    out.p(i) = alpha * d_image.col(i).norm() / z_object.col(i).norm();  // Eq. (19)
  }
  out.p_bar = out.p.maxCoeff();  // Eq. (24)
  if (!(out.p_bar > 0.0)) {
    throw InvalidArgument("d_image: every image vector is zero, p_bar = 0 (Eq. 24)");
  }
  out.beta = 1.0 / out.p_bar;  // Eq. (25)
  return out;
}

AffineOrientationResult affine_orientation_unknown_scale(const Eigen::Matrix3Xd& z_object,
                                                         const Eigen::Matrix2Xd& d_image,
                                                         const Eigen::VectorXd& weights,
                                                         const AffineOrientationOptions& options) {
  internal::check_options("options", options);
  validate_vectors<2>(z_object, d_image, weights, 2, "d_image");
  check_count(z_object.cols(), options, "");
  return solve_affine(z_object, d_image, lub_scale(z_object, d_image).alpha, weights, options);
}

double affine_residual(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image,
                       double alpha, const Eigen::Matrix3d& R_camera_object,
                       const Eigen::VectorXd& weights) {
  validate_vectors<2>(z_object, d_image, weights, 1, "d_image");
  internal::check_positive_finite("alpha", alpha);
  return residual_direct(z_object, alpha * d_image, weights, R_camera_object);
}

}  // namespace vantage
