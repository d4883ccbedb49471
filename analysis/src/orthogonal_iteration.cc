#include "vantage/analysis/orthogonal_iteration.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "vantage/analysis/common.h"

namespace vantage {

const char* to_string(OrthogonalIterationStatus status) {
  switch (status) {
    case OrthogonalIterationStatus::kConverged:
      return "converged";
    case OrthogonalIterationStatus::kMaxIterations:
      return "max_iterations";
    case OrthogonalIterationStatus::kDegenerate:
      return "degenerate";
  }
  return "unknown";
}

bool OrthogonalIterationOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(focal_length > 0.0 && std::isfinite(focal_length)))
    return fail("focal_length must be positive and finite");
  if (!(absolute_tolerance >= 0.0)) return fail("absolute_tolerance must be >= 0");
  if (!(relative_tolerance >= 0.0)) return fail("relative_tolerance must be >= 0");
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
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options: " + why);
  if (model.cols() != image.cols()) {
    std::ostringstream out;
    out << "model_object has " << model.cols() << " points but image has " << image.cols();
    throw InvalidArgument(out.str());
  }
  if (model.cols() < min_points) {
    std::ostringstream out;
    out << "model_object: need at least " << min_points << " points, got " << model.cols();
    throw InvalidArgument(out.str());
  }
  if (weights.size() != 0 && weights.size() != model.cols()) {
    std::ostringstream out;
    out << "weights has " << weights.size() << " entries, expected " << model.cols();
    throw InvalidArgument(out.str());
  }
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    if (!model.col(i).allFinite())
      throw InvalidArgument("model_object[" + std::to_string(i) + "] is not finite");
    if (!image.col(i).allFinite())
      throw InvalidArgument("image[" + std::to_string(i) + "] is not finite");
    if (weights.size() != 0 && !(weights(i) > 0.0 && std::isfinite(weights(i))))
      throw InvalidArgument("weights[" + std::to_string(i) + "] must be positive and finite");
  }
}

inline double weight(const Eigen::VectorXd& weights, Eigen::Index i) {
  return weights.size() == 0 ? 1.0 : weights(i);
}

/// The line of sight m_i = (u / f, v / f, 1).
inline Eigen::Vector3d ray(const Eigen::Matrix2Xd& image, Eigen::Index i, double inverse_focal) {
  return Eigen::Vector3d(image(0, i) * inverse_focal, image(1, i) * inverse_focal, 1.0);
}

/// Everything the iteration needs that does not change with R.
struct Setup {
  Eigen::Vector3d model_mean = Eigen::Vector3d::Zero();  // x_bar
  Eigen::Matrix<double, 3, 9> translation_factor;        // p(R) = factor * vec(R), Eq. (10)
  double f_min_eigenvalue = 0.0;                         // of F = sum w (I - V)
  double weight_sum = 0.0;
};

