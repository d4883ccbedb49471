#include "vantage/simulate/bound_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
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

double elevation(double s) { return std::atan2(s, std::sqrt((1.0 - s) * (1.0 + s))); }

/// A noise-free copy of `scene` for the estimators (the trial's noisy image is not used).
Scene noise_free(const Scene& scene) {
  Scene clean = scene;
  clean.image = scene.image_clean;
  clean.sigma = 0.0;
  return clean;
}

PoseRelation relate(const std::string& estimator, const VectorSetBound& own, double bound_rad,
                    const std::vector<double>& rot_err_rad) {
  PoseRelation r;
  r.estimator = estimator;
  r.free_vectors = own.free_vectors;
  r.own_bound_deg = own.bound_rad * kDegreesPerRadian;
  r.own_pbar_min = own.pbar_min;
  std::vector<double> deg;
  for (double e : rot_err_rad) {
    deg.push_back(e * kDegreesPerRadian);
    if (e > bound_rad) ++r.exceeds_bound;
    if (e > own.bound_rad) ++r.exceeds_own_bound;
  }
  r.rot_err_deg = summarize(deg);
  return r;
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
  const double max_ratio = ratio.maxCoeff();
  VectorErrors out;
  out.p = scene.alpha_true * ratio;
  out.pbar = scene.alpha_true * max_ratio;
  out.angle_rad.resize(m);
  out.eq26_rad.resize(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Vector3d v = scene.R_true * z.col(k) / scene.alpha_true;
    const double r = max_ratio > 0.0 ? ratio(k) / max_ratio : 0.0;
    if (r == 0.0) {  // along the optical axis: v_e is parallel to v, no error
      out.angle_rad(k) = 0.0;
      out.eq26_rad(k) = 0.0;
      continue;
    }
    const double depth = d.col(k).norm() * std::sqrt((1.0 - r) * (1.0 + r)) / r;
    const Eigen::Vector3d v_e(d(0, k), d(1, k), v.z() < 0.0 ? -depth : depth);
    out.angle_rad(k) = std::atan2(v.cross(v_e).norm(), v.dot(v_e));
    out.eq26_rad(k) = elevation(r) - elevation(std::min(1.0, out.p(k)));
  }
  return out;
}

BoundTrial check_bound_trial(const BoundLayout& layout, const Scene& scene) {
  const VectorErrors errors = vector_errors(layout, scene);
  BoundTrial trial;
  trial.pbar = errors.pbar;
  trial.max_error_rad = errors.angle_rad.maxCoeff();
  trial.max_mismatch_rad = (errors.angle_rad - errors.eq26_rad).cwiseAbs().maxCoeff();
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

BoundCheck summarize_bound_check(const BoundLayout& layout, const std::vector<BoundTrial>& trials) {
  BoundCheck check;
  check.trials = static_cast<long>(trials.size());
  check.vectors = layout.data.vectors.cols();
  check.bound_deg = layout.data.bound_rad * kDegreesPerRadian;
  check.pbar_min = layout.data.pbar_min;
  double max_error = 0.0;
  double max_mismatch = 0.0;
  std::vector<double> affine;
  std::vector<double> spanning;
  for (const BoundTrial& t : trials) {
    max_error = std::max(max_error, t.max_error_rad);
    max_mismatch = std::max(max_mismatch, t.max_mismatch_rad);
    affine.push_back(t.affine_rot_err_rad);
    spanning.push_back(t.spanning_rot_err_rad);
  }
  check.max_error_deg = max_error * kDegreesPerRadian;
  check.max_abs_eq26_mismatch_deg = max_mismatch * kDegreesPerRadian;
  check.max_ratio = layout.data.bound_rad > 0.0 ? max_error / layout.data.bound_rad : 0.0;
  check.passed = check.max_ratio <= 1.0 + kBoundRatioTolerance && max_mismatch <= kEq26Tolerance;
  check.relations.push_back(relate("affine", layout.affine, layout.data.bound_rad, affine));
  if (!layout.vectors) {
    check.relations.push_back(
        relate("affine-spanning", layout.spanning, layout.data.bound_rad, spanning));
  }
  return check;
}

}  // namespace vantage::simulate
