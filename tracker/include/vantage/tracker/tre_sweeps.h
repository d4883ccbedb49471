#pragma once

/// The sweeps behind `vantage plot LAYOUT --tre` (docs/math.md §23, "Sweeps and figures"): the
/// RMS TRE along the tip axis and on NDI-style circles about the tool's axes, each at fixed lines
/// of sight, with the report of the targets (whose worst and best directions they use). Every
/// value is TreModel::at() (Eq. 23.2 at V(a)) or, with an isotropic FLE, Eq. (23.3).
///
/// Frames: targets, directions and the centroid are in the tool frame; a line of sight is a unit
/// vector from the tool toward the tracker.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::tracker {

/// Options of tre_sweeps().
struct TreSweepOptions {
  int tip_axis_samples = 61;     ///< distances 0 .. tip_axis_extent * D1, in [2, 100000]
  double tip_axis_extent = 1.5;  ///< the tip axis runs to this multiple of D1, finite, > 0
  /// Radius of the polar circles (layout units, finite, > 0); default D1, the first target's
  /// distance from the markers' centroid.
  std::optional<double> radius;
  int polar_step_deg = 1;  ///< angle step in whole degrees, a divisor of 360 in [1, 90]

  /// Names "tip_axis_samples", "tip_axis_extent", "radius" or "polar_step_deg".
  bool is_valid(std::string* why = nullptr) const;
};

/// The RMS TRE of a sweep's targets at one fixed line of sight.
struct TreCurve {
  /// "worst" and "best" (the first target's, TreTargetReport::extremes) or "direction"
  /// (TreOptions::direction).
  std::string label;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit
  bool tracked = false;              ///< as TreAtDirection; an untracked curve has no values
  std::vector<int> visible_markers;  ///< V(direction), the same for every target
  std::vector<double> rms;           ///< one per target of the sweep (empty when not tracked)
};

/// Targets g + s u at the distances s from the markers' centroid g along the tip axis u.
struct TreTipAxisSweep {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< g, of every marker
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();     ///< u = (r1 - g) / D1
  double target_distance = 0.0;                        ///< D1
  std::vector<double> distance;                        ///< s, 0 .. extent * D1, equal steps
  std::vector<TreCurve> curves;                        ///< worst, best, then direction if given
  /// Eq. (23.3) at each target, every marker registered: with an isotropic FLE only, else empty.
  std::vector<double> rms_isotropic;

  Eigen::Vector3d target(std::size_t k) const { return centroid + distance[k] * axis; }
};

/// Targets g + R (cos t e_i + sin t e_j) on a circle about each tool axis k, (k; i, j) =
/// (x; y, z), (y; z, x), (z; x, y), at the first target's worst line of sight.
struct TrePolarSweep {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< g
  double radius = 0.0;                                 ///< R
  std::vector<double> angle_deg;                       ///< 0, step, ..., 360
  std::array<TreCurve, 3> curves;                      ///< about x, y, z; each labelled "worst"
  /// Eq. (23.3) about x, y, z: with an isotropic FLE only, else empty.
  std::array<std::vector<double>, 3> rms_isotropic;

  /// The target at angle index k about axis `axis` (0 x, 1 y, 2 z).
  Eigen::Vector3d target(int axis, std::size_t k) const;
};

/// The report of the targets and the two sweeps of the first one.
struct TreSweeps {
  TreReport report;
  TreTipAxisSweep tip_axis;
  TrePolarSweep polar;
};

/// tre_report(model, targets, options) and the sweeps of targets[0] at its reported worst and
/// best line of sight (and options.direction). Throws InvalidArgument as tre_report() does,
/// "target[0]" when the first target is the markers' centroid (no tip axis), or the sweep
/// option's field. A first target that is tracked from no direction gives curves with
/// tracked = false.
TreSweeps tre_sweeps(const TreModel& model, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& options, const TreSweepOptions& sweep = {});

}  // namespace vantage::tracker
