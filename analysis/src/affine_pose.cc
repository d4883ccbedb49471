// Prop. 8 (pose from image points through free vectors) and the paper's two baselines of
// Sec. IV: the standard approach and the full 3-D one.

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "affine_sign_enumeration.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"

namespace vantage {

using internal::check_count;
using internal::residual_direct;
using internal::weight_at;

bool AffinePoseOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!orientation.is_valid(&inner)) {
    if (why) *why = "orientation." + inner;
    return false;
  }
  if (!camera.is_valid(&inner)) {
    if (why) *why = "camera." + inner;
    return false;
  }
  return true;
}

namespace {

template <int Rows>
void validate_points(const Eigen::Matrix3Xd& model,
                     const Eigen::Matrix<double, Rows, Eigen::Dynamic>& image,
                     const Eigen::VectorXd& w, const AffinePoseOptions& options,
                     const char* image_name) {
  internal::check_options("options", options);
  internal::check_correspondences("model_object", model, image_name, image, w, 3);
  internal::check_distinct_columns("model_object", model);
}

/// The pairs of options.free_vectors for this image; kAllPairs beyond orientation.max_vectors
/// is refused.
Eigen::Matrix2Xi checked_pairs(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                               const AffinePoseOptions& options) {
  const Eigen::Matrix2Xi pairs = free_vector_pairs<2>(model, image, options.free_vectors);
  if (options.free_vectors != FreeVectorSet::kAuto) {
    check_count(pairs.cols(), options.orientation,
                "; use FreeVectorSet::kAuto (never more than 12 free vectors)");
  }
  return pairs;
}

/// Weighted means of the model points and of their measurements.
template <int Rows>
void weighted_means(const Eigen::Matrix3Xd& model,
                    const Eigen::Matrix<double, Rows, Eigen::Dynamic>& measured,
                    const Eigen::VectorXd& weights, Eigen::Vector3d* model_mean,
                    Eigen::Matrix<double, Rows, 1>* measured_mean) {
  double weight_sum = 0.0;
  model_mean->setZero();
  measured_mean->setZero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double wi = weight_at(weights, i);
    weight_sum += wi;
    *model_mean += wi * model.col(i);
    *measured_mean += wi * measured.col(i);
  }
  *model_mean /= weight_sum;
  *measured_mean /= weight_sum;
}

OrientationOptions theorem1_options(const AffinePoseOptions& options) {
  OrientationOptions theorem1;
  theorem1.eigen = options.orientation.eigen;
  theorem1.degenerate_gap = options.orientation.degenerate_gap;
  return theorem1;
}

/// Eq. (36): p_x, p_y of rotation R and scale alpha from the weighted centroids; p_z from
/// Eq. (37) or NaN.
Eigen::Vector3d affine_translation(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                                   const Eigen::VectorXd& weights, const Eigen::Matrix3d& R,
                                   double alpha, const Camera& camera) {
  Eigen::Vector3d z_mean;
  Eigen::Vector2d q_mean;
  weighted_means<2>(model, centred, weights, &z_mean, &q_mean);
  Eigen::Vector3d p;
  p.head<2>() = alpha * q_mean - R.topRows<2>() * z_mean;
  p.z() = camera.has_focal_length() ? alpha * camera.focal_length
                                    : std::numeric_limits<double>::quiet_NaN();
  return p;
}

/// J of Eq. (35) and the matching RMS image residual in pixels.
double affine_objective(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                        const Eigen::VectorXd& weights, const Eigen::Matrix3d& R,
                        const Eigen::Vector3d& p, double alpha, double* rms_px) {
  double j = 0.0;
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double wi = weight_at(weights, i);
    j += wi * (R.topRows<2>() * model.col(i) + p.head<2>() - alpha * centred.col(i)).squaredNorm();
    weight_sum += wi;
  }
  *rms_px = std::sqrt(j / weight_sum) / alpha;
  return j;
}

/// The pose fields of Prop. 8 and the standard approach from result->orientation.
void finish_affine_pose(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                        const Eigen::VectorXd& weights, const AffinePoseOptions& options,
                        AffinePoseResult* result) {
  const AffineOrientationResult& o = result->orientation;
  const Eigen::Matrix2Xd centred = image.colwise() - options.camera.principal_point;
  result->R_camera_object = o.R_camera_object;
  result->alpha = o.alpha;
  result->depth_known = options.camera.has_focal_length();
  result->p_camera_object =
      affine_translation(model, centred, weights, o.R_camera_object, o.alpha, options.camera);
  result->objective =
      affine_objective(model, centred, weights, o.R_camera_object, result->p_camera_object, o.alpha,
                       &result->reprojection_rms_px);
  if (std::isfinite(o.runner_up_residual) && o.sign_patterns > 1) {
    PoseAlternative alternative;
    alternative.R_camera_object = o.runner_up_R_camera_object;
    alternative.p_camera_object = affine_translation(
        model, centred, weights, o.runner_up_R_camera_object, o.alpha, options.camera);
    affine_objective(model, centred, weights, alternative.R_camera_object,
                     alternative.p_camera_object, o.alpha, &alternative.reprojection_rms_px);
    result->alternative = alternative;
  }
  result->status = o.status;
  result->ambiguous = o.ambiguous;
  result->message = o.message;
}

}  // namespace

