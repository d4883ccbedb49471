#pragma once

/// The target registration error (TRE) of a tool tracked by a 3-D tracker, to first order
/// (docs/math.md §23): markers p_i (tool frame) measured in the tracker frame with zero-mean
/// fiducial localisation error (FLE), registered by unweighted least squares without scale
/// (Theorem 1, Eq. 23.1), the error of the registered target r expressed in the tool frame.
///
/// Frames: x_tracker = R_tracker_tool * x_tool + t. The line of sight a is a unit vector in the
/// tool frame from the tool toward the tracker (docs/math.md §20's viewing direction).

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vantage::tracker {

/// The FLE of every marker: standard deviations sigma_perp across and sigma_axial along the
/// line of sight, Sigma(a) = sigma_perp^2 (I - a a^T) + sigma_axial^2 a a^T (Eq. 23.4).
struct FleModel {
  double sigma_perp = 0.0;   ///< per-axis standard deviation across the line of sight, >= 0
  double sigma_axial = 0.0;  ///< standard deviation along the line of sight, >= 0
  /// Set by isotropic(): the model came from an RMS (E|e|^2 = rms^2), reported as such.
  bool from_rms = false;

  /// Isotropic FLE with E|e|^2 = rms^2: sigma_perp = sigma_axial = rms / sqrt(3).
  static FleModel isotropic(double rms);
  /// sqrt(E|e|^2) = sqrt(2 sigma_perp^2 + sigma_axial^2).
  double rms() const;
  /// Finite, non-negative, not both zero; otherwise *why names "sigma_perp" or "sigma_axial".
  bool is_valid(std::string* why = nullptr) const;
};

/// How a visible set registers a target (docs/math.md §23, "Five degrees of freedom").
enum class Registration {
  kFull,     ///< at least 3 markers, not collinear: the whole pose
  kOnAxis,   ///< a 5-DoF tool (every marker of the tool on one line), at least 3 of them seen
             ///< and the target on their line: the rotation about the line is not measured and
             ///< does not move the target
  kTooFew,   ///< fewer than 3 markers
  kOffAxis,  ///< collinear markers and the target off their line (its error is unbounded), or
             ///< collinear markers of a tool that is not collinear (no 6-DoF pose)
};

/// "full", "on_axis", "too_few" or "off_axis".
const char* to_string(Registration registration);

/// The registration of `target_tool` by the markers `visible` of the tool `points_tool`. A set
/// is collinear when the smallest eigenvalue of Lambda (Eq. 23.2) is at most 1e-12 of its trace;
/// the target, at distance D from the set's centroid, is on the fitted line when its distance
/// from it is at most 1e-9 (r + D) + 2 epsilon (1 + D / r), r the set's RMS radius and epsilon
/// the larger of the markers' largest distance from the line and sqrt(1e-12 trace Lambda), the
/// largest deviation the collinearity test accepts (what the line's fit leaves undetermined).
Registration registration_of(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                             const Eigen::Vector3d& target_tool);

/// The line of a 5-DoF tool (every marker of `points_tool` collinear): a point on it (the
/// markers' centroid) and its unit direction (the first non-zero of its z, y, x components
/// positive); false when the markers are not collinear.
bool tool_axis(const Eigen::Matrix3Xd& points_tool, Eigen::Vector3d* point,
               Eigen::Vector3d* direction);

/// RMS^2(a) = c + a^T M a for one visible set (Eq. 23.4).
struct TreQuadratic {
  /// registration is kFull or kOnAxis: Lambda invertible, or invertible across the 5-DoF line
  /// whose rotation does not move the target (its pseudo-inverse then).
  bool registrable = false;
  Registration registration = Registration::kTooFew;
  double c = 0.0;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();

  /// c + a^T M a (a unit).
  double rms_squared(const Eigen::Vector3d& a) const { return c + a.dot(M * a); }
};

/// The first-order maps A_i of Eq. (23.2), TRE = sum_{i in visible} A_i e'_i, one per entry of
/// `visible` (indices into the columns of points_tool, distinct); for Registration::kOnAxis with
/// the pseudo-inverse of Lambda. Returns false (and leaves *A empty) unless registration_of() is
/// kFull or kOnAxis; *how (when given) is registration_of(), found on the way.
bool tre_linear_maps(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                     const Eigen::Vector3d& target_tool, std::vector<Eigen::Matrix3d>* A,
                     Registration* how = nullptr);

/// c and M of Eq. (23.4) for the visible set.
TreQuadratic tre_quadratic(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                           const Eigen::Vector3d& target_tool, const FleModel& fle);

/// Cov(TRE) in the tool frame at line of sight a (unit), Eq. (23.2) with Sigma(a) of every marker.
/// Zero when the set is not registrable.
Eigen::Matrix3d tre_covariance(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                               const Eigen::Vector3d& target_tool, const FleModel& fle,
                               const Eigen::Vector3d& a);

/// The lengths within which the TRE is computed in double precision (docs/math.md §23, "Numeric
/// range"): RMS^2 of a target then stays a normal number, so that a reported TRE is never an
/// overflow's inf or an underflow's 0.
inline constexpr double kTreMinLength = 1e-50;
inline constexpr double kTreMaxLength = 1e50;

/// Throws InvalidArgument when a length leaves [kTreMinLength, kTreMaxLength]: the markers' RMS
/// radius about their centroid ("points"), the larger FLE standard deviation and each of them
/// ("fle.sigma_perp", "fle.sigma_axial"), the target's distance from the centroid (at most;
/// "target"), or the RMS TRE at the target with every marker registered ("target"); the message
/// names "target <index>" when index >= 0 (one of several); and a target off a 5-DoF tool's line
/// (check_on_axis()). Other markers that cannot be registered are left to the search to report.
void check_tre_range(const Eigen::Matrix3Xd& points_tool, const Eigen::Vector3d& target_tool,
                     const FleModel& fle, long index);

/// Throws InvalidArgument "target" (with "target <index>: " when index >= 0) when the tool is a
/// 5-DoF tool (every marker collinear) and the target is off its line, naming the distance and
/// the nearest point on the line; nothing otherwise. check_tre_range() calls it.
void check_on_axis(const Eigen::Matrix3Xd& points_tool, const Eigen::Vector3d& target_tool,
                   long index);

/// Fitzpatrick, West & Maurer 1998's RMS TRE for isotropic FLE with E|e|^2 = fle_rms^2 and every
/// marker registered, Eq. (23.3) (for a 5-DoF tool and a target on its line, with the rotation
/// about the line left out). Throws InvalidArgument ("points" for fewer than 3 markers,
/// "target" for a target off a 5-DoF tool's line, naming its distance and the nearest point on
/// the line).
double tre_rms_isotropic(const Eigen::Matrix3Xd& points_tool, const Eigen::Vector3d& target_tool,
                         double fle_rms);

/// What a Monte Carlo run measured (docs/math.md §23, "Monte Carlo").
struct TreMonteCarlo {
  long trials = 0;
  double rms = 0.0;          ///< sqrt(mean |TRE|^2) measured
  double formula_rms = 0.0;  ///< sqrt(trace Cov) of Eq. (23.2) at the same a and visible set
  double rel_diff = 0.0;     ///< rms / formula_rms - 1
};

/// `trials` registrations of the visible markers at line of sight a: the tool at the rotation
/// taking a to the tracker's +z, Gaussian FLE of the model's covariance in the tracker frame,
/// the q-method fit of Eq. (23.1), the target error measured. Trials are drawn in blocks of 1024,
/// block b from a generator seeded with (seed, b), so the result does not depend on `threads`
/// (0: all cores); they run a chunk of 2^20 at a time, so the memory does not grow with
/// `trials`, and trials_done (if given) is called after each chunk with the trials done so far.
/// Throws InvalidArgument for trials < 1 or a set that is not registrable.
TreMonteCarlo tre_monte_carlo(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                              const Eigen::Vector3d& target_tool, const FleModel& fle,
                              const Eigen::Vector3d& a, long trials, std::uint64_t seed,
                              int threads = 0,
                              const std::function<void(long trials_done)>& trials_done = {});

}  // namespace vantage::tracker
