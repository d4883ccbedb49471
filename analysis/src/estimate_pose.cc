// estimate_pose(): one dispatch from a PoseMethod to its solver, and one conversion of each
// solver's result into the PoseEstimate every front end reads.

#include "vantage/analysis/estimate_pose.h"

#include <cmath>
#include <limits>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/haralick_2d.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/refined_pose.h"
#include "vantage/analysis/two_view.h"

namespace vantage {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The camera a method projects with: the pinhole methods and two-view read an image without
/// a focal length as normalised coordinates (f = 1).
Camera camera_for(PoseMethod method, const Camera& given) {
  Camera camera = given;
  if ((is_pinhole_method(method) || method == PoseMethod::kTwoView) && !camera.has_focal_length()) {
    camera.focal_length = 1.0;
  }
  return camera;
}

AffinePoseOptions affine_options(const PoseOptions& options, const Camera& camera) {
  AffinePoseOptions affine;
  affine.orientation = options.orientation;
  affine.free_vectors = options.free_vectors;
  affine.pair_weighting = options.pair_weighting;
  affine.camera = camera;
  return affine;
}

/// Prop. 4's fields (affine, standard).
void fill_sign_patterns(const AffineOrientationResult& o, PoseDiagnostics* d) {
  d->sign_patterns = o.sign_patterns;
  d->orientation_residual = o.residual;
  d->runner_up_residual = o.runner_up_residual;
  d->ambiguity_margin = o.ambiguity_margin;
  d->runner_up_angle_rad = std::isfinite(o.runner_up_residual) ? o.runner_up_angle : kNaN;
  d->clamped = o.clamped;
  d->in_plane = o.in_plane;
  d->eigen_gap = o.eigen_gap;
}

PoseEstimate from_affine(const AffinePoseResult& pose, FreeVectorSet requested) {
  PoseEstimate e = pose;
  e.diagnostics.free_vectors = requested;
  e.diagnostics.free_vector_count = pose.pairs.cols();
  fill_sign_patterns(pose.orientation, &e.diagnostics);
  return e;
}

/// Lemma 7 (affine) on direction data: no translation.
PoseEstimate affine_directions(const Correspondences& data, const PoseOptions& options) {
  const AffineOrientationResult o =
      affine_orientation_unknown_scale(data.model, data.image, data.weights, options.orientation);
  PoseEstimate e;
  e.R_camera_object = o.R_camera_object;
  e.p_camera_object.setConstant(kNaN);
  e.alpha = o.alpha;
  e.status = o.status;
  e.ambiguous = o.ambiguous;
  e.objective = o.residual;
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < data.model.cols(); ++i) {
    weight_sum += internal::weight_at(data.weights, i);
  }
  e.reprojection_rms_px = std::sqrt(o.residual / weight_sum) / o.alpha;
  if (std::isfinite(o.runner_up_residual) && o.sign_patterns > 1) {
    PoseAlternative alternative;
    alternative.R_camera_object = o.runner_up_R_camera_object;
    alternative.p_camera_object.setConstant(kNaN);
    alternative.reprojection_rms_px = std::sqrt(o.runner_up_residual / weight_sum) / o.alpha;
    e.alternative = alternative;
  }
  e.message = o.message;
  fill_sign_patterns(o, &e.diagnostics);
  return e;
}

/// The standard approach on direction data: Theorem 1 with v_z = 0, alpha from Eq. (4).
PoseEstimate standard_directions(const Correspondences& data) {
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, data.image.cols());
  v.topRows<2>() = data.image;
  if (!(v.squaredNorm() > 0.0)) throw InvalidArgument("image", "every image vector is zero");
  const OrientationResult o = absolute_orientation(data.model, v, data.weights);
  PoseEstimate e;
  e.R_camera_object = o.R_camera_object;
  e.p_camera_object.setConstant(kNaN);
  e.alpha = o.alpha;
  e.status = o.status == OrientationStatus::kOk ? PoseStatus::kOk : PoseStatus::kDegenerate;
  e.objective = o.residual;
  e.reprojection_rms_px = kNaN;
  e.message = o.message;
  e.diagnostics.sign_patterns = 1;
  e.diagnostics.eigen_gap = o.eigen_gap;
  return e;
}

/// A 3-D pose (full3d, haralick-3d): no image residual.
PoseEstimate from_pose_3d(const PoseResult& pose) {
  PoseEstimate e;
  e.R_camera_object = pose.R_camera_object;
  e.p_camera_object = pose.p_camera_object;
  e.alpha = pose.alpha;
  e.status = pose.status == OrientationStatus::kOk ? PoseStatus::kOk : PoseStatus::kDegenerate;
  e.objective = pose.residual;
  e.reprojection_rms_px = kNaN;
  e.message = pose.message;
  e.diagnostics.eigen_gap = pose.eigen_gap;
  return e;
}

