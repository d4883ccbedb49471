#pragma once

/// Pose from a single affine image (McInroy et al., Sec. III): Prop. 4 (orientation with known
/// scale, 2^n sign patterns in Gray-code order), the least-upper-bound scale (Eqs. 19, 23-25),
/// Lemma 7 (orientation with unknown scale), Prop. 8 (full pose from image points through free
/// vectors), the two baselines the paper compares with ("standard approach" and "full 3-D"), and
/// a direct NLopt minimisation of J_2d that cross-checks Prop. 4.
///
/// Frames and scale (Eq. 14): x_camera = R_camera_object * x_object + p_camera_object, the camera
/// looks along +z and P = [I_2 0] drops the depth. Image measurements relate to the object by
///   alpha * d_i ~= P R z_i              (free vectors, Eqs. 15, 34)
///   alpha * q_i ~= P (R z_i + p)        (points, Eq. 35)
/// so alpha > 0 converts image units into object units (alpha = depth / focal length, Eq. 37).
/// With known alpha the missing component of each measured vector is (Eq. 21)
///   v_zi = +-sqrt(|z_i|^2 / alpha^2 - |d_i|^2),  so that alpha [d_i; v_zi] = R z_i exactly
/// on noise-free data. When noise makes |d_i| > |z_i| / alpha, v_zi is set to 0 and the vector
/// is counted as clamped (docs/math.md §8); such a vector, like one lying in the image plane,
/// has a single sign and is not enumerated.
///
/// Vector sets: Eigen::Matrix3Xd (object) and Eigen::Matrix2Xd (image), one column per vector or
/// point. Weights: Eigen::VectorXd with one positive entry per column; empty means all 1.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <string>

#include "vantage/analysis/absolute_orientation.h"
#include "vantage/analysis/camera.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/analysis/pose_estimate.h"
#include "vantage/analysis/quaternion.h"

