#include "vantage/analysis/refined_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include "perspective_start.h"
#include "pose_refinement.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"
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

const char* to_string(PerspectiveStart start) {
  switch (start) {
    case PerspectiveStart::kClosedForm:
      return "closed_form";
    case PerspectiveStart::kProp8:
      return "prop8";
  }
  return "unknown";
}

namespace {

enum class Model { kAffine, kPinhole };

double weight_sum(const Eigen::VectorXd& weights, Eigen::Index n) {
  return weights.size() == 0 ? static_cast<double>(n) : weights.sum();
}

/// The data every start and refinement of one solve shares.
struct Problem {
  Model model;
  const Eigen::Matrix3Xd& z;
  const Eigen::Matrix2Xd& image;
  const Eigen::VectorXd& weights;
  const RefinedPoseOptions& options;
  Eigen::Matrix2Xd centred;  // image - principal point
  internal::PlaneFit plane;

  bool pinhole() const { return model == Model::kPinhole; }
  bool planar() const { return plane.planarity <= options.branches.necker_planarity; }
  double start_sse(const internal::LmPose& start) const {
    return internal::pinhole_sse(z, centred, weights, options.camera.focal_length, start.R,
                                 start.p);
  }
};

internal::LmPose refine(const Problem& problem, const internal::LmPose& start) {
  internal::LmSettings settings;
  settings.max_iterations = problem.options.max_iterations;
  settings.step_tolerance = problem.options.step_tolerance;
  settings.relative_tolerance = problem.options.relative_tolerance;
  return problem.pinhole()
             ? internal::refine_pinhole(problem.z, problem.centred, problem.weights,
                                        problem.options.camera.focal_length, start, settings)
             : internal::refine_scaled_orthographic(problem.z, problem.centred, problem.weights,
                                                    start, settings);
}

internal::LmPose from(const internal::PinholeStart& start) {
  internal::LmPose pose;
  pose.R = start.R;
  pose.p = start.p;
  return pose;
}

internal::LmPose necker_mirror_of(const Problem& problem, const internal::LmPose& start) {
  internal::LmPose mirror = start;
  internal::necker_mirror(problem.plane, start.R, start.p, &mirror.R, &mirror.p);
  if (!problem.pinhole()) mirror.p.z() = start.p.z();
  return mirror;
}

/// The closed-form pinhole starts (perspective_start.h): POSIT, with its Necker mirror for
/// near-planar models, or IPPE's two poses for (almost) exactly planar ones. Empty when they do
/// not apply.
std::vector<internal::LmPose> closed_form_starts(const Problem& problem) {
  std::vector<internal::LmPose> starts;
  const double f = problem.options.camera.focal_length;
  internal::PinholeStart start;
  if (problem.plane.planarity > internal::kPlanarStartPlanarity &&
      internal::scaled_orthographic_start(problem.z, problem.centred, problem.weights, f,
                                          internal::PositSettings{}, &start)) {
    starts.push_back(from(start));
    if (problem.planar()) starts.push_back(necker_mirror_of(problem, starts.front()));
    return starts;
  }
  if (!problem.planar()) return starts;
  internal::PinholeStart planar[2];
  const int count = internal::planar_starts(problem.z, problem.centred, problem.weights, f,
                                            problem.plane, planar);
  for (int k = 0; k < count; ++k) starts.push_back(from(planar[k]));
  return starts;
}

/// Prop. 8's start, its Necker mirror for (near-)planar models and, under the pinhole model, the
/// better-fitting IPPE pose. *affine receives Prop. 8's result.
std::vector<internal::LmPose> prop8_starts(const Problem& problem, AffinePoseResult* affine) {
  AffinePoseOptions start_options = problem.options.start;
  start_options.camera = problem.options.camera;
  *affine = affine_pose(problem.z, problem.image, problem.weights, start_options);
  std::vector<internal::LmPose> starts;
  if (affine->status == PoseStatus::kDegenerate) return starts;
  internal::LmPose start;
  start.R = affine->R_camera_object;
  start.p = affine->p_camera_object;
  start.inverse_alpha = 1.0 / affine->alpha;
  starts.push_back(start);
  if (!problem.planar()) return starts;
  starts.push_back(necker_mirror_of(problem, start));
  internal::PinholeStart planar[2];
  const int count =
      problem.pinhole()
          ? internal::planar_starts(problem.z, problem.centred, problem.weights,
                                    problem.options.camera.focal_length, problem.plane, planar)
          : 0;
  if (count > 0) {
    const bool second =
        count == 2 && problem.start_sse(from(planar[1])) < problem.start_sse(from(planar[0]));
    starts.push_back(from(planar[second ? 1 : 0]));
  }
  return starts;
}

/// The best refined pose and the best one at a distinct rotation.
struct Branches {
  double same_pose_angle = 0.0;
  std::optional<internal::LmPose> best;
  std::optional<internal::LmPose> other;
  int count = 0;
  int iterations = 0;

