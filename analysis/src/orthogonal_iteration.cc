#include "vantage/analysis/orthogonal_iteration.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>

#include "perspective_start.h"
#include "pose_refinement.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage {

bool OrthogonalIterationOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  std::string inner;
  if (!camera.is_valid(&inner)) {
    if (why) *why = "camera." + inner;
    return false;
  }
  if (!camera.has_focal_length()) return fail("camera.focal_length must be > 0 (pixels)");
  if (!(absolute_tolerance >= 0.0)) return fail("absolute_tolerance must be >= 0");
  if (!(relative_tolerance >= 0.0)) return fail("relative_tolerance must be >= 0");
  if (!(pose_tolerance >= 0.0)) return fail("pose_tolerance must be >= 0");
  if (!branches.is_valid(&inner)) {
    if (why) *why = "branches." + inner;
    return false;
  }
  if (max_iterations < 0) return fail("max_iterations must be >= 0");
  if (!(degenerate_tolerance >= 0.0 && degenerate_tolerance < 1.0))
    return fail("degenerate_tolerance must be in [0, 1)");
  if (!(eigen.fallback_relative_gap >= 0.0 && eigen.fallback_relative_gap < 1.0))
    return fail("eigen.fallback_relative_gap must be in [0, 1)");
  return true;
}

namespace {

void validate(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
              const Eigen::VectorXd& weights, const OrthogonalIterationOptions& options,
              Eigen::Index min_points) {
  internal::check_options("options", options);
  internal::check_correspondences("model_object", model, "image", image, weights, min_points);
}

/// The line of sight m_i = ((u - c_x) / f, (v - c_y) / f, 1).
inline Eigen::Vector3d ray(const Eigen::Matrix2Xd& image, Eigen::Index i, const Camera& camera) {
  const double inverse_focal = 1.0 / camera.focal_length;
  return Eigen::Vector3d((image(0, i) - camera.principal_point.x()) * inverse_focal,
                         (image(1, i) - camera.principal_point.y()) * inverse_focal, 1.0);
}

/// Pinhole RMS image residual in pixels (+infinity with a point at or behind the camera).
double reprojection_rms(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                        const Eigen::VectorXd& weights, const Camera& camera,
                        const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  double sse = 0.0;
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const Eigen::Vector3d x = R * model.col(i) + p;
    if (!(x.z() > 0.0)) return std::numeric_limits<double>::infinity();
    const Eigen::Vector2d q = camera.principal_point + camera.focal_length / x.z() * x.head<2>();
    sse += internal::weight_at(weights, i) * (q - image.col(i)).squaredNorm();
    weight_sum += internal::weight_at(weights, i);
  }
  return std::sqrt(sse / weight_sum);
}

/// Everything the iteration needs that does not change with R.
struct Setup {
  Eigen::Vector3d model_mean = Eigen::Vector3d::Zero();  // x_bar
  Eigen::Matrix<double, 3, 9> translation_factor;        // p(R) = factor * vec(R), Eq. (10)
  double f_min_eigenvalue = 0.0;                         // of F = sum w (I - V)
  double weight_sum = 0.0;
  double spread = 0.0;  // sum w |x - x_bar|^2
};

Setup make_setup(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                 const Eigen::VectorXd& weights, const Camera& camera) {
  Setup s;
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  // sum_i w_i x_ik (V_i - I) for k = 0, 1, 2: the blocks of the factor before F^-1.
  Eigen::Matrix<double, 3, 9> blocks = Eigen::Matrix<double, 3, 9>::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double w = internal::weight_at(weights, i);
    const Eigen::Vector3d m = ray(image, i, camera);
    const Eigen::Matrix3d v_minus_i =
        m * m.transpose() / m.squaredNorm() - Eigen::Matrix3d::Identity();
    F -= w * v_minus_i;
    for (int k = 0; k < 3; ++k) blocks.middleCols<3>(3 * k) += (w * model(k, i)) * v_minus_i;
    s.model_mean += w * model.col(i);
    s.weight_sum += w;
  }
  s.model_mean /= s.weight_sum;
  for (Eigen::Index i = 0; i < model.cols(); ++i)
    s.spread += internal::weight_at(weights, i) * (model.col(i) - s.model_mean).squaredNorm();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(F, Eigen::EigenvaluesOnly);
  s.f_min_eigenvalue = eigen.eigenvalues()(0);
  const Eigen::Matrix3d f_inverse = F.inverse();
  for (int k = 0; k < 3; ++k)
    s.translation_factor.middleCols<3>(3 * k) = f_inverse * blocks.middleCols<3>(3 * k);
  return s;
}