namespace vantage {

/// Default of AffineOrientationOptions::max_vectors: 2^24 = 16.8 M patterns, about a second.
inline constexpr int kDefaultMaxAffineVectors = 24;
/// Hard ceiling of AffineOrientationOptions::max_vectors (2^30 patterns: minutes of work).
inline constexpr int kMaxAffineVectorsCeiling = 30;

/// How Prop. 4 visits and solves the sign patterns. All three return the same winner.
///
/// Bilinearity of K makes D (Eq. 2) a linear function of H = sum w_i z_i v_i^T, and only the
/// third column h = sum w_i v_zi z_i of H depends on the signs. Toggling v_zj therefore changes
/// h by -2 w_j v_zj z_j and D by Eq. (17) with the factor of docs/math.md §9,
/// Delta D = -2 w_j v_zj K(e_z, z_j), v_zj the value before the toggle.
enum class SignEnumeration {
  /// Gray code (one sign per step, both updates above), then per pattern: the largest root
  /// lambda of D's characteristic quartic (Laguerre from an upper bound; its coefficients need
  /// only |H|_F, det H and |adj H|_F, each O(1) in h), the viewpoint r3 (third row of R) from
  /// FOAM's closed form (docs/math.md §5), and J_2d = tr S - r3^T S r3 - 2 (lambda - r3^T h)
  /// + sum w |alpha d|^2 with S = sum w z z^T. The root finder starts from the previous
  /// pattern's root + |Delta h| (an upper bound) and takes one Laguerre and one Halley step
  /// (more only for the rare pattern not yet converged to ~1e-12 relative); the top four sign
  /// bits are fixed per lane so each Gray-code step solves 16 independent patterns, in lockstep
  /// on Eigen arrays (SIMD, no per-lane branches). About 100 flops, one square root, two
  /// divisions and no allocation per pattern; the winner and runner-up are re-solved exactly by
  /// Theorem 1 at the end; when lambda is nearly double (FOAM's zeta ~ 0) or J_2d is not finite
  /// the pattern falls back to top_eigenpair(D).
  kGrayCode,
  /// Gray code with the Eq. (17) update of D, top_eigenpair() (fast path) for the quaternion,
  /// R from Eq. (5) and J_2d from moments: the paper's procedure, O(1) and allocation-free.
  kGrayCodeEigen,
  /// Reference: binary counting, D recomputed from all n vectors, Eigen's full
  /// SelfAdjointEigenSolver and J_2d summed over all n vectors, O(n) per pattern.
  kNaive,
};

/// "gray_code", "gray_code_eigen" or "naive".
const char* to_string(SignEnumeration enumeration);

/// Options of affine_orientation() and affine_orientation_unknown_scale().
struct AffineOrientationOptions {
  SignEnumeration enumeration = SignEnumeration::kGrayCode;
  /// Eigen-solver tuning of kGrayCodeEigen and of kGrayCode's fallback; fallback_relative_gap
  /// also sets kGrayCode's threshold zeta <= fallback_relative_gap * lambda^3.
  TopEigenOptions eigen;
  /// Input with more vectors than this throws InvalidArgument instead of running 2^n solves.
  /// In [1, kMaxAffineVectorsCeiling].
  int max_vectors = kDefaultMaxAffineVectors;
  /// A vector with |z_i|^2 - alpha^2 |d_i|^2 <= in_plane_tolerance * |z_i|^2 is taken to lie in
  /// the image plane: v_zi = 0 and it is not enumerated (the LUB vector of Lemma 7 is one).
  /// Dimensionless, in [0, 1).
  double in_plane_tolerance = 1e-12;
  /// Relative margin of the ambiguity test (see AffineOrientationResult::ambiguous),
  /// dimensionless, >= 0.
  double ambiguity_tolerance = 1e-9;
  /// Rotations closer than this are the same answer for the ambiguity test and the runner-up.
  /// Radians, >= 0. A vector near the image plane (small |v_zi| / |z_i|) makes its two sign
  /// patterns near-copies, their rotations apart by about that ratio (0.11 deg for the bundled
  /// examples/correspondences/affine_pose.json): not an ambiguity. A mirror pose is about twice
  /// the tilt away, so 1 deg separates the two for any tilt worth calling a view.
  double distinct_rotation_angle = kPi / 180.0;
  /// Relative eigen gap of the winning D at or below which the status is
  /// PoseStatus::kDegenerate, as in OrientationOptions::degenerate_gap. Dimensionless, in [0, 1).
  double degenerate_gap = 1e-10;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Result of Prop. 4 / Lemma 7.
struct AffineOrientationResult {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();  ///< winner, re-solved exactly
  double alpha = 1.0;     ///< scale used: given (Prop. 4) or the LUB estimate (Lemma 7, Eq. 23)
  double residual = 0.0;  ///< J_2d of the winner: sum w_i |P R z_i - alpha d_i|^2 (Eq. 15)
  /// J_2d of the runner-up: the best pattern (among the 64 best) whose rotation is more than
  /// distinct_rotation_angle from the winner's — flipping a near-zero v_z only gives a near-copy
  /// of the winner, which is not the two-fold ambiguity; the second best when all 64 are
  /// near-copies. +infinity when only one pattern exists.
  double runner_up_residual = 0.0;
  double ambiguity_margin = 0.0;  ///< runner_up_residual - residual (>= 0; may be +infinity)
  /// Rotation of the runner-up pattern (identity when only one pattern exists).
  Eigen::Matrix3d runner_up_R_camera_object = Eigen::Matrix3d::Identity();
  /// Angle between the winner's and the runner-up's rotations, radians (0 with one pattern).
  double runner_up_angle = 0.0;
  /// Missing components of the winner, image units: alpha [d_i; v_z(i)] ~= R z_i (Eq. 21).
  Eigen::VectorXd v_z;
  std::uint64_t sign_patterns = 0;  ///< patterns solved: 2^m, m = vectors with two signs
  int clamped = 0;                  ///< vectors with |d_i| > |z_i| / alpha (v_zi set to 0)
  int in_plane = 0;                 ///< vectors within in_plane_tolerance of the image plane
  /// Patterns whose fast solve was not trusted: kGrayCode patterns sent to top_eigenpair(),
  /// plus top_eigenpair() calls that used the full eigensolver.
  std::uint64_t eigen_fallbacks = 0;
  double eigen_gap = 0.0;  ///< lambda_1 - lambda_2 of the winner's D
  /// kOk, or kDegenerate: the winner's Theorem-1 problem is degenerate (relative eigen gap of D
  /// <= degenerate_gap, e.g. all vectors parallel), so the data do not determine R.
  PoseStatus status = PoseStatus::kOk;
  /// The runner-up fits as well as the winner, runner_up_residual - residual <=
  /// ambiguity_tolerance * sum w_i |z_i|^2, with a rotation more than distinct_rotation_angle
  /// away: the data cannot tell two poses apart (e.g. the two-fold "Necker" reversal of
  /// coplanar vectors, docs/math.md §15). R is one of them; runner_up_R_camera_object the other.
  bool ambiguous = false;
  std::string message;  ///< empty when status is kOk and not ambiguous
};

/// Prop. 4: minimises J_2d = sum w_i |P R z_i - alpha d_i|^2 (Eq. 15 with the scale of Eq. 14)
/// over R in SO(3) for known alpha > 0, by solving Theorem 1 for every sign choice of the
/// missing components v_zi (Eq. 21) and keeping the rotation of least J_2d.
///
/// All 2^m patterns are solved (m = vectors with v_zi > 0). Negating every v_z is NOT a
/// symmetry in general: it fits R z_i with the reflection diag(1, 1, -1) R, so its Theorem-1
/// rotation is a different (usually poor) answer. Only for coplanar z_i does it give the mirror
/// pose R' = diag(1, 1, -1) R (I - 2 n n^T) (n the plane normal) with the same J_2d, which is
/// exactly the two-fold ambiguity reported as `ambiguous`; so 2^(m-1) patterns would lose it.
///
/// z_object: 3 x n, n >= 2, finite, non-zero columns; d_image: 2 x n, finite; weights: n positive
/// entries or empty; n <= options.max_vectors. Gray-code per-pattern work allocates nothing.
/// Throws InvalidArgument naming the argument on bad input.
AffineOrientationResult affine_orientation(const Eigen::Matrix3Xd& z_object,
                                           const Eigen::Matrix2Xd& d_image, double alpha,
                                           const Eigen::VectorXd& weights = {},
                                           const AffineOrientationOptions& options = {});

/// Lemma 7: orientation with unknown scale, alpha estimated by the least upper bound (Eq. 23),
/// then Prop. 4. Exact on noise-free data when some vector lies in the image plane; otherwise
/// the scale error beta = 1 / p_bar (Eq. 25) causes the angular errors of Eq. (26).
/// Same preconditions as affine_orientation(); d_image must not be all zero.
AffineOrientationResult affine_orientation_unknown_scale(
    const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image,
    const Eigen::VectorXd& weights = {}, const AffineOrientationOptions& options = {});

/// Least-upper-bound scale, Eq. (23): alpha_e = 1 / max_i (|d_i| / |z_i|).
struct LubScale {
  double alpha = 1.0;         ///< alpha_e
  Eigen::Index limiting = 0;  ///< index i attaining the maximum ratio
  double max_ratio = 0.0;     ///< max_i |d_i| / |z_i| (image units per object unit)
};

/// Eq. (23). z_object 3 x n and d_image 2 x n, n >= 1, finite, non-zero z columns, some d_i != 0.
LubScale lub_scale(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image);

/// Fractions of each vector's norm that survive the projection, for a given (true) scale.
struct ProjectionFractions {
  Eigen::VectorXd p;   ///< p_i = alpha |d_i| / |z_i|, Eq. (19); <= 1 on noise-free data
  double p_bar = 0.0;  ///< max_i p_i, Eq. (24)
  double beta = 1.0;   ///< alpha_e / alpha = 1 / p_bar, the LUB scale error, Eq. (25)
};

/// Eqs. (19), (24), (25) for the true scale alpha > 0. Same preconditions as lub_scale().
ProjectionFractions projection_fractions(const Eigen::Matrix3Xd& z_object,
                                         const Eigen::Matrix2Xd& d_image, double alpha);

/// Options of affine_pose(), standard_affine_pose() and full_3d_pose().
struct AffinePoseOptions {
  AffineOrientationOptions orientation;
  /// kAuto never throws for the number of points; an explicit kAllPairs set larger than
  /// orientation.max_vectors throws InvalidArgument.
  FreeVectorSet free_vectors = FreeVectorSet::kAuto;
  PairWeighting pair_weighting = PairWeighting::kGeometricMean;
  /// Pixels: image = c + (1 / alpha) P (R z + p). Without a focal length p_z is NaN; with one,
  /// p_z = alpha f (Eq. 37).
  Camera camera;

