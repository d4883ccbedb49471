#pragma once

/// The Cramér–Rao bound of the 6-DoF pose from one pinhole image, over every viewpoint of a
/// layout (docs/math.md §22).
///
/// Camera. Centre c = o + D a, a the unit viewing direction (object frame, from the body toward
/// the camera, as in §20), optical axis -a, looking at the aim point o (the markers' centroid
/// unless an aim is given). Frames:
/// x_camera = R_camera_object x_object + p_camera_object, the camera looks along +z, and a
/// camera-frame point x projects to q = pp + f (x / z, y / z) pixels, each coordinate with
/// independent Gaussian noise of standard deviation S pixels.
///
/// Perturbation. The pose is perturbed on the left, in the camera frame:
///   R = exp([dtheta]x) R0,   p = p0 + dt,
/// so x_i = R p_i + p moves by dx_i = -[R p_i]x dtheta + dt (p is not rotated). The 6-vector is
/// ordered as ROS PoseWithCovariance: (dt_x, dt_y, dt_z, dtheta_x, dtheta_y, dtheta_z), camera
/// frame.
///
/// Bound. J_i = d q_i / d(dt, dtheta) (2 x 6, analytic), F = sum over visible markers of
/// J_i^T J_i / S^2, C = F^-1. rot_rms_deg = sqrt(tr C_rot) in degrees (the RMS rotation angle of
/// an efficient estimator), trans_rms = sqrt(tr C_trans) in layout units. Neither depends on the
/// roll about the optical axis nor on the principal point (§22). The bound is first order: where
/// F is near singular or rot_rms passes PoseCrbAt::kMaxRotRmsDeg it means nothing, and the
/// direction is `unbounded`, never a figure (§22, "Unbounded").
///
/// Visibility. Marker i is visible iff n_i . unit(c - p_i) >= cos(cone_i) and, with a body, the
/// segment from p_i to c meets no triangle; a layout without visibility sees every marker.

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/visibility/camera_visibility.h"
#include "vantage/visibility/visibility.h"

namespace vantage::camera {

/// Options of the pose CRB (the camera and the search).
struct PoseCrbOptions {
  double distance =
      0.0;  ///< D, layout units, > the layout's radius about o, in [kMinLength, kMaxLength]
  double focal_length = 0.0;  ///< f, pixels, in [kMinPixels, kMaxPixels]
  /// Principal point, pixels, finite (the bound does not depend on it; it is reported).
  Eigen::Vector2d principal_point = Eigen::Vector2d::Zero();
  double noise_px = 0.0;  ///< S, pixels per coordinate, in [kMinPixels, kMaxPixels]
  /// o, the point the camera looks at (object frame, finite); none: the markers' centroid.
  std::optional<Eigen::Vector3d> aim;
  /// Directions of the map at the density of this many on the whole sphere (the workspace's own
  /// lattice, visibility::workspace_lattice), in [100, 10'000'000].
  int samples = 10000;
  /// Best samples from which the worst (and best) direction is refined, in [1, 1000].
  int refine_starts = 8;
  /// Threads of the map, >= 0 (0: all cores).
  int threads = 0;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;

  /// The ranges of f and S, of f / S and of lengths (D): inside them no entry of F, a sum of
  /// (f / (S z))^2 terms, overflows (docs/math.md §22).
  static constexpr double kMinPixels = 1e-50;
  static constexpr double kMaxPixels = 1e50;
  static constexpr double kMinFocalOverNoise = 1e-12;
  static constexpr double kMaxFocalOverNoise = 1e12;
  static constexpr double kMinLength = 1e-50;
  static constexpr double kMaxLength = 1e50;
};

/// The bound at one viewing direction.
struct PoseCrbAt {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< a, unit, object frame
  std::vector<int> visible_markers;                      ///< increasing
  /// In the workspace, at least max(3, min_visible) visible markers, F not singular
  /// (cond(F~) <= kMaxCondition for F~ = F with its translation rows and columns scaled by D)
  /// and rot_rms_deg <= kMaxRotRmsDeg: the first-order bound holds.
  bool trackable = false;
  /// Not trackable only because the first-order bound means nothing here: in the workspace and
  /// enough visible markers, but F fails the condition test (ill_conditioned) or the first-order
  /// rot_rms exceeds kMaxRotRmsDeg. No figure is reported (rot_rms_deg and trans_rms are +inf).
  bool unbounded = false;
  /// Unbounded because F failed the condition test: the pose is not determined to first order
  /// (too far, or a degenerate view).
  bool ill_conditioned = false;
  double rot_rms_deg = 0.0;  ///< sqrt(tr C_rot), degrees (+inf when not trackable)
  double trans_rms = 0.0;    ///< sqrt(tr C_trans), layout units (+inf when not trackable)
  /// sqrt(tr C_rot) in degrees whenever F passes the condition test, past kMaxRotRmsDeg too
  /// (+inf otherwise): what a search ranks layouts by, never a reported figure.
  double first_order_rot_rms_deg = 0.0;
  /// C, 6 x 6, ROS order (x, y, z, rx, ry, rz), camera frame, layout units and radians (zero
  /// when not trackable).
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();