PoseEstimate refined(PoseMethod method, const Correspondences& data, const PoseOptions& options,
                     const Camera& camera) {
  RefinedPoseOptions refine;
  refine.camera = camera;
  refine.start = affine_options(options, camera);
  refine.branches = options.branches;
  const RefinedPoseResult pose =
      method == PoseMethod::kPerspective
          ? perspective_pose(data.model, data.image, data.weights, refine)
          : affine_refined_pose(data.model, data.image, data.weights, refine);
  PoseEstimate e = pose;
  e.diagnostics.branches = pose.branches;
  e.diagnostics.planarity = pose.planarity;
  e.diagnostics.start_reprojection_rms_px = pose.start_reprojection_rms_px;
  return e;
}

PoseEstimate orthogonal_iteration(PoseMethod method, const Correspondences& data,
                                  const PoseOptions& options, const Camera& camera) {
  OrthogonalIterationOptions oi;
  oi.rotation_step =
      method == PoseMethod::kOiSvd ? OrientationMethod::kSvd : OrientationMethod::kFoam;
  oi.camera = camera;
  oi.branches = options.branches;
  const OrthogonalIterationResult pose =
      orthogonal_iteration_pose(data.model, data.image, data.weights, oi);
  PoseEstimate e = pose;
  e.diagnostics.branches = pose.branches;
  e.diagnostics.initial_objective = pose.initial_objective;
  e.diagnostics.points_behind_camera = pose.points_behind_camera;
  e.diagnostics.rotation_step = oi.rotation_step;
  return e;
}

PoseEstimate two_view(const Correspondences& data, const Camera& camera) {
  TwoViewOptions options;
  options.focal_length = camera.focal_length;
  const TwoViewResult pose = two_view_pose(data.image1.colwise() - camera.principal_point,
                                           data.image2.colwise() - camera.principal_point, options);
  PoseEstimate e;
  e.R_camera_object = pose.R_camera2_camera1;
  e.p_camera_object = pose.t_camera2_camera1;
  switch (pose.status) {
    case TwoViewStatus::kOk:
      e.status = PoseStatus::kOk;
      break;
    case TwoViewStatus::kDegenerate:
      e.status = PoseStatus::kDegenerate;
      break;
    case TwoViewStatus::kNoPointsInFront:
      e.status = PoseStatus::kNoPointsInFront;
      break;
  }
  e.objective = pose.residual;
  e.reprojection_rms_px = kNaN;
  e.message = pose.message;
  e.diagnostics.essential = pose.essential;
  e.diagnostics.null_space_ratio = pose.null_space_ratio;
  e.diagnostics.points_in_front = pose.points_in_front;
  return e;
}

PoseEstimate haralick_2d(const Correspondences& data) {
  const Pose2dResult pose = pose_2d(data.model.topRows<2>(), data.image, data.weights);
  PoseEstimate e;
  e.R_camera_object.topLeftCorner<2, 2>() = pose.R_to_from;
  e.p_camera_object << pose.t_to_from, 0.0;
  e.status = pose.status == Pose2dStatus::kOk ? PoseStatus::kOk : PoseStatus::kDegenerate;
  e.objective = pose.residual;
  e.reprojection_rms_px = kNaN;
  e.message = pose.message;
  e.diagnostics.rejected_objective = pose.rejected_residual;
  return e;
}

PoseEstimate dispatch(PoseMethod method, const Correspondences& data, const PoseOptions& options,
                      const Camera& camera) {
  switch (method) {
    case PoseMethod::kAffine:
      if (data.directions) return affine_directions(data, options);
      return from_affine(
          affine_pose(data.model, data.image, data.weights, affine_options(options, camera)),
          options.free_vectors);
    case PoseMethod::kStandard: {
      if (data.directions) return standard_directions(data);
      const AffinePoseOptions affine = affine_options(options, camera);
      return from_affine(standard_affine_pose(data.model, data.image, data.weights, affine),
                         options.free_vectors);
    }
    case PoseMethod::kAffineRefined:
    case PoseMethod::kPerspective:
      return refined(method, data, options, camera);
    case PoseMethod::kFull3d: {
      PoseEstimate e = from_pose_3d(
          full_3d_pose(data.model, data.measured, data.weights, affine_options(options, camera)));
      e.diagnostics.free_vectors = options.free_vectors;
      e.diagnostics.free_vector_count =
          free_vector_count(data.model.cols(), single_pattern_free_vectors(options.free_vectors));
      return e;
    }
    case PoseMethod::kOiFoam:
    case PoseMethod::kOiSvd:
      return orthogonal_iteration(method, data, options, camera);
    case PoseMethod::kTwoView:
      return two_view(data, camera);
    case PoseMethod::kHaralick2d:
      return haralick_2d(data);
    case PoseMethod::kHaralick3d: {
      OrientationOptions svd;
      svd.method = OrientationMethod::kSvd;
      return from_pose_3d(absolute_pose(data.model, data.measured, data.weights, svd));
    }
  }
  VANTAGE_CHECK(false, "unknown pose method");
  return {};
}

}  // namespace

PoseEstimate estimate_pose(PoseMethod method, const Correspondences& data,
                           const PoseOptions& options) {
  validate_correspondences(method, data, options);
  const Camera camera = camera_for(method, data.camera);
  PoseEstimate e = dispatch(method, data, options, camera);
  e.method = method;
  e.camera = camera;
  return e;
}

}  // namespace vantage
