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
/// Numerics. Eq. (26) is evaluated by lub_scale_error_angle() (analysis/error_bounds.h), in a
/// form that does not cancel (docs/math.md, "Eq. (26) without cancellation"); the measured angle
/// is atan2(|v x v_e|, v.v_e). The depth of v_e_i is computed from the ratio r = p / p_bar as
/// |d_i| sqrt((1 - r)(1 + r)) / r, which is exactly 0 for the limiting vector (Eq. 23 puts it in
/// the image plane). Both angles are correct to rounding, but their inputs are not exact: p_i
/// and r_i are ratios of norms of rounded image and object vectors (relative rounding u, larger
/// in point mode where d_i = q_b - q_a and z_i = x_b - x_a cancel), and an elevation asin(x)
/// moves by u x / sqrt(1 - x^2) under such a change, up to sqrt(2 u) at x = 1. Each vector's
/// tolerance is that conditioning (input_rounding in bound_check.cc), not one fixed number: a
/// vector in or near the image plane (p or r within 1e-14 of 1) legitimately differs by ~1e-8
/// rad, while elsewhere the two agree to ~1e-15.
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
/// Relative rounding of p_i = alpha |d_i| / |z_i| in units of the double epsilon, before the
/// cancellation of point-mode differences: the image point (a rotation, a scale, a shift) and two
/// norms and a division, a rounding or two each.
inline constexpr double kEq26InputUlps = 8.0;
/// Rounding of the two angle evaluations themselves, in epsilons per radian (plus one).
inline constexpr double kEq26AngleUlps = 64.0;
/// Safety factor on the first-order sensitivities of the tolerance. Measured (issue 17, 30
/// random 8-marker layouts x 20000 views): the largest |measured - Eq. 26| is 0.03 of its
/// tolerance, so the factor does not hide a real mismatch of the size the old fixed bound saw.
inline constexpr double kEq26ConditioningMargin = 2.0;

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
  /// largest |angle(v_i, v_e_i) - Eq. 26| / tolerance_rad_i over the data vectors (<= 1: agree)
  double max_mismatch_ratio = 0.0;
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
  /// |measured - Eq. 26| the rounding of the inputs allows for each vector (file comment)
  Eigen::VectorXd tolerance_rad;
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
  /// Largest BoundTrial::max_mismatch_ratio: <= 1 when every measured angle is Eq. (26) to the
  /// rounding of its inputs.
  double max_eq26_mismatch_over_tolerance = 0.0;
  /// max_ratio <= 1 + kBoundRatioTolerance and max_eq26_mismatch_over_tolerance <= 1.
  bool passed = false;
  /// Empty when passed; otherwise which promise failed, with the numbers and the trial.
  std::string message;
  std::vector<PoseRelation> relations;  ///< "affine" (and "affine-spanning" in point mode)
};

/// The bound check folded one trial at a time (in trial order), in memory that does not grow
/// with the trials.
class BoundCheckAccumulator {
 public:
  explicit BoundCheckAccumulator(const BoundLayout& layout);
  /// Adds trial number `trial` (named in BoundCheck::message when it is the worst).
  void add(long trial, const BoundTrial& result);
  BoundCheck result() const;

 private:
  struct Relation {
    std::string estimator;
    std::string free_vectors;
    double own_bound_rad = 0.0;
    double own_pbar_min = 1.0;
    SummaryAccumulator rot_err_deg;
    long exceeds_bound = 0;
    long exceeds_own_bound = 0;
  };
  double bound_rad_;
  long vectors_;
  double pbar_min_;
  bool point_mode_;
  long trials_ = 0;
  double max_error_rad_ = 0.0;
  double max_mismatch_rad_ = 0.0;
  double max_mismatch_ratio_ = 0.0;
  long worst_error_trial_ = 0;
  long worst_mismatch_trial_ = 0;
  std::vector<Relation> relations_;
};

/// The accumulator over `trials` (trial k = trials[k]).
BoundCheck summarize_bound_check(const BoundLayout& layout, const std::vector<BoundTrial>& trials);

}  // namespace vantage::simulate
