#pragma once

/// The estimators a simulation runs, as a registry: a name, the scene kinds it applies to and a
/// callable on the scene's correspondences returning R, p and a status. A new estimator is one
/// entry in estimators.cc.
///
/// Every estimate is expressed in the scene's frames (scene.h): R_camera_object and
/// p_camera_object (for two views R_camera2_camera1 and the unit direction of T). Image points
/// are handed to the estimators centred at the principal point.

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "vantage/simulate/scene.h"

namespace vantage::simulate {

/// What one estimator returned on one scene.
struct Estimate {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  bool has_translation = false;  ///< false: no translation estimated (direction data)
  /// Estimated affine scale (object units per image unit), NaN when the method has none.
  double alpha = std::numeric_limits<double>::quiet_NaN();
  std::string status;  ///< the library's to_string() of the result status
  /// The status claims success: kOk and, for a single-image pose, not ambiguous (an ambiguous
  /// pose has status "ambiguous").
  bool ok = true;
};

/// A registered estimator.
struct Estimator {
  std::string name;         ///< command-line name, e.g. "affine"
  std::string description;  ///< one line: the method and its paper
  /// Scene kinds it applies to, and an extra size limit (e.g. Prop. 4's 2^m sign patterns).
  std::function<bool(const Scene&)> applies;
  std::function<Estimate(const Scene&)> solve;
};

/// Every estimator vantage has, in a fixed order:
///  affine           Prop. 8 (affine/pinhole points: all free-vector pairs while there are at
///                   most kMaxAllPairs of them, else the maximum spanning tree) or Lemma 7
///                   (direction data); McInroy et al. "new 2-D"
///  affine-spanning  Prop. 8 on the n - 1 free vectors of the maximum spanning tree
///  affine-refined   Prop. 8 refined on the affine image residual (affine_refined_pose()),
///                   affine images
///  standard         the paper's "standard approach" (Theorem 1 with v_z = 0)
///  full3d           the paper's "full 3-D" baseline on the 3-D sensor's measurements
///  oi-foam, oi-svd  orthogonal iteration (Wu & Wu; Lu et al.), pinhole images
///  perspective      maximum-likelihood pinhole pose (perspective_pose()), pinhole images
///  haralick-2d      Haralick et al. Sec. 2 (2D-2D)
///  haralick-3d      Haralick et al. Sec. 3 (3D-3D, SVD)
///  two-view         Haralick et al. Sec. 4 (simplified linear two-view algorithm)
const std::vector<Estimator>& estimator_registry();

/// Most free vectors the "affine" entry enumerates as all pairs (2^15 sign patterns).
inline constexpr int kMaxAllPairs = 15;
/// Most free vectors any affine entry enumerates (2^16 sign patterns per solve).
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