FreeVectorSet single_pattern_free_vectors(FreeVectorSet requested) {
  return requested == FreeVectorSet::kAuto ? FreeVectorSet::kAllPairs : requested;
}

FreeVectors affine_free_vectors(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                                const Eigen::VectorXd& weights, const AffinePoseOptions& options) {
  validate_points<2>(model_object, image, weights, options, "image");
  return build_free_vectors<2>(model_object, image, weights,
                               free_vector_pairs<2>(model_object, image, options.free_vectors),
                               options.pair_weighting);
}

AffinePoseResult affine_pose(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                             const Eigen::VectorXd& weights, const AffinePoseOptions& options) {
  validate_points<2>(model_object, image, weights, options, "image");
  const FreeVectors free =
      build_free_vectors<2>(model_object, image, weights,
                            checked_pairs(model_object, image, options), options.pair_weighting);
  AffinePoseResult result;
  result.pairs = free.pairs;
  result.orientation =
      affine_orientation_unknown_scale(free.z_object, free.d, free.weights, options.orientation);
  finish_affine_pose(model_object, image, weights, options, &result);
  return result;
}

AffinePoseResult standard_affine_pose(const Eigen::Matrix3Xd& model_object,
                                      const Eigen::Matrix2Xd& image, const Eigen::VectorXd& weights,
                                      const AffinePoseOptions& options) {
  validate_points<2>(model_object, image, weights, options, "image");
  const FreeVectors free = build_free_vectors<2>(
      model_object, image, weights,
      free_vector_pairs(model_object, single_pattern_free_vectors(options.free_vectors)),
      options.pair_weighting);
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, free.z_object.cols());
  v.topRows<2>() = free.d;
  if (!(v.squaredNorm() > 0.0)) {
    throw InvalidArgument("image: all image points coincide, the scale is undefined");
  }
  const OrientationResult solve =
      absolute_orientation(free.z_object, v, free.weights, theorem1_options(options));

  AffinePoseResult result;
  result.pairs = free.pairs;
  AffineOrientationResult& o = result.orientation;
  o.R_camera_object = solve.R_camera_object;
  o.alpha = solve.alpha;  // Eq. (4)
  o.residual =
      residual_direct(free.z_object, solve.alpha * free.d, free.weights, solve.R_camera_object);
  o.runner_up_residual = std::numeric_limits<double>::infinity();
  o.ambiguity_margin = std::numeric_limits<double>::infinity();
  o.v_z = Eigen::VectorXd::Zero(free.z_object.cols());
  o.sign_patterns = 1;
  o.eigen_gap = solve.eigen_gap;
  if (solve.status == OrientationStatus::kDegenerate) {
    o.status = PoseStatus::kDegenerate;
    o.message = solve.message;
  }
  finish_affine_pose(model_object, image, weights, options, &result);
  return result;
}

PoseResult full_3d_pose(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix3Xd& measured,
                        const Eigen::VectorXd& weights, const AffinePoseOptions& options) {
  validate_points<3>(model_object, measured, weights, options, "measured");
  const FreeVectorsOf<3> free = build_free_vectors<3>(
      model_object, measured, weights,
      free_vector_pairs(model_object, single_pattern_free_vectors(options.free_vectors)),
      options.pair_weighting);
  const Eigen::Matrix3Xd& z = free.z_object;
  const Eigen::Matrix3Xd& m = free.d;
  const Eigen::VectorXd& w = free.weights;
  if (!(m.squaredNorm() > 0.0)) {
    throw InvalidArgument("measured: all measured points coincide, the scale is undefined");
  }
  const OrientationResult solve = absolute_orientation(z, m, w, theorem1_options(options));

  PoseResult result;
  result.R_camera_object = solve.R_camera_object;
  result.alpha = solve.alpha;
  result.eigen_gap = solve.eigen_gap;
  result.used_fallback = solve.used_fallback;
  result.status = solve.status;
  result.message = solve.message;
  Eigen::Vector3d z_mean, q_mean;
  weighted_means<3>(model_object, measured, weights, &z_mean, &q_mean);
  result.p_camera_object = solve.alpha * q_mean - solve.R_camera_object * z_mean;
  double j = 0.0;
  for (Eigen::Index i = 0; i < model_object.cols(); ++i) {
    j += weight_at(weights, i) * (solve.R_camera_object * model_object.col(i) +
                                  result.p_camera_object - solve.alpha * measured.col(i))
                                     .squaredNorm();
  }
  result.residual = j;  // Eq. (12)
  return result;
}

}  // namespace vantage