  /// Largest condition number of the scaled Fisher information that counts as invertible.
  static constexpr double kMaxCondition = 1e12;
  /// Largest first-order rot_rms (degrees) reported as a figure: beyond it the linearisation
  /// behind the bound no longer describes the estimator (§22, "Unbounded").
  static constexpr double kMaxRotRmsDeg = 45.0;
};

/// A layout's pose CRB problem: markers, visibility and camera; built once, asked many times.
class PoseCrbModel {
 public:
  /// Throws InvalidArgument on a bad layout (Layout::validate()), a direction-mode layout
  /// ("vectors": the CRB needs marker points), fewer than 3 points, or bad options
  /// ("distance" when D does not exceed the layout's radius about the aim point, ...).
  PoseCrbModel(const Layout& layout, const PoseCrbOptions& options);
  ~PoseCrbModel();
  PoseCrbModel(PoseCrbModel&&) noexcept;
  PoseCrbModel& operator=(PoseCrbModel&&) noexcept;

  /// The bound at unit direction a (normalised here; zero throws InvalidArgument "direction").
  PoseCrbAt at(const Eigen::Vector3d& a) const;
  /// The same at another camera distance (> the radius, else InvalidArgument "distance").
  PoseCrbAt at(const Eigen::Vector3d& a, double distance) const;
  /// Throws InvalidArgument "distance" unless D is a camera distance of this model: in range and
  /// above the layout's radius about the aim point.
  void check_distance(double distance) const;

  /// The camera pose of direction a at distance D: R's third row is -a and its first row the
  /// unit part of a fixed reference axis orthogonal to a (the roll is immaterial, §22).
  void camera_pose(const Eigen::Vector3d& a, double distance, Eigen::Matrix3d* R_camera_object,
                   Eigen::Vector3d* p_camera_object) const;
  /// The markers' pixels seen from direction a at distance D (every marker, visible or not).
  Eigen::Matrix2Xd project(const Eigen::Vector3d& a, double distance) const;

  /// J (2n x 6) of every marker's pixels at the pose of a at distance D: rows 2i, 2i+1 are
  /// d q_i / d(dt, dtheta).
  Eigen::MatrixXd jacobian(const Eigen::Vector3d& a, double distance) const;

  const Eigen::Matrix3Xd& points() const;
  /// o: the aim point (options().aim, or the markers' centroid).
  const Eigen::Vector3d& centroid() const;
  double radius() const;  ///< max |p_i - o|
  bool in_workspace(const Eigen::Vector3d& a) const;
  /// The layout's workspace (none: the whole sphere).
  const std::optional<visibility::Workspace>& workspace() const;
  const PoseCrbOptions& options() const;
  bool with_body() const;
  /// Which markers a camera centre sees (§22, "Visibility").
  const visibility::CameraVisibility& visibility() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The camera of direction a (unit) at distance D looking at o (§22, "Camera"): R's third row is
/// -a, its first row the unit part of the coordinate axis least aligned with a orthogonal to a,
/// and p = -R (o + D a).
void camera_pose_toward(const Eigen::Vector3d& aim, const Eigen::Vector3d& a, double distance,
                        Eigen::Matrix3d* R_camera_object, Eigen::Vector3d* p_camera_object);

/// J^T J of one marker at object point x seen by the camera (R, p) of focal length f: its Fisher
/// information at a noise of 1 pixel (§22, "Fisher information").
Eigen::Matrix<double, 6, 6> marker_information(const Eigen::Vector3d& x, const Eigen::Matrix3d& R,
                                               const Eigen::Vector3d& p, double focal_length);

/// Completes `out` from F1, the summed marker_information() of its visible markers: the condition
/// test (§22, "Visibility"), C = S^2 F1^-1, rot_rms_deg and trans_rms. The caller has checked the
/// workspace and the marker count; `out` is left untrackable and unbounded when F is singular
/// (also marked ill_conditioned) or when rot_rms passes PoseCrbAt::kMaxRotRmsDeg (then only
/// first_order_rot_rms_deg is set).
void complete_pose_crb(const Eigen::Matrix<double, 6, 6>& F1, double noise_px, double distance,
                       PoseCrbAt* out);

/// The q-quantile (0 <= q <= 1) of increasing values, nearest rank: sorted[ceil(q n) - 1] (the
/// first for q n < 1). `sorted` is not empty.
double nearest_rank(const std::vector<double>& sorted, double q);

/// Percentiles of rot_rms_deg over the trackable area (equal-area samples).
struct PoseCrbPercentiles {
  double p50 = 0.0;
  double p95 = 0.0;
  double p99 = 0.0;
};

/// The map of the bound over the workspace (docs/math.md §22, "Sampling").
struct PoseCrbMap {
  enum class Status {
    kOk,           ///< at least one sampled direction of the workspace is trackable
    kUntrackable,  ///< no sampled direction of the workspace sees enough markers
    /// No sampled direction is trackable, and some see enough markers but every such F fails
    /// the condition test: the pose is not determined to first order (worst/best mean nothing).
    kIllConditioned,
    /// No sampled direction is trackable, some see enough markers, and at each the bound is
    /// unbounded, at least one by a first-order rot_rms above PoseCrbAt::kMaxRotRmsDeg.
    kUnbounded,
  };
  Status status = Status::kUntrackable;
  std::vector<PoseCrbAt> samples;  ///< at the workspace's lattice directions
  /// Largest first-order rot_rms where it exists: the largest samples refined by compass search
  /// on the sphere (no certificate: F is smooth only between visibility changes); unbounded when
  /// that passes kMaxRotRmsDeg or a sample's F is singular (§22, "Unbounded").
  PoseCrbAt worst;
  PoseCrbAt best;                   ///< smallest rot_rms_deg, found likewise
  double trackable_fraction = 0.0;  ///< of the workspace's area (sample count)
  /// Of the workspace's area, the directions that see enough markers where the bound is
  /// unbounded (PoseCrbAt::unbounded); worst, best and percentiles are over the trackable rest.
  double unbounded_fraction = 0.0;
  PoseCrbPercentiles percentiles;
  /// Width (degrees) of the region around `worst` where rot_rms >= worst / 2, the narrowest of
  /// four great-circle cuts through it (capped at 2 kMaxSliverProbeDeg); a cut that the
  /// workspace's edge ends on both sides is not counted.
  double worst_region_width_deg = 0.0;
  /// No cut counted: the region reaches the workspace's edge along every cut (the width is then
  /// the cap, and says nothing of the region).
  bool worst_region_fills_workspace = false;
  bool sliver = false;  ///< worst_region_width_deg < kSliverWidthDeg