  bool distinct(const internal::LmPose& a, const internal::LmPose& b) const {
    return rotation_angle_between(a.R, b.R) > same_pose_angle;
  }
  void add(const internal::LmPose& pose) {
    ++count;
    iterations += pose.iterations;
    if (!best) {
      best = pose;
    } else if (pose.sse < best->sse) {
      if (distinct(pose, *best)) other = best;
      best = pose;
    } else if (distinct(pose, *best) && std::isfinite(pose.sse) &&
               (!other || pose.sse < other->sse)) {
      other = pose;
    }
  }
};

/// The result's pose, scale, ambiguity and status from the refined branches.
void finish(const Problem& problem, const Branches& branches, RefinedPoseResult* result) {
  const RefinedPoseOptions& options = problem.options;
  const double w_sum = weight_sum(problem.weights, problem.z.cols());
  const auto rms = [&](double sse) { return std::sqrt(sse / w_sum); };
  const internal::LmPose& best = *branches.best;
  result->branches = branches.count;
  result->iterations = branches.iterations;
  if (branches.other && branches.distinct(best, *branches.other)) {
    result->alternative =
        PoseAlternative{branches.other->R, branches.other->p, rms(branches.other->sse)};
  }
  result->R_camera_object = best.R;
  result->p_camera_object = best.p;
  result->reprojection_rms_px = rms(best.sse);
  const double f = options.camera.focal_length;
  result->alpha = problem.pinhole() ? best.p.z() / f : 1.0 / best.inverse_alpha;
  if (!problem.pinhole()) {
    result->p_camera_object.z() = options.camera.has_focal_length()
                                      ? result->alpha * f
                                      : std::numeric_limits<double>::quiet_NaN();
    if (result->alternative) result->alternative->p_camera_object.z() = result->p_camera_object.z();
  }
  result->ambiguous = options.branches.ambiguous(*result);
  std::ostringstream message;
  if (best.degenerate) {
    result->status = PoseStatus::kDegenerate;
    message << "the normal equations are singular at the result: the points do not determine "
               "the pose (collinear?)";
  } else if (!best.converged) {
    result->status = PoseStatus::kMaxIterations;
    message << "stopped after max_iterations = " << options.max_iterations
            << " steps without meeting the stopping rule";
  } else if (result->ambiguous) {
    message << "the Necker branch fits about as well (rms "
            << result->alternative->reprojection_rms_px << " vs " << result->reprojection_rms_px
            << " px, ratio <= " << options.branches.ambiguity_ratio << ")";
  }
  result->message = message.str();
}

RefinedPoseResult refined_pose(Model model, const Eigen::Matrix3Xd& z,
                               const Eigen::Matrix2Xd& image, const Eigen::VectorXd& weights,
                               const RefinedPoseOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
  const bool pinhole = model == Model::kPinhole;
  if (pinhole && !options.camera.has_focal_length())
    throw InvalidArgument("options: camera.focal_length must be > 0 for the perspective pose");
  internal::check_correspondences("model_object", z, "image", image, weights, 3);
  internal::check_distinct_columns("model_object", z);
  Problem problem{model,
                  z,
                  image,
                  weights,
                  options,
                  image.colwise() - options.camera.principal_point,
                  internal::fit_plane(z, weights)};
  RefinedPoseResult result;
  result.planarity = problem.plane.planarity;

  std::vector<internal::LmPose> starts;
  if (pinhole && options.perspective_start == PerspectiveStart::kClosedForm)
    starts = closed_form_starts(problem);
  AffinePoseResult affine;
  if (starts.empty()) {
    starts = prop8_starts(problem, &affine);
    if (starts.empty()) {
      result.R_camera_object = affine.R_camera_object;
      result.p_camera_object = affine.p_camera_object;
      result.start_reprojection_rms_px = affine.reprojection_rms_px;
      result.status = PoseStatus::kDegenerate;
      result.message = affine.message;
      return result;
    }
  }
  if (pinhole) {
    double sse = std::numeric_limits<double>::infinity();
    for (const internal::LmPose& start : starts) sse = std::min(sse, problem.start_sse(start));
    result.start_reprojection_rms_px = std::sqrt(sse / weight_sum(weights, z.cols()));
  } else {
    result.start_reprojection_rms_px = affine.reprojection_rms_px;
  }
  Branches branches;
  branches.same_pose_angle = options.branches.same_pose_angle;
  for (const internal::LmPose& start : starts) branches.add(refine(problem, start));
  finish(problem, branches, &result);
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
