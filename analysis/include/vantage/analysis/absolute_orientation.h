#pragma once

/// Absolute orientation and pose from 3-D correspondences: Theorem 1 (the q-method of McInroy et
/// al.), Haralick et al.'s SVD solution ([H] Sec. 3) and FOAM ([W]; Markley 1993),
/// plus Prop. 2 (swap sensitivity) and Prop. 3 (decoupled pose).
///
/// Frames: x_camera = R_camera_object * x_object + p_camera_object. Measured data live in the
/// camera (sensor) frame up to the unknown scale alpha:
///   direction data (Theorem 1):  alpha * v_i ~= R z_i,             Eq. (1)
///   point data (Prop. 3):        alpha * q_i ~= R z_i + p,         Eq. (12)
/// so alpha converts measured units into object units.
///
/// Point sets are Eigen::Matrix3Xd with one column per point. Weights are an Eigen::VectorXd with
/// one positive entry per column; an empty vector means all weights are 1.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

#include "vantage/analysis/quaternion.h"

namespace vantage {

/// Which absolute-orientation solver computes R.
enum class OrientationMethod {
  kQMethod,  ///< Theorem 1: top eigenvector of D (Eq. 2), rotation from Eq. (5)
  kSvd,      ///< Haralick et al. Sec. 3: SVD of the cross-covariance with the det = -1 guard
  kFoam,     ///< Markley's FOAM: Newton on the characteristic quartic, closed-form attitude
};

/// "qmethod", "svd" or "foam".
const char* to_string(OrientationMethod method);

/// The method named `name` (as to_string() spells it), or nullopt.
std::optional<OrientationMethod> parse_orientation_method(std::string_view name);

/// Outcome of an orientation or pose solve.
enum class OrientationStatus {
  kOk,  ///< the optimum is unique: relative eigen gap > OrientationOptions::degenerate_gap
  /// relative eigen gap <= degenerate_gap: the data (e.g. all vectors parallel) do not determine
  /// the rotation; R is one of several optima
  kDegenerate,
  /// decoupled_pose() only: ||sum w_i z_i|| > OrientationOptions::centred_tolerance *
  /// sum w_i ||z_i||, so Prop. 3's condition (Eq. 11) fails; no pose is returned
  kNotCentred,
};

/// "ok", "degenerate" or "not_centred".
const char* to_string(OrientationStatus status);

/// Options of absolute_orientation(), absolute_pose() and decoupled_pose().
struct OrientationOptions {
  OrientationMethod method = OrientationMethod::kQMethod;
  TopEigenOptions eigen;  ///< q-method eigen-solver tuning
  /// Relative eigen gap (lambda_1 - lambda_2) / (2 ||H||_F) of D at or below which the status
  /// is kDegenerate (H = sum w_i z_i v_i^T). Dimensionless, in [0, 1).
  double degenerate_gap = 1e-10;
  /// Relative size of sum w_i z_i tolerated by decoupled_pose() (Eq. 11). Dimensionless, >= 0.
  double centred_tolerance = 1e-9;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Rotation and scale from direction correspondences (Theorem 1).
struct OrientationResult {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  Eigen::Vector4d quaternion = Eigen::Vector4d::UnitW();  ///< [e; eps4] of R, eps4 >= 0
  double alpha = 1.0;                                     ///< optimal scale, Eq. (4)
  double residual = 0.0;       ///< J of Eq. (1) at the optimum (weighted sum of squares)
  double eigen_gap = 0.0;      ///< lambda_1 - lambda_2 of D (Eq. 2): conditioning of the problem
  bool used_fallback = false;  ///< q-method: full eigensolver used; FOAM: SVD used (zeta ~ 0)
  OrientationStatus status = OrientationStatus::kOk;
  std::string message;  ///< empty when status is kOk
};

/// Pose and scale from point correspondences (Prop. 3 and its centred generalisation).
struct PoseResult {
  Eigen::Matrix3d R_camera_object = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_camera_object = Eigen::Vector3d::Zero();
  double alpha = 1.0;      ///< scale: alpha q_i ~= R z_i + p
  double residual = 0.0;   ///< J of Eq. (12) at the optimum (weighted sum of squares)
  double eigen_gap = 0.0;  ///< lambda_1 - lambda_2 of D built from the centred data
  bool used_fallback = false;
  OrientationStatus status = OrientationStatus::kOk;
  std::string message;
};

/// D = sum_i w_i K(v_i, z_i), Eq. (2). Sizes as in absolute_orientation().
Eigen::Matrix4d orientation_matrix_d(const Eigen::Matrix3Xd& z_object,
                                     const Eigen::Matrix3Xd& v_camera,
                                     const Eigen::VectorXd& weights = {});

/// Theorem 1: minimises J = sum w_i ||R z_i - alpha v_i||^2 (Eq. 1) over R in SO(3), alpha > 0.
/// z_object and v_camera: 3 x n, n >= 1, finite; weights: n positive entries or empty. The
/// solution is scale invariant in v; alpha follows from Eq. (4). Allocates nothing.
/// Throws InvalidArgument on mismatched sizes, non-finite data, bad weights, all-zero v_camera.
OrientationResult absolute_orientation(const Eigen::Matrix3Xd& z_object,
                                       const Eigen::Matrix3Xd& v_camera,
                                       const Eigen::VectorXd& weights = {},
                                       const OrientationOptions& options = {});

/// General similarity pose: minimises J = sum w_i ||R z_i + p - alpha q_i||^2 over R, p and
/// alpha by centring both sets at their weighted centroids (so Eq. 11 holds for the centred z),
/// then Theorem 1 on the centred data, alpha from Eq. (4), and p from Eq. (13).
/// Same preconditions as absolute_orientation().
PoseResult absolute_pose(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix3Xd& q_camera,
                         const Eigen::VectorXd& weights = {},
                         const OrientationOptions& options = {});

/// Prop. 3: with sum w_i z_i = 0 (Eq. 11) and known alpha > 0, R is Theorem 1's rotation of the
/// uncentred data and p follows from Eq. (13). When Eq. (11) fails (see
/// OrientationOptions::centred_tolerance) the status is kNotCentred and R, p are left at
/// identity and zero: use absolute_pose(), which centres, instead.
PoseResult decoupled_pose(const Eigen::Matrix3Xd& z_object, const Eigen::Matrix3Xd& q_camera,
                          double alpha, const Eigen::VectorXd& weights = {},
                          const OrientationOptions& options = {});

/// Prop. 2, Eq. (10): the change of D when v_j and v_k are swapped (v_j matched with z_k and v_k
/// with z_j): Delta D = K(v_k - v_j, w_j z_j - w_k z_k).
Eigen::Matrix4d swap_delta_d(const Eigen::Vector3d& v_j, const Eigen::Vector3d& v_k,
                             const Eigen::Vector3d& z_j, const Eigen::Vector3d& z_k, double w_j,
                             double w_k);

/// The rotation maximising trace(R H) = sum w_i v_i^T R z_i over SO(3), for the weighted
/// cross-covariance H = sum w_i z_i v_i^T, by options.method. The building block of
/// absolute_orientation() for callers that accumulate H themselves (e.g. orthogonal
/// iteration). Allocates nothing. *eigen_gap, when given, receives lambda_1 - lambda_2 of D.
Eigen::Matrix3d optimal_rotation(const Eigen::Matrix3d& H, const OrientationOptions& options = {},
                                 double* eigen_gap = nullptr);

/// The top eigenpair of D (Eq. 2) as a rotation: R(eps) of Eq. (5) for the top eigenvector.
/// Used by analyses that modify D incrementally (Prop. 2, Prop. 4).
Eigen::Matrix3d rotation_from_d(const Eigen::Matrix4d& D, const TopEigenOptions& options = {});

/// Geodesic angle in radians, in [0, pi], between two rotations: the rotation angle of A^T B,
/// computed as 2 atan2(|e|, |eps4|) of its quaternion. (acos((trace(A^T B) - 1) / 2) is the same
/// angle but loses half the digits near 0.)
double rotation_angle_between(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B);

}  // namespace vantage
