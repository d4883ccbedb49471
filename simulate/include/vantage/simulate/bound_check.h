#pragma once

/// The paper's promise, checked trial by trial (McInroy et al. Sec. III.C-D; docs/math.md,
/// "worst-case error at a viewpoint").
///
/// On a noise-free affine image, the least-upper-bound scale alpha_e (Eq. 23) reconstructs each
/// data vector as v_e_i = [d_i; s_i sqrt(|z_i|^2 / alpha_e^2 - |d_i|^2)] (Eq. 22, s_i the sign
/// of the true depth component). The angle between v_e_i and the true camera-frame vector
/// v_i = R z_i / alpha must equal Eq. (26) at that trial's p_i = alpha |d_i| / |z_i| (Eq. 19) and
/// p_bar = max_i p_i (Eq. 24), and can never exceed arccos p_bar_min, the largest per-vector error
/// over all viewpoints (Eq. 30's maximum; p_bar_min from the certified global worst viewpoint,
/// Theorem 6).
///
/// Numerics. Eq. (26) is the angle between the unit vectors (p, sqrt(1 - p^2)) and
/// (p / p_bar, sqrt(1 - p^2 / p_bar^2)) (in-plane and depth parts of v_i / |v_i| and
/// v_e_i / |v_e_i|, which share the direction of d_i), i.e. the difference of their elevation
/// angles, evaluated here as atan2(r, sqrt((1 - r)(1 + r))) - atan2(p, sqrt((1 - p)(1 + p))) with
/// r = p / p_bar. The acos form of analysis/error_bounds.h loses about 1e-8 rad near p = p_bar
/// (acos near 1); this form keeps the comparison at rounding level. The depth of v_e_i is
/// computed from the same ratio, |d_i| sqrt((1 - r)(1 + r)) / r, which is exactly 0 for the
/// limiting vector (Eq. 23 puts it in the image plane).
///
/// The affine estimator's rotation error is a different quantity (the paper bounds per-vector
/// errors, not the pose): it is measured against the same bound and against the bound of the
/// free vectors the estimator actually used, as a relation, not a promise.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "vantage/simulate/scene.h"
#include "vantage/simulate/statistics.h"

namespace vantage::simulate {

/// Ratio max_error / bound tolerated by the check (rounding of the angles).
inline constexpr double kBoundRatioTolerance = 1e-9;
/// |measured - Eq. 26| tolerated by the check, radians.
inline constexpr double kEq26Tolerance = 1e-9;

/// The worst case of a set of data vectors: certified p_bar_min and the bound arccos p_bar_min.
struct VectorSetBound {
  std::string free_vectors;  ///< "vectors", "all_pairs" or "max_spanning_tree"
  Eigen::Matrix3Xd vectors;  ///< the data vectors, 3 x m
  Eigen::Matrix2Xi pairs;    ///< point mode: markers (i, j) of each free vector z_i - z_j
  Eigen::Vector3d worst_viewpoint = Eigen::Vector3d::UnitZ();
  double t_lower = 0.0;   ///< attained min_i |a.n_i| at worst_viewpoint
  double t_upper = 0.0;   ///< certified upper bound of t* (Theorem 6, global)
  double pbar_min = 1.0;  ///< sqrt(1 - t_lower^2)
  /// asin(t_upper) >= arccos p_bar_min: the certified largest per-vector error, radians.
  double bound_rad = 0.0;
};

/// A layout prepared for the check: its data vectors as `vantage analyze` defines them (all
/// pairs in point mode) and, in point mode, the maximum spanning tree's n - 1 free vectors.
struct BoundLayout {
  Eigen::Matrix3Xd entries;
  bool vectors = false;
  VectorSetBound data;      ///< every data vector
  VectorSetBound spanning;  ///< point mode only (free_vectors empty in direction mode)
  /// The set the registry's "affine" estimator uses on this layout: all pairs up to
  /// kAutoAllPairsLimit free vectors, else the kAuto set of the object points (the estimator
  /// may swap its last pair for the image's LUB pair, free_vectors.h); the data vectors in
  /// direction mode.
  VectorSetBound affine;
};

/// Prepares a layout: entries 3 x n (points, n >= 3, or vectors, n >= 2). Runs the certified
/// global worst viewpoint on each vector set. Throws InvalidArgument on bad entries and
/// InternalError when the worst viewpoint cannot be certified.
BoundLayout prepare_bound_layout(const Eigen::Matrix3Xd& entries, bool vectors);

/// One trial of the check.
struct BoundTrial {
  double pbar = 0.0;              ///< p_bar(a) at this trial's viewpoint (Eq. 24)
  double max_error_rad = 0.0;     ///< largest measured angle(v_i, v_e_i) over the data vectors
  double max_mismatch_rad = 0.0;  ///< largest |angle(v_i, v_e_i) - Eq. 26|
  /// "affine" estimator on the noise-free image (NaN when it does not apply, e.g. more than
  /// kMaxAffineVectors + 1 markers)
  double affine_rot_err_rad = 0.0;
  double spanning_rot_err_rad = 0.0;  ///< "affine-spanning" (NaN in direction mode, or as above)
};

/// The check on the noise-free image of `scene` (an affine layout scene of layout.entries:
/// kAffineImage or kAffineVectors). Throws InvalidArgument for another scene kind.
BoundTrial check_bound_trial(const BoundLayout& layout, const Scene& scene);

/// The measured angles of every data vector and their Eq. (26) values on one scene, for figures.
struct VectorErrors {
  Eigen::VectorXd p;          ///< p_i (Eq. 19)
  Eigen::VectorXd angle_rad;  ///< measured angle(v_i, v_e_i)
  Eigen::VectorXd eq26_rad;   ///< Eq. (26) at (p_i, p_bar)
  double pbar = 0.0;
};
VectorErrors vector_errors(const BoundLayout& layout, const Scene& scene);

/// The affine estimator's rotation error over the trials against a bound (a measured relation).
struct PoseRelation {
  std::string estimator;       ///< "affine" or "affine-spanning"
  std::string free_vectors;    ///< the free vectors it used
  double own_bound_deg = 0.0;  ///< arccos p_bar_min of those free vectors
  double own_pbar_min = 1.0;
  Summary rot_err_deg;         ///< over the trials
  long exceeds_bound = 0;      ///< trials with rot_err > bound_deg (all data vectors)
  long exceeds_own_bound = 0;  ///< trials with rot_err > own_bound_deg
};

/// Summary of the check over the trials (`vantage simulate --json` "bound_check").
struct BoundCheck {
  long trials = 0;
  long vectors = 0;  ///< data vectors per trial
  double max_abs_eq26_mismatch_deg = 0.0;
  double max_error_deg = 0.0;
  double bound_deg = 0.0;  ///< asin(t_upper) of all data vectors
  double pbar_min = 1.0;
  double max_ratio = 0.0;  ///< max_error_deg / bound_deg
  bool passed = false;     ///< max_ratio <= 1 + kBoundRatioTolerance and mismatch <= kEq26Tolerance
  std::vector<PoseRelation> relations;  ///< "affine" (and "affine-spanning" in point mode)
};

BoundCheck summarize_bound_check(const BoundLayout& layout, const std::vector<BoundTrial>& trials);

}  // namespace vantage::simulate