  bool is_valid(std::string* why = nullptr) const;
};

/// Free vectors of Prop. 8 built from image points (d = image differences).
using FreeVectors = FreeVectorsOf<2>;

/// The free vectors and weights Prop. 8 uses for these points. Sizes as in affine_pose().
FreeVectors affine_free_vectors(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                                const Eigen::VectorXd& weights, const AffinePoseOptions& options);

/// Result of Prop. 8 and of the 2-D standard approach. PoseEstimate's fields:
///  - status: kDegenerate when Prop. 4's winner is (orientation.status), else kOk;
///  - ambiguous: Prop. 4's runner-up fits as well (orientation.ambiguous: for coplanar points
///    the Necker pair, which the affine model cannot tell apart); alternative: the runner-up
///    rotation with its Eq. (36) translation, whenever Prop. 4 had one;
///  - alpha: the scale, object units per pixel: alpha (q_i - c) ~= P (R z_i + p);
///  - objective: J of Eq. (35) at the estimate, sum w_i |P (R z_i + p) - alpha (q_i - c)|^2
///    (object units^2);
///  - reprojection_rms_px = sqrt(objective / (alpha^2 sum w)): the affine model's image residual.
struct AffinePoseResult : PoseEstimate {
  bool depth_known = false;  ///< true when p_z came from Eq. (37) (a focal length was given)
  /// Prop. 4 / Lemma 7 on the free vectors (sign_patterns, ambiguity_margin, clamped, ...).
  /// For the standard approach: one pattern (v_z = 0), runner-up +infinity.
  AffineOrientationResult orientation;
  Eigen::Matrix2Xi pairs;  ///< the free vectors used, (i, j) per column
};

/// Prop. 8: pose and scale from n >= 3 image points of a known model: free vectors (options),
/// Lemma 7 for R and alpha, p_x, p_y from Eq. (36) with the point weights, p_z from Eq. (37).
/// model_object: 3 x n finite, no two points equal; image: 2 x n finite, pixels; weights: n
/// positive or empty; an explicit free-vector set must not exceed
/// options.orientation.max_vectors. Three points are always coplanar, so n = 3 gives the
/// two-fold ambiguity (ambiguous = true).
AffinePoseResult affine_pose(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix2Xd& image,
                             const Eigen::VectorXd& weights = {},
                             const AffinePoseOptions& options = {});

/// The paper's "standard approach" (Sec. IV): free vectors augmented with v_z = 0, Theorem 1 for
/// R, alpha from Eq. (4), p_x, p_y from Eq. (36) (= the first two rows of Eq. 13), p_z from
/// Eq. (37). Same preconditions as affine_pose() (no limit on the number of vectors; kAuto means
/// all pairs here, since nothing is enumerated).
/// ambiguous is always false (one pattern).
AffinePoseResult standard_affine_pose(const Eigen::Matrix3Xd& model_object,
                                      const Eigen::Matrix2Xd& image,
                                      const Eigen::VectorXd& weights = {},
                                      const AffinePoseOptions& options = {});

/// The free-vector set that standard_affine_pose() and full_3d_pose() build for `requested`:
/// they solve a single Theorem-1 problem (nothing is enumerated), so kAuto means all pairs.
FreeVectorSet single_pattern_free_vectors(FreeVectorSet requested);

/// The paper's "full 3-D" baseline (Sec. IV): free vectors of 3-D measured points (measured
/// alpha q_i ~= R z_i + p), Theorem 1 for R and alpha (Eq. 4), p from Eq. (13). Uses
/// options.free_vectors (kAuto: all pairs), pair_weighting and orientation.degenerate_gap only.
/// residual is J of
/// Eq. (12). (absolute_pose() is the centred equivalent.) n >= 3 points, as in affine_pose().
PoseResult full_3d_pose(const Eigen::Matrix3Xd& model_object, const Eigen::Matrix3Xd& measured,
                        const Eigen::VectorXd& weights = {}, const AffinePoseOptions& options = {});

/// Options of minimize_affine_residual().
struct AffineCrossCheckOptions {
  int starts = 16;             ///< random starting rotations (uniform on SO(3)), >= 1
  std::uint32_t seed = 1;      ///< seed of the starting rotations
  double x_tolerance = 1e-13;  ///< absolute step tolerance, radians, > 0
  int max_evaluations = 4000;  ///< per start, >= 1

