#include "vantage/simulate/bound_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/simulate/estimators.h"

namespace vantage::simulate {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

VectorSetBound certify(const std::string& name, const Eigen::Matrix3Xd& vectors,
                       const Eigen::Matrix2Xi& pairs) {
  const sdp::WorstViewpoint worst = sdp::global_worst_viewpoint(vectors);
  VANTAGE_CHECK(worst.status == sdp::WorstViewpoint::Status::kCertified,
                "bound check: the worst viewpoint of the " + name + " is not certified");
  VectorSetBound set;
  set.free_vectors = name;
  set.vectors = vectors;
  set.pairs = pairs;
  set.worst_viewpoint = worst.viewpoint;
  set.t_lower = worst.t_lower;
  set.t_upper = worst.t_upper;
  set.pbar_min = worst.pbar_min;
  set.bound_rad = std::asin(std::min(1.0, worst.t_upper));
  return set;
}

/// The free vectors of `which` for the object points alone (kAuto: before an image's LUB pair).
VectorSetBound free_vector_bound(const Eigen::Matrix3Xd& points, FreeVectorSet which) {
  const FreeVectorsOf<3> free = build_free_vectors<3>(
      points, points, {}, free_vector_pairs(points, which), PairWeighting::kGeometricMean);
  return certify(to_string(which), free.z_object, free.pairs);
}

/// The image-side data vectors d of a scene, one per data vector of the layout, in the free-vector
/// convention of free_vectors.h: pair (i, j) gives q_j - q_i.
Eigen::Matrix2Xd image_vectors(const BoundLayout& layout, const Scene& scene) {
  if (layout.vectors) return scene.image_clean;
  const Eigen::Matrix2Xi& pairs = layout.data.pairs;
  Eigen::Matrix2Xd d(2, pairs.cols());
  for (Eigen::Index k = 0; k < pairs.cols(); ++k) {
    d.col(k) = scene.image_clean.col(pairs(1, k)) - scene.image_clean.col(pairs(0, k));
  }
  return d;
}

const double kEpsilon = std::numeric_limits<double>::epsilon();

/// How far the elevation asin(x) of a vector can move when x in [0, 1] moves by a relative u:
/// u x / sqrt(1 - x^2) where that is small, and at most about sqrt(2 u x) at x = 1 (where asin
/// has an infinite slope).
double elevation_sensitivity(double x, double u) {
  const double c = std::sqrt(std::max(0.0, (1.0 - x) * (1.0 + x)));
  return u * x / std::max(c, std::sqrt(u * x));
}

/// The relative rounding of each p_i = alpha |d_i| / |z_i|: a few roundings of each norm, plus
/// the cancellation of the differences in point mode (d_i = q_b - q_a of image points and
/// z_i = x_b - x_a of markers keep only |d_i| / (|q_a| + |q_b|) of their digits).
Eigen::VectorXd input_rounding(const BoundLayout& layout, const Scene& scene,
                               const Eigen::Matrix2Xd& d) {
  const Eigen::Index m = d.cols();
  Eigen::VectorXd u = Eigen::VectorXd::Constant(m, kEq26InputUlps * kEpsilon);
  if (layout.vectors) return u;
  const Eigen::Matrix2Xi& pairs = layout.data.pairs;
  const Eigen::Matrix3Xd& z = layout.data.vectors;
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Index a = pairs(0, k), b = pairs(1, k);
    const double image =
        (scene.image_clean.col(a).norm() + scene.image_clean.col(b).norm()) / d.col(k).norm();
    const double object =
        (layout.entries.col(a).norm() + layout.entries.col(b).norm()) / z.col(k).norm();
    u(k) *= 1.0 + image + object;
  }
  return u;
}

/// A noise-free copy of `scene` for the estimators (the trial's noisy image is not used).
Scene noise_free(const Scene& scene) {
  Scene clean = scene;
  clean.image = scene.image_clean;
  clean.sigma = 0.0;
  return clean;
}

}  // namespace