inline Eigen::Vector3d optimal_translation(const Setup& s, const Eigen::Matrix3d& R) {
  return s.translation_factor.middleCols<3>(0) * R.col(0) +
         s.translation_factor.middleCols<3>(3) * R.col(1) +
         s.translation_factor.middleCols<3>(6) * R.col(2);
}

/// One pass over the points: returns E(R, p) and sets H = sum w (x_i - x_bar) q_i^T with
/// q_i = V_i (R x_i + p), the cross-covariance of the next absolute-orientation step.
double collinearity_pass(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                         const Eigen::VectorXd& weights, const Camera& camera,
                         const Eigen::Vector3d& model_mean, const Eigen::Matrix3d& R,
                         const Eigen::Vector3d& p, Eigen::Matrix3d* H) {
  double error = 0.0;
  H->setZero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double w = internal::weight_at(weights, i);
    const Eigen::Vector3d x = R * model.col(i) + p;
    const Eigen::Vector3d m = ray(image, i, camera);
    const Eigen::Vector3d q = m * (m.dot(x) / m.squaredNorm());
    error += w * (x - q).squaredNorm();
    H->noalias() += w * (model.col(i) - model_mean) * q.transpose();
  }
  return error;
}

OrientationOptions step_options(const OrthogonalIterationOptions& options) {
  OrientationOptions step;
  step.method = options.rotation_step;
  step.eigen = options.eigen;
  return step;
}

bool step_is_degenerate(const Eigen::Matrix3d& H, double gap, double tolerance) {
  const double scale = 2.0 * H.norm();
  return !(scale > 0.0) || !(gap > tolerance * scale);
}

Eigen::Matrix3d weak_perspective_start(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                                       const Eigen::VectorXd& weights,
                                       const OrthogonalIterationOptions& options,
                                       const Eigen::Vector3d& model_mean, bool* degenerate) {
  Eigen::Vector3d ray_mean = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    ray_mean += internal::weight_at(weights, i) * ray(image, i, options.camera);
    weight_sum += internal::weight_at(weights, i);
  }
  ray_mean /= weight_sum;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    H.noalias() += internal::weight_at(weights, i) * (model.col(i) - model_mean) *
                   (ray(image, i, options.camera) - ray_mean).transpose();
  }
  double gap = 0.0;
  const Eigen::Matrix3d R = optimal_rotation(H, step_options(options), &gap);
  *degenerate = step_is_degenerate(H, gap, options.degenerate_tolerance);
  return R;
}

OrthogonalIterationResult iterate(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                                  const Eigen::VectorXd& weights, const Setup& setup,
                                  const Eigen::Matrix3d& initial_R,
                                  const OrthogonalIterationOptions& options) {
  OrthogonalIterationResult result;
  if (!(setup.f_min_eigenvalue > options.degenerate_tolerance * setup.weight_sum)) {
    result.status = PoseStatus::kDegenerate;
    result.message =
        "all lines of sight are (nearly) parallel: sum w_i (I - V_i) is singular, the "
        "translation is undetermined";
    return result;
  }
  const OrientationOptions step = step_options(options);
  const Camera& camera = options.camera;

  Eigen::Matrix3d R = initial_R;
  Eigen::Vector3d p = optimal_translation(setup, R);
  Eigen::Matrix3d H;
  double error = collinearity_pass(model, image, weights, camera, setup.model_mean, R, p, &H);
  result.initial_objective = error;
  result.status = PoseStatus::kMaxIterations;
  while (true) {
    if (error <= options.absolute_tolerance * setup.spread) {
      result.status = PoseStatus::kOk;
      break;
    }
    if (result.iterations >= options.max_iterations) break;
    double gap = 0.0;
    const Eigen::Matrix3d previous_R = R;
    const Eigen::Vector3d previous_p = p;
    R = optimal_rotation(H, step, &gap);
    if (step_is_degenerate(H, gap, options.degenerate_tolerance)) {
      result.status = PoseStatus::kDegenerate;
      result.message =
          "the absolute-orientation step is degenerate (relative eigen gap below "
          "degenerate_tolerance): collinear or coincident model points?";
    }
    p = optimal_translation(setup, R);
    const double previous = error;
    error = collinearity_pass(model, image, weights, camera, setup.model_mean, R, p, &H);
    ++result.iterations;
    if (result.status == PoseStatus::kDegenerate) break;
    const bool objective_still =
        std::abs(previous - error) <= options.relative_tolerance * previous;
    const bool pose_still = rotation_angle_between(previous_R, R) <= options.pose_tolerance &&
                            (p - previous_p).norm() <= options.pose_tolerance * p.norm();
    if (objective_still || pose_still) {
      result.status = PoseStatus::kOk;
      break;
    }
  }
  if (result.status == PoseStatus::kMaxIterations) {
    std::ostringstream out;
    out << "stopped after max_iterations = " << options.max_iterations
        << " rotation steps with E = " << error;
    result.message = out.str();
  }
  result.R_camera_object = R;
  result.p_camera_object = p;
  result.objective = error;
  result.reprojection_rms_px = reprojection_rms(model, image, weights, camera, R, p);
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    if (!((R * model.col(i) + p).z() > 0.0)) ++result.points_behind_camera;
  }
  return result;
}

