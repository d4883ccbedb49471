#include "vantage/simulate/estimators.h"

#include <algorithm>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/affine_pose.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/haralick_2d.h"
#include "vantage/analysis/orthogonal_iteration.h"
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

Estimate from_affine(const AffinePoseResult& pose) {
  Estimate e;
  e.R = pose.R_camera_object;
  e.p = pose.p_camera_object;
  e.has_translation = pose.depth_known;
  e.alpha = pose.alpha;
  e.status = to_string(pose.status);
  e.ok = pose.status == AffineStatus::kOk;
  return e;
}

Estimate affine_points(const Scene& s, FreeVectorSet set) {
  AffinePoseOptions options;
  options.free_vectors = set;
  options.focal_length = s.focal;
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
    options.focal_length = s.focal;
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

/// A pose result with R_camera_object, p_camera_object and a status; ok when status == ok.
template <typename Result, typename Status>
Estimate from_pose(const Result& pose, Status ok) {
  Estimate e;
  e.R = pose.R_camera_object;
  e.p = pose.p_camera_object;
  e.has_translation = true;
  e.status = to_string(pose.status);
  e.ok = pose.status == ok;
  return e;
}

Estimate solve_full3d(const Scene& s) {
  return from_pose(full_3d_pose(s.model, s.measured), OrientationStatus::kOk);
}

Estimate solve_oi(const Scene& s, OrientationMethod step) {
  OrthogonalIterationOptions options;
  options.rotation_step = step;
  options.focal_length = s.focal;
  return from_pose(orthogonal_iteration_pose(s.model, centred_image(s), {}, options),
                   OrthogonalIterationStatus::kConverged);
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
  return from_pose(absolute_pose(s.model, s.measured, {}, options), OrientationStatus::kOk);
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
