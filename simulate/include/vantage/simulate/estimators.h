#pragma once

/// The estimators a simulation runs, as a registry over the one pose vocabulary: each entry is
/// a PoseMethod (pose_method.h) run through estimate_pose() on the scene's correspondences, so
/// `vantage simulate` runs exactly what `vantage pose` runs. A new estimator is one entry in
/// estimators.cc.
///
/// Every estimate is expressed in the scene's frames (scene.h): R_camera_object and
/// p_camera_object (for two views R_camera2_camera1 and the unit direction of T). Image points
/// are handed to the estimators centred at the principal point.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "vantage/analysis/estimate_pose.h"
#include "vantage/analysis/pose_estimate.h"
#include "vantage/analysis/pose_method.h"
#include "vantage/simulate/scene.h"

namespace vantage::simulate {

/// A registered estimator: a pose method of the one vocabulary (pose_method.h) with its
/// free-vector set, the scene kinds it applies to, and its run on a scene through
/// estimate_pose().
struct Estimator {
  std::string name;         ///< the method's name, e.g. "affine" (or "affine-spanning")
  std::string description;  ///< one line: the method and its paper
  PoseMethod method = PoseMethod::kAffine;
  FreeVectorSet free_vectors = FreeVectorSet::kAuto;
  /// Scene kinds it applies to, and an extra size limit (e.g. Prop. 4's 2^m sign patterns).
  std::function<bool(const Scene&)> applies;

  /// estimate_pose() on the scene's correspondences (image points centred at the principal
  /// point, the scene's focal length).
  PoseEstimate solve(const Scene& scene) const;
};

/// The correspondences estimate_pose() sees for a scene.
Correspondences scene_correspondences(const Scene& scene);

/// Every estimator vantage has, in a fixed order: the pose methods (pose_method.h) that apply to
/// simulated scenes, with the free vectors of the one kAuto policy (free_vectors.h), and
///  affine-spanning  affine on the n - 1 free vectors of the maximum spanning tree
/// (`vantage pose --method affine --free-vectors spanning`).
const std::vector<Estimator>& estimator_registry();

/// Most free vectors an explicit affine set enumerates here (2^16 sign patterns per solve).
inline constexpr int kMaxAffineVectors = 16;

/// The registry entry of that name, or nullptr.
const Estimator* find_estimator(const std::string& name);

/// The registered names joined by ", " (for error messages and --help).
std::string estimator_names();

/// The entries of `names` (all applicable ones when empty) that apply to `scene`, in registry
/// order. Throws InvalidArgument naming `argument` for an unknown name or a named estimator
/// that does not apply to the scene.
std::vector<Estimator> select_estimators(const std::vector<std::string>& names, const Scene& scene,
                                         const std::string& argument);

}  // namespace vantage::simulate