BoundLayout prepare_bound_layout(const Eigen::Matrix3Xd& entries, bool vectors) {
  if (!entries.allFinite() || entries.cols() < (vectors ? 2 : 3)) {
    throw InvalidArgument("prepare_bound_layout: entries must be finite, 3 x n with n >= " +
                          std::string(vectors ? "2 vectors" : "3 points"));
  }
  BoundLayout layout;
  layout.entries = entries;
  layout.vectors = vectors;
  if (vectors) {
    layout.data = certify("vectors", entries, Eigen::Matrix2Xi());
    layout.affine = layout.data;
    return layout;
  }
  layout.data = free_vector_bound(entries, FreeVectorSet::kAllPairs);
  layout.spanning = free_vector_bound(entries, FreeVectorSet::kMaxSpanningTree);
  layout.affine = layout.data.vectors.cols() <= kAutoAllPairsLimit
                      ? layout.data
                      : free_vector_bound(entries, FreeVectorSet::kAuto);
  return layout;
}

VectorErrors vector_errors(const BoundLayout& layout, const Scene& scene) {
  if (scene.kind != SceneKind::kAffineImage && scene.kind != SceneKind::kAffineVectors) {
    throw InvalidArgument("vector_errors: scene must be an affine image of the layout");
  }
  const Eigen::Matrix3Xd& z = layout.data.vectors;
  Eigen::Matrix2Xd d = image_vectors(layout, scene);
  const Eigen::Index m = z.cols();
  Eigen::VectorXd ratio(m);
  for (Eigen::Index k = 0; k < m; ++k) ratio(k) = d.col(k).norm() / z.col(k).norm();
  Eigen::Index limiting = 0;
  const double max_ratio = ratio.maxCoeff(&limiting);
  const Eigen::VectorXd rounding = input_rounding(layout, scene, d);
  VectorErrors out;
  out.p = scene.alpha_true * ratio;
  out.pbar = scene.alpha_true * max_ratio;
  out.angle_rad.resize(m);
  out.eq26_rad.resize(m);
  out.tolerance_rad.resize(m);
  const double pbar = std::min(1.0, out.pbar);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Vector3d v = scene.R_true * z.col(k) / scene.alpha_true;
    const double r = max_ratio > 0.0 ? ratio(k) / max_ratio : 0.0;
    const double p = std::min(out.p(k), pbar);
    out.eq26_rad(k) = lub_scale_error_angle(p, pbar);
    // p and r come from rounded data; the angles are near-singular functions of them at 1.
    const double u_p = rounding(k);
    const double u_r = rounding(k) + rounding(limiting);
    out.tolerance_rad(k) = kEq26ConditioningMargin * (u_p + elevation_sensitivity(p, u_p) +
                                                      elevation_sensitivity(r, u_r)) +
                           kEq26AngleUlps * kEpsilon * (1.0 + out.eq26_rad(k));
    if (r == 0.0) {  // along the optical axis: v_e is parallel to v, no error
      out.angle_rad(k) = 0.0;
      continue;
    }
    const double depth = d.col(k).norm() * std::sqrt((1.0 - r) * (1.0 + r)) / r;
    const Eigen::Vector3d v_e(d(0, k), d(1, k), v.z() < 0.0 ? -depth : depth);
    out.angle_rad(k) = std::atan2(v.cross(v_e).norm(), v.dot(v_e));
  }
  return out;
}

BoundTrial check_bound_trial(const BoundLayout& layout, const Scene& scene) {
  const VectorErrors errors = vector_errors(layout, scene);
  BoundTrial trial;
  trial.pbar = errors.pbar;
  trial.max_error_rad = errors.angle_rad.maxCoeff();
  const Eigen::VectorXd mismatch = (errors.angle_rad - errors.eq26_rad).cwiseAbs();
  trial.max_mismatch_rad = mismatch.maxCoeff();
  trial.max_mismatch_ratio = mismatch.cwiseQuotient(errors.tolerance_rad).maxCoeff();
  const Scene clean = noise_free(scene);
  const auto rot_err = [&](const char* name) {
    const Estimator* estimator = find_estimator(name);
    VANTAGE_CHECK(estimator != nullptr, std::string("registry lacks ") + name);
    if (!estimator->applies(clean)) return kNaN;  // e.g. too many markers to enumerate
    return rotation_angle_between(estimator->solve(clean).R_camera_object, scene.R_true);
  };
  trial.affine_rot_err_rad = rot_err("affine");
  trial.spanning_rot_err_rad = layout.vectors ? kNaN : rot_err("affine-spanning");
  return trial;
}

