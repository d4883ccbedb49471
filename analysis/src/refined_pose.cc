#include "vantage/analysis/refined_pose.h"

#include <cmath>
#include <sstream>

#include "pose_refinement.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/quaternion.h"

namespace vantage {

bool RefinedPoseOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  std::string inner;
  if (!camera.is_valid(&inner)) return fail("camera." + inner);
  if (!start.orientation.is_valid(&inner)) return fail("start.orientation." + inner);
  if (!(max_iterations >= 1)) return fail("max_iterations must be >= 1");
  if (!(step_tolerance > 0.0)) return fail("step_tolerance must be > 0");
  if (!(relative_tolerance >= 0.0)) return fail("relative_tolerance must be >= 0");
  if (!branches.is_valid(&inner)) return fail("branches." + inner);
  return true;
}

namespace {

enum class Model { kAffine, kPinhole };

double weight_sum(const Eigen::VectorXd& weights, Eigen::Index n) {
  return weights.size() == 0 ? static_cast<double>(n) : weights.sum();
}

internal::LmPose refine(Model model, const Eigen::Matrix3Xd& z, const Eigen::Matrix2Xd& centred,
                        const Eigen::VectorXd& weights, const RefinedPoseOptions& options,
                        const internal::LmPose& start) {
  internal::LmSettings settings;
  settings.max_iterations = options.max_iterations;
  settings.step_tolerance = options.step_tolerance;
  settings.relative_tolerance = options.relative_tolerance;
  return model == Model::kAffine
             ? internal::refine_scaled_orthographic(z, centred, weights, start, settings)
             : internal::refine_pinhole(z, centred, weights, options.camera.focal_length, start,
                                        settings);
}

RefinedPoseResult refined_pose(Model model, const Eigen::Matrix3Xd& z,
                               const Eigen::Matrix2Xd& image, const Eigen::VectorXd& weights,
                               const RefinedPoseOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
  const bool pinhole = model == Model::kPinhole;
  if (pinhole && !options.camera.has_focal_length())
    throw InvalidArgument("options: camera.focal_length must be > 0 for the perspective pose");
  AffinePoseOptions start_options = options.start;
  start_options.camera = options.camera;
  const AffinePoseResult affine = affine_pose(z, image, weights, start_options);

  RefinedPoseResult result;
  const double w_sum = weight_sum(weights, z.cols());
  const auto rms = [&](double sse) { return std::sqrt(sse / w_sum); };
  result.start_reprojection_rms_px = affine.reprojection_rms_px;
  if (affine.status == PoseStatus::kDegenerate) {
    result.R_camera_object = affine.R_camera_object;
    result.p_camera_object = affine.p_camera_object;
    result.status = PoseStatus::kDegenerate;
    result.message = "the affine start is degenerate: " + affine.message;
    return result;
  }
  const Eigen::Matrix2Xd centred = image.colwise() - options.camera.principal_point;
  const internal::PlaneFit plane = internal::fit_plane(z, weights);
  result.planarity = plane.planarity;

  internal::LmPose start;
  start.R = affine.R_camera_object;
  start.p = affine.p_camera_object;
  start.inverse_alpha = 1.0 / affine.alpha;
  internal::LmPose best = refine(model, z, centred, weights, options, start);
  result.branches = 1;
  result.iterations = best.iterations;
  if (plane.planarity <= options.branches.necker_planarity) {
    internal::LmPose mirror = start;
    internal::necker_mirror(plane, start.R, start.p, &mirror.R, &mirror.p);
    if (!pinhole) mirror.p.z() = start.p.z();
    internal::LmPose other = refine(model, z, centred, weights, options, mirror);
    result.branches = 2;
    result.iterations += other.iterations;
    if (other.sse < best.sse) std::swap(best, other);
    internal::LmPose planar;
    if (pinhole && internal::homography_start(z, centred, options.camera.focal_length, plane,
                                              &planar.R, &planar.p)) {
      internal::LmPose third = refine(model, z, centred, weights, options, planar);
      result.iterations += third.iterations;
      ++result.branches;
      const auto distinct = [&](const internal::LmPose& a, const internal::LmPose& b) {
        return rotation_angle_between(a.R, b.R) > options.branches.same_pose_angle;
      };
      if (third.sse < best.sse) {
        if (distinct(third, best)) other = best;
        best = third;
      } else if (distinct(third, best) && (third.sse < other.sse || !distinct(best, other))) {
        other = third;
      }
    }
    if (rotation_angle_between(best.R, other.R) > options.branches.same_pose_angle &&
        std::isfinite(other.sse)) {
      result.alternative = PoseAlternative{other.R, other.p, rms(other.sse)};
    }
  }
  result.R_camera_object = best.R;
  result.p_camera_object = best.p;
  result.reprojection_rms_px = rms(best.sse);
  result.alpha = pinhole ? best.p.z() / options.camera.focal_length : 1.0 / best.inverse_alpha;
  if (!pinhole) {
    result.p_camera_object.z() = options.camera.has_focal_length()
                                     ? result.alpha * options.camera.focal_length
                                     : std::numeric_limits<double>::quiet_NaN();
    if (result.alternative) result.alternative->p_camera_object.z() = result.p_camera_object.z();
  }
  result.ambiguous = options.branches.ambiguous(result);
  std::ostringstream message;
  if (best.degenerate) {
    result.status = PoseStatus::kDegenerate;
    message << "the normal equations are singular at the result: the points do not determine "
               "the pose (collinear?)";
  } else if (!best.converged) {
    result.status = PoseStatus::kMaxIterations;
    message << "stopped after max_iterations = " << options.max_iterations
            << " steps without meeting the stopping rule";
  } else if (result.ambiguous) {
    message << "the Necker branch fits about as well (rms "
            << result.alternative->reprojection_rms_px << " vs " << result.reprojection_rms_px
            << " px, ratio <= " << options.branches.ambiguity_ratio << ")";
  }
  result.message = message.str();
  return result;
}

}  // namespace

RefinedPoseResult affine_refined_pose(const Eigen::Matrix3Xd& model_object,
                                      const Eigen::Matrix2Xd& image, const Eigen::VectorXd& weights,
                                      const RefinedPoseOptions& options) {
  return refined_pose(Model::kAffine, model_object, image, weights, options);
}

RefinedPoseResult perspective_pose(const Eigen::Matrix3Xd& model_object,
                                   const Eigen::Matrix2Xd& image, const Eigen::VectorXd& weights,
                                   const RefinedPoseOptions& options) {
  return refined_pose(Model::kPinhole, model_object, image, weights, options);
}

}  // namespace vantage
