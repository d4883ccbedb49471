#include "vantage/simulate/estimators.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/haralick_2d.h"
#include "vantage/analysis/orthogonal_iteration.h"
#include "vantage/analysis/refined_pose.h"
#include "vantage/analysis/two_view.h"

namespace vantage::simulate {
namespace {

bool is_image(const Scene& s) {
  return s.kind == SceneKind::kAffineImage || s.kind == SceneKind::kPinholeImage;
}

Eigen::Index all_pairs(const Scene& s) { return s.model.cols() * (s.model.cols() - 1) / 2; }

Eigen::Matrix2Xd centred_image(const Scene& s) { return s.image.colwise() - s.principal_point; }

/// The free-vector set "affine" uses: all pairs while they are few, else the spanning tree.
FreeVectorSet affine_set(const Scene& s) {
  return all_pairs(s) <= kMaxAllPairs ? FreeVectorSet::kAllPairs : FreeVectorSet::kMaxSpanningTree;
}

bool affine_applies(const Scene& s) {
  if (s.kind == SceneKind::kAffineVectors) return s.model.cols() <= kMaxAffineVectors;
  return is_image(s) && s.model.cols() >= 3 && s.model.cols() - 1 <= kMaxAffineVectors;
}

/// The camera the estimators see: the scene's focal length, image points centred at c.
Camera centred_camera(const Scene& s) {
  Camera camera;
  camera.focal_length = s.focal;
  return camera;
}

/// A single-image pose estimate: ok when the status is kOk and the result is not ambiguous
/// ("ambiguous" is reported as the status, as AffineStatus::kAmbiguous was).
Estimate from_pose_estimate(const PoseEstimate& pose) {
  Estimate e;
  e.R = pose.R_camera_object;
  e.p = pose.p_camera_object;
  e.has_translation = std::isfinite(pose.p_camera_object.z());
  e.status = pose.ambiguous ? "ambiguous" : to_string(pose.status);
  e.ok = pose.status == PoseStatus::kOk && !pose.ambiguous;
  return e;
}

Estimate from_affine(const AffinePoseResult& pose) {
  Estimate e = from_pose_estimate(pose);
  e.has_translation = pose.depth_known;
  e.alpha = pose.alpha;
  return e;
}

Estimate affine_points(const Scene& s, FreeVectorSet set) {
  AffinePoseOptions options;
  options.free_vectors = set;
  options.camera = centred_camera(s);
  return from_affine(affine_pose(s.model, centred_image(s), {}, options));
}

Estimate solve_affine(const Scene& s) {
  if (s.kind != SceneKind::kAffineVectors) return affine_points(s, affine_set(s));
  const AffineOrientationResult o = affine_orientation_unknown_scale(s.model, s.image);
  Estimate e;
  e.R = o.R_camera_object;
  e.alpha = o.alpha;
  e.status = to_string(o.status);
  e.ok = o.status == AffineStatus::kOk;
  return e;
}

Estimate solve_standard(const Scene& s) {
  if (s.kind != SceneKind::kAffineVectors) {
    AffinePoseOptions options;
    options.free_vectors = FreeVectorSet::kAllPairs;
    options.camera = centred_camera(s);
    return from_affine(standard_affine_pose(s.model, centred_image(s), {}, options));
  }
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, s.image.cols());
  v.topRows<2>() = s.image;
  const OrientationResult o = absolute_orientation(s.model, v);
  Estimate e;
  e.R = o.R_camera_object;
  e.alpha = o.alpha;  // Eq. (4): alpha v ~= R z, the affine scale of Eq. (15)
  e.status = to_string(o.status);
  e.ok = o.status == OrientationStatus::kOk;
  return e;
}

/// A 3-D pose result (PoseResult): ok when status == OrientationStatus::kOk.
Estimate from_pose(const PoseResult& pose) {
  Estimate e;
  e.R = pose.R_camera_object;
  e.p = pose.p_camera_object;
  e.has_translation = true;
  e.status = to_string(pose.status);
  e.ok = pose.status == OrientationStatus::kOk;
  return e;
}

Estimate solve_full3d(const Scene& s) {
  AffinePoseOptions options;
  options.free_vectors = FreeVectorSet::kAllPairs;
  return from_pose(full_3d_pose(s.model, s.measured, {}, options));
}

Estimate solve_oi(const Scene& s, OrientationMethod step) {
  OrthogonalIterationOptions options;
  options.rotation_step = step;
  options.camera = centred_camera(s);
  return from_pose_estimate(orthogonal_iteration_pose(s.model, centred_image(s), {}, options));
}

/// affine_refined_pose() or perspective_pose() from Prop. 8's start (library defaults).
Estimate solve_refined(const Scene& s, bool perspective) {
  RefinedPoseOptions options;
  options.camera = centred_camera(s);
  const RefinedPoseResult pose = perspective
                                     ? perspective_pose(s.model, centred_image(s), {}, options)
                                     : affine_refined_pose(s.model, centred_image(s), {}, options);
  Estimate e = from_pose_estimate(pose);
  e.alpha = pose.alpha;
  return e;
}

Estimate solve_haralick_2d(const Scene& s) {
  const Pose2dResult pose = pose_2d(s.model.topRows<2>(), s.image);
  Estimate e;
  e.R.topLeftCorner<2, 2>() = pose.R_to_from;
  e.p.head<2>() = pose.t_to_from;
  e.has_translation = true;
  e.status = to_string(pose.status);
  e.ok = pose.status == Pose2dStatus::kOk;
  return e;
}

Estimate solve_haralick_3d(const Scene& s) {
  OrientationOptions options;
  options.method = OrientationMethod::kSvd;
  return from_pose(absolute_pose(s.model, s.measured, {}, options));
}

Estimate solve_two_view(const Scene& s) {
  const TwoViewResult pose = two_view_pose(s.first_view, s.image);
  Estimate e;
  e.R = pose.R_camera2_camera1;
  e.p = pose.t_camera2_camera1;
  e.has_translation = true;
  e.status = to_string(pose.status);
  e.ok = pose.status == TwoViewStatus::kOk;
  return e;
}

std::vector<Estimator> make_registry() {
  const auto image_points = [](const Scene& s) { return is_image(s) && s.model.cols() >= 3; };
  return {
      {"affine",
       "Prop. 8 / Lemma 7 (McInroy et al. 'new 2-D'): free vectors, LUB scale, 2^m sign patterns",
       affine_applies, solve_affine},
      {"affine-spanning", "Prop. 8 on the n - 1 free vectors of the maximum spanning tree",
       [](const Scene& s) {
         return is_image(s) && s.model.cols() >= 3 && s.model.cols() - 1 <= kMaxAffineVectors;
       },
       [](const Scene& s) { return affine_points(s, FreeVectorSet::kMaxSpanningTree); }},
      {"affine-refined",
       "Prop. 8 refined by Levenberg-Marquardt on the affine image residual (affine cameras)",
       [](const Scene& s) { return s.kind == SceneKind::kAffineImage && s.model.cols() >= 3; },
       [](const Scene& s) { return solve_refined(s, false); }},
      {"standard", "the paper's standard approach: Theorem 1 with v_z = 0",
       [image_points](const Scene& s) {
         return s.kind == SceneKind::kAffineVectors || image_points(s);
       },
       solve_standard},
      {"full3d", "the paper's full 3-D baseline: Theorem 1 + Eq. 13 on 3-D measurements",
       image_points, solve_full3d},
      {"oi-foam", "orthogonal iteration with the FOAM step (Wu & Wu)",
       [](const Scene& s) { return s.kind == SceneKind::kPinholeImage && s.model.cols() >= 3; },
       [](const Scene& s) { return solve_oi(s, OrientationMethod::kFoam); }},
      {"oi-svd", "orthogonal iteration with the SVD step (Lu et al.)",
       [](const Scene& s) { return s.kind == SceneKind::kPinholeImage && s.model.cols() >= 3; },
       [](const Scene& s) { return solve_oi(s, OrientationMethod::kSvd); }},
      {"perspective",
       "maximum-likelihood pinhole pose: Levenberg-Marquardt from Prop. 8 (pinhole images)",
       [](const Scene& s) { return s.kind == SceneKind::kPinholeImage && s.model.cols() >= 3; },
       [](const Scene& s) { return solve_refined(s, true); }},
      {"haralick-2d", "Haralick et al. Sec. 2: closed-form 2D-2D rigid pose",
       [](const Scene& s) { return s.kind == SceneKind::kPlanar2d; }, solve_haralick_2d},
      {"haralick-3d", "Haralick et al. Sec. 3: 3D-3D pose by the SVD",
       [](const Scene& s) { return s.kind == SceneKind::kPoints3d; }, solve_haralick_3d},
      {"two-view", "Haralick et al. Sec. 4: simplified linear two-view algorithm",
       [](const Scene& s) { return s.kind == SceneKind::kTwoView && s.image.cols() >= 8; },
       solve_two_view},
  };
}

}  // namespace

const std::vector<Estimator>& estimator_registry() {
  static const std::vector<Estimator> registry = make_registry();
  return registry;
}

const Estimator* find_estimator(const std::string& name) {
  for (const Estimator& e : estimator_registry()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::string estimator_names() {
  std::string names;
  for (const Estimator& e : estimator_registry()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

std::vector<Estimator> select_estimators(const std::vector<std::string>& names, const Scene& scene,
                                         const std::string& argument) {
  for (const std::string& name : names) {
    const Estimator* e = find_estimator(name);
    if (!e) {
      throw InvalidArgument(argument + ": unknown estimator '" + name +
                            "' (known: " + estimator_names() + ")");
    }
    if (!e->applies(scene)) {
      throw InvalidArgument(argument + ": estimator '" + name + "' does not apply to a " +
                            to_string(scene.kind) + " scene of " +
                            std::to_string(scene.model.cols()) + " entries");
    }
  }
  std::vector<Estimator> selected;
  for (const Estimator& e : estimator_registry()) {
    const bool named = std::find(names.begin(), names.end(), e.name) != names.end();
    if ((names.empty() && e.applies(scene)) || named) selected.push_back(e);
  }
  return selected;
}

}  // namespace vantage::simulate