Setup make_setup(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& image,
                 const Eigen::VectorXd& weights, double inverse_focal) {
  Setup s;
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  // sum_i w_i x_ik (V_i - I) for k = 0, 1, 2: the blocks of the factor before F^-1.
  Eigen::Matrix<double, 3, 9> blocks = Eigen::Matrix<double, 3, 9>::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double w = weight(weights, i);
    const Eigen::Vector3d m = ray(image, i, inverse_focal);
    const Eigen::Matrix3d v_minus_i =
        m * m.transpose() / m.squaredNorm() - Eigen::Matrix3d::Identity();
    F -= w * v_minus_i;
    for (int k = 0; k < 3; ++k) blocks.middleCols<3>(3 * k) += (w * model(k, i)) * v_minus_i;
    s.model_mean += w * model.col(i);
    s.weight_sum += w;
  }
  s.model_mean /= s.weight_sum;
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
                         const Eigen::VectorXd& weights, double inverse_focal,
                         const Eigen::Vector3d& model_mean, const Eigen::Matrix3d& R,
                         const Eigen::Vector3d& p, Eigen::Matrix3d* H) {
  double error = 0.0;
  H->setZero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const double w = weight(weights, i);
    const Eigen::Vector3d x = R * model.col(i) + p;
    const Eigen::Vector3d m = ray(image, i, inverse_focal);
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
  const double inverse_focal = 1.0 / options.focal_length;
  Eigen::Vector3d ray_mean = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    ray_mean += weight(weights, i) * ray(image, i, inverse_focal);
    weight_sum += weight(weights, i);
  }
  ray_mean /= weight_sum;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    H.noalias() += weight(weights, i) * (model.col(i) - model_mean) *
                   (ray(image, i, inverse_focal) - ray_mean).transpose();
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
  using Status = OrthogonalIterationStatus;
  OrthogonalIterationResult result;
  const double inverse_focal = 1.0 / options.focal_length;
  if (!(setup.f_min_eigenvalue > options.degenerate_tolerance * setup.weight_sum)) {
    result.status = Status::kDegenerate;
    result.message =
        "all lines of sight are (nearly) parallel: sum w_i (I - V_i) is singular, the "
        "translation is undetermined";
    return result;
  }
  const OrientationOptions step = step_options(options);

  Eigen::Matrix3d R = initial_R;
  Eigen::Vector3d p = optimal_translation(setup, R);
  Eigen::Matrix3d H;
  double error =
      collinearity_pass(model, image, weights, inverse_focal, setup.model_mean, R, p, &H);
  result.initial_error = error;
  result.status = Status::kMaxIterations;
  while (true) {
    if (error <= options.absolute_tolerance) {
      result.status = Status::kConverged;
      break;
    }
    if (result.iterations >= options.max_iterations) break;
    double gap = 0.0;
    R = optimal_rotation(H, step, &gap);
    if (step_is_degenerate(H, gap, options.degenerate_tolerance)) {
      result.status = Status::kDegenerate;
      result.message =
          "the absolute-orientation step is degenerate (relative eigen gap below "
          "degenerate_tolerance): collinear or coincident model points?";
    }
    p = optimal_translation(setup, R);
    const double previous = error;
    error = collinearity_pass(model, image, weights, inverse_focal, setup.model_mean, R, p, &H);
    ++result.iterations;
    if (result.status == Status::kDegenerate) break;
    if (std::abs(previous - error) <= options.relative_tolerance * previous) {
      result.status = Status::kConverged;
      break;
    }
  }
  if (result.status == Status::kMaxIterations) {
    std::ostringstream out;
    out << "stopped after max_iterations = " << options.max_iterations
        << " rotation steps with E = " << error;
    result.message = out.str();
  }
  result.R_camera_object = R;
  result.p_camera_object = p;
  result.error = error;
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    if (!((R * model.col(i) + p).z() > 0.0)) ++result.points_behind_camera;
  }
  return result;
}

}  // namespace

OrthogonalIterationResult orthogonal_iteration_pose(const Eigen::Matrix3Xd& model_object,
                                                    const Eigen::Matrix2Xd& image,
                                                    const Eigen::VectorXd& weights,
                                                    const OrthogonalIterationOptions& options) {
  validate(model_object, image, weights, options, 3);
  const Setup setup = make_setup(model_object, image, weights, 1.0 / options.focal_length);
  bool degenerate = false;
  const Eigen::Matrix3d start =
      weak_perspective_start(model_object, image, weights, options, setup.model_mean, &degenerate);
  if (degenerate) {
    OrthogonalIterationResult result;
    result.R_camera_object = start;
    result.status = OrthogonalIterationStatus::kDegenerate;
    result.message =
        "the weak-perspective start is degenerate: the centred model or the centred image "
        "points span less than a plane (coincident or collinear points?)";
    return result;
  }
  return iterate(model_object, image, weights, setup, start, options);
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
  const Setup setup = make_setup(model_object, image, weights, 1.0 / options.focal_length);
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
    model_mean += weight(weights, i) * model_object.col(i);
    weight_sum += weight(weights, i);
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
  return collinearity_pass(model_object, image, weights, 1.0 / options.focal_length,
                           Eigen::Vector3d::Zero(), R_camera_object, p_camera_object, &unused);
}

}  // namespace vantage