  bool is_valid(std::string* why = nullptr) const;
};

/// Result of minimize_affine_residual().
struct AffineCrossCheckResult {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();  ///< best over all starts
  double residual = 0.0;  ///< J_2d of Eq. (15) at R (with the scale alpha)
  int evaluations = 0;    ///< objective evaluations over all starts
  int failed_starts = 0;  ///< starts whose local optimiser reported an error
  /// Empty when the minimisation ran. kWithoutNlopt (vantage/analysis/build_options.h) when
  /// vantage was built without NLopt: nothing ran, residual is NaN and R the identity.
  std::string skipped;
};

/// Direct minimisation of J_2d = sum w_i |P R z_i - alpha d_i|^2 over SO(3) by a local
/// optimiser (NLopt BOBYQA on the rotation vector around each start) from options.starts seeded
/// random rotations (built without NLopt: validates its input, runs nothing and says so in
/// `skipped`). An independent check of Prop. 4: on noise-free data both reach J_2d = 0 at
/// the truth; under noise Prop. 4's answer (the best of 2^m Theorem-1 rotations, each optimal
/// for its own 3-D subproblem) is in general not the minimiser of J_2d, so this residual is
/// lower. Same preconditions as affine_orientation() (no limit on n).
AffineCrossCheckResult minimize_affine_residual(const Eigen::Matrix3Xd& z_object,
                                                const Eigen::Matrix2Xd& d_image, double alpha,
                                                const Eigen::VectorXd& weights = {},
                                                const AffineCrossCheckOptions& options = {});

/// J_2d = sum w_i |P R z_i - alpha d_i|^2 (Eq. 15 with scale), summed directly.
double affine_residual(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_image,
                       double alpha, const Eigen::Matrix3d& R_camera_object,
                       const Eigen::VectorXd& weights = {});

namespace internal {
/// D of the sign pattern `signs` (bit i set: v_zi negative) recomputed from scratch, for tests of
/// the Gray-code update. v_z: the non-negative missing components in object units.
Eigen::Matrix4d affine_pattern_d(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix2Xd& d_object,
                                 const Eigen::VectorXd& v_z, const Eigen::VectorXd& weights,
                                 std::uint64_t signs);
/// D after walking the Gray code for `steps` steps from the all-positive pattern with the
/// update of Eq. (17) (docs/math.md §9); *signs receives the pattern reached.
Eigen::Matrix4d affine_gray_code_d(const Eigen::Matrix3Xd& z_object,
                                   const Eigen::Matrix2Xd& d_object, const Eigen::VectorXd& v_z,
                                   const Eigen::VectorXd& weights, std::uint64_t steps,
                                   std::uint64_t* signs);
}  // namespace internal

}  // namespace vantage