  static constexpr double kSliverWidthDeg = 1.0;
  static constexpr double kMaxSliverProbeDeg = 20.0;
};

/// "ok", "untrackable", "ill_conditioned" or "unbounded".
const char* to_string(PoseCrbMap::Status status);

/// Why a map at distance D is not kOk, one sentence without a final full stop: no sampled
/// direction sees enough markers, or how many saw enough markers but failed the condition test
/// (or passed the rot_rms limit). Empty for kOk.
std::string untrackable_reason(const PoseCrbMap& map, double distance);

/// The map of `model` at its distance (docs/math.md §22).
PoseCrbMap pose_crb_map(const PoseCrbModel& model);
/// The map at another distance (the sweeps).
PoseCrbMap pose_crb_map(const PoseCrbModel& model, double distance);

/// One row of the distance sweep: the worst and the median direction at that distance.
struct PoseCrbSweepRow {
  double distance = 0.0;
  PoseCrbMap::Status status = PoseCrbMap::Status::kUntrackable;
  PoseCrbAt worst;
  /// The trackable sample whose rot_rms_deg is the median (p50) at this distance.
  PoseCrbAt median;
  double trackable_fraction = 0.0;
  double unbounded_fraction = 0.0;  ///< as PoseCrbMap::unbounded_fraction
};

/// Called before each step of a long computation with its stage ("distance 3/1000"), e.g. to
/// show progress; empty: nothing is called.
using CrbProgress = std::function<void(const std::string& stage)>;

/// The distance sweep D_k = D1 + k (D2 - D1) / (N - 1), k < N (N >= 2, D1 < D2 both above the
/// radius; InvalidArgument "sweep_distance" otherwise). `progress` gets "distance k/N".
std::vector<PoseCrbSweepRow> pose_crb_distance_sweep(const PoseCrbModel& model, double d1,
                                                     double d2, int count,
                                                     const CrbProgress& progress = {});

/// Everything `vantage crb` and `vantage.crb` report.
struct PoseCrbReport {
  PoseCrbOptions camera;  ///< the options used
  bool with_body = false;
  int markers = 0;
  std::optional<PoseCrbAt> at_direction;  ///< when a direction was asked
  PoseCrbMap map;
  /// The visibility worst-case error of the same layout (arccos pbar_min, docs/math.md §20; the
  /// seen-whole global value of Theorem 6 without visibility), degrees.
  double affine_bound_deg = 90.0;
  std::vector<PoseCrbSweepRow> sweep_distance;  ///< when asked
};

/// The front door: the model, the map, the bound at `direction` (when given), the affine bound
/// (report::analyze_layout()) and the distance sweep (when `sweep` = {D1, D2, N} is given, with
/// `progress` per distance).
struct PoseCrbSweep {
  double from = 0.0;
  double to = 0.0;
  int count = 0;
};
PoseCrbReport pose_crb_report(const Layout& layout, const PoseCrbOptions& options,
                              const std::optional<Eigen::Vector3d>& direction = std::nullopt,
                              const std::optional<PoseCrbSweep>& sweep = std::nullopt,
                              const CrbProgress& progress = {});

}  // namespace vantage::camera