/// The two starts of a (near-)planar model: for an (almost) exactly planar one IPPE's pair of
/// poses from the plane's homography (perspective_start.h), exact on noise-free images; else, or
/// when the homography is degenerate, Prop. 8 (affine_pose()) and its
/// Necker mirror, whose rotation carries the tilt. The weak-perspective start cannot: with
/// coplanar points the centred model and the centred rays both lie in planes, so its
/// cross-covariance only determines a rotation about the axis. *found is false when neither
/// applies (a degenerate homography and a degenerate or refused affine estimate: coincident
/// model points, which orthogonal iteration itself accepts).
void planar_starts(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                   const Eigen::VectorXd& weights, const OrthogonalIterationOptions& options,
                   const internal::PlaneFit& plane, Eigen::Matrix3d starts[2], bool* found) {
  const Eigen::Matrix2Xd centred = image.colwise() - options.camera.principal_point;
  internal::PinholeStart ippe[2];
  // IPPE only where the homography describes the points: on merely near-planar models (4 random
  // points, say) its poses can lie outside OI's basin, where Prop. 8's pair does not.
  if (plane.planarity <= internal::kPlanarStartPlanarity &&
      internal::planar_starts(model, centred, weights, options.camera.focal_length, plane, ippe) ==
          2) {
    starts[0] = ippe[0].R;
    starts[1] = ippe[1].R;
    *found = true;
    return;
  }
  AffinePoseOptions affine;
  affine.camera = options.camera;
  try {
    const AffinePoseResult start = affine_pose(model, image, weights, affine);
    *found = start.status == PoseStatus::kOk;
    starts[0] = start.R_camera_object;
  } catch (const InvalidArgument&) {
    *found = false;
  }
  Eigen::Vector3d unused;
  if (*found)
    internal::necker_mirror(plane, starts[0], Eigen::Vector3d::Zero(), &starts[1], &unused);
}

/// Iterates from both starts and keeps the better of the two (smaller E, then fewer points
/// behind the camera), recording the other as the alternative.
OrthogonalIterationResult with_two_branches(const Eigen::Matrix3Xd& model,
                                            const Eigen::Matrix2Xd& image,
                                            const Eigen::VectorXd& weights, const Setup& setup,
                                            const Eigen::Matrix3d starts[2],
                                            const OrthogonalIterationOptions& options) {
  OrthogonalIterationResult first = iterate(model, image, weights, setup, starts[0], options);
  OrthogonalIterationResult second = iterate(model, image, weights, setup, starts[1], options);
  const auto worse = [](const OrthogonalIterationResult& a, const OrthogonalIterationResult& b) {
    if (a.status == PoseStatus::kDegenerate) return b.status != PoseStatus::kDegenerate;
    if (a.points_behind_camera != b.points_behind_camera)
      return a.points_behind_camera > b.points_behind_camera;
    return a.objective > b.objective;
  };
  if (worse(first, second)) std::swap(first, second);
  first.iterations += second.iterations;
  first.branches = 2;
  if (second.status != PoseStatus::kDegenerate &&
      rotation_angle_between(first.R_camera_object, second.R_camera_object) >
          options.branches.same_pose_angle) {
    first.alternative =
        PoseAlternative{second.R_camera_object, second.p_camera_object, second.reprojection_rms_px};
    first.ambiguous = options.branches.ambiguous(first);
  }
  if (first.ambiguous && first.status == PoseStatus::kOk) {
    first.message = "the Necker branch fits about as well (see alternative)";
  }
  return first;
}

}  // namespace