BoundCheckAccumulator::BoundCheckAccumulator(const BoundLayout& layout)
    : bound_rad_(layout.data.bound_rad),
      vectors_(layout.data.vectors.cols()),
      pbar_min_(layout.data.pbar_min),
      point_mode_(!layout.vectors) {
  const VectorSetBound& used = layout.affine;
  relations_.push_back({"affine", used.free_vectors, used.bound_rad, used.pbar_min, {}, 0, 0});
  if (point_mode_) {
    relations_.push_back({"affine-spanning",
                          layout.spanning.free_vectors,
                          layout.spanning.bound_rad,
                          layout.spanning.pbar_min,
                          {},
                          0,
                          0});
  }
}

void BoundCheckAccumulator::add(long trial, const BoundTrial& t) {
  ++trials_;
  if (t.max_error_rad > max_error_rad_ || trials_ == 1) {
    max_error_rad_ = std::max(max_error_rad_, t.max_error_rad);
    worst_error_trial_ = trial;
  }
  max_mismatch_rad_ = std::max(max_mismatch_rad_, t.max_mismatch_rad);
  if (t.max_mismatch_ratio > max_mismatch_ratio_ || trials_ == 1) {
    max_mismatch_ratio_ = std::max(max_mismatch_ratio_, t.max_mismatch_ratio);
    worst_mismatch_trial_ = trial;
  }
  const double rotation[2] = {t.affine_rot_err_rad, t.spanning_rot_err_rad};
  for (std::size_t r = 0; r < relations_.size(); ++r) {
    Relation& relation = relations_[r];
    relation.rot_err_deg.add(rotation[r] * kDegreesPerRadian);
    if (rotation[r] > bound_rad_) ++relation.exceeds_bound;
    if (rotation[r] > relation.own_bound_rad) ++relation.exceeds_own_bound;
  }
}

BoundCheck BoundCheckAccumulator::result() const {
  BoundCheck check;
  check.trials = trials_;
  check.vectors = vectors_;
  check.bound_deg = bound_rad_ * kDegreesPerRadian;
  check.pbar_min = pbar_min_;
  check.max_error_deg = max_error_rad_ * kDegreesPerRadian;
  check.max_abs_eq26_mismatch_deg = max_mismatch_rad_ * kDegreesPerRadian;
  check.max_eq26_mismatch_over_tolerance = max_mismatch_ratio_;
  check.max_ratio = bound_rad_ > 0.0 ? max_error_rad_ / bound_rad_ : 0.0;
  const bool bound_holds = check.max_ratio <= 1.0 + kBoundRatioTolerance;
  const bool eq26_holds = max_mismatch_ratio_ <= 1.0;
  check.passed = bound_holds && eq26_holds;
  std::ostringstream why;
  why.precision(9);
  if (!bound_holds) {
    why << "a data vector's error " << check.max_error_deg << " deg (trial " << worst_error_trial_
        << ") exceeds the bound arccos p-bar_min = " << check.bound_deg
        << " deg of Eq. (30) (max_ratio " << check.max_ratio << ")";
  }
  if (!eq26_holds) {
    why << (bound_holds ? "" : "; ") << "a measured error differs from Eq. (26) by "
        << max_mismatch_ratio_ << " times its rounding tolerance (trial " << worst_mismatch_trial_
        << "; largest difference " << check.max_abs_eq26_mismatch_deg << " deg)";
  }
  check.message = why.str();
  for (const Relation& r : relations_) {
    PoseRelation relation;
    relation.estimator = r.estimator;
    relation.free_vectors = r.free_vectors;
    relation.own_bound_deg = r.own_bound_rad * kDegreesPerRadian;
    relation.own_pbar_min = r.own_pbar_min;
    relation.rot_err_deg = r.rot_err_deg.summary();
    relation.exceeds_bound = r.exceeds_bound;
    relation.exceeds_own_bound = r.exceeds_own_bound;
    check.relations.push_back(relation);
  }
  return check;
}

BoundCheck summarize_bound_check(const BoundLayout& layout, const std::vector<BoundTrial>& trials) {
  BoundCheckAccumulator accumulator(layout);
  for (std::size_t k = 0; k < trials.size(); ++k) {
    accumulator.add(static_cast<long>(k), trials[k]);
  }
  return accumulator.result();
}

}  // namespace vantage::simulate