OrthogonalIterationResult orthogonal_iteration_pose(const Eigen::Matrix3Xd& model_object,
                                                    const Eigen::Matrix2Xd& image,
                                                    const Eigen::VectorXd& weights,
                                                    const OrthogonalIterationOptions& options) {
  validate(model_object, image, weights, options, 3);
  const Setup setup = make_setup(model_object, image, weights, options.camera);
  bool degenerate = false;
  const Eigen::Matrix3d start =
      weak_perspective_start(model_object, image, weights, options, setup.model_mean, &degenerate);
  if (degenerate) {
    OrthogonalIterationResult result;
    result.R_camera_object = start;
    result.status = PoseStatus::kDegenerate;
    result.message =
        "the model points or their images are collinear (or coincide): they do not determine "
        "the pose";
    return result;
  }
  const internal::PlaneFit plane = internal::fit_plane(model_object, weights);
  if (plane.planarity > options.branches.necker_planarity) {
    return iterate(model_object, image, weights, setup, start, options);
  }
  bool found = false;
  Eigen::Matrix3d starts[2];
  planar_starts(model_object, image, weights, options, plane, starts, &found);
  if (!found) {
    starts[0] = start;
    Eigen::Vector3d unused;
    internal::necker_mirror(plane, start, Eigen::Vector3d::Zero(), &starts[1], &unused);
  }
  return with_two_branches(model_object, image, weights, setup, starts, options);
}

OrthogonalIterationResult orthogonal_iteration_pose(const Eigen::Matrix3Xd& model_object,
                                                    const Eigen::Matrix2Xd& image,
                                                    const Eigen::Matrix3d& initial_R_camera_object,
                                                    const Eigen::VectorXd& weights,
                                                    const OrthogonalIterationOptions& options) {
  validate(model_object, image, weights, options, 3);
  const Eigen::Matrix3d& R0 = initial_R_camera_object;
  if (!R0.allFinite() || (R0.transpose() * R0 - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
      !(R0.determinant() > 0.0)) {
    throw InvalidArgument("initial_R_camera_object is not a rotation matrix");
  }
  const Setup setup = make_setup(model_object, image, weights, options.camera);
  return iterate(model_object, image, weights, setup, R0, options);
}

Eigen::Matrix3d weak_perspective_rotation(const Eigen::Matrix3Xd& model_object,
                                          const Eigen::Matrix2Xd& image,
                                          const Eigen::VectorXd& weights,
                                          const OrthogonalIterationOptions& options) {
  validate(model_object, image, weights, options, 3);
  Eigen::Vector3d model_mean = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < model_object.cols(); ++i) {
    model_mean += internal::weight_at(weights, i) * model_object.col(i);
    weight_sum += internal::weight_at(weights, i);
  }
  model_mean /= weight_sum;
  bool degenerate = false;
  return weak_perspective_start(model_object, image, weights, options, model_mean, &degenerate);
}

double object_space_error(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                          const Eigen::Matrix3d& R_camera_object,
                          const Eigen::Vector3d& p_camera_object, const Eigen::VectorXd& weights,
                          const OrthogonalIterationOptions& options) {
  validate(model_object, image, weights, options, 1);
  if (!R_camera_object.allFinite()) throw InvalidArgument("R_camera_object is not finite");
  if (!p_camera_object.allFinite()) throw InvalidArgument("p_camera_object is not finite");
  Eigen::Matrix3d unused;
  return collinearity_pass(model_object, image, weights, options.camera, Eigen::Vector3d::Zero(),
                           R_camera_object, p_camera_object, &unused);
}

}  // namespace vantage
