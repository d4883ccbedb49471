#pragma once

/// The worst and best target registration error over the tracked directions of a tool
/// (docs/math.md §23, "Worst and best"): RMS^2(a) = c_V + a^T M_V a on the directions a whose
/// visible set is V (§20's visibility), bounded by a best-first branch and bound over the patches
/// of the cube sphere.
///
/// Frames: a is a unit vector in the tool frame from the tool toward the tracker.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "vantage/tracker/target_registration.h"
#include "vantage/visibility/visibility.h"

namespace vantage::tracker {

/// Options of tre_extremes().
struct TreSearchOptions {
  /// Required (bound - attained) / attained of the RMS for the certificate, in [1e-12, 1e-2].
  double relative_tolerance = 1e-6;
  /// Patch budget per extreme, >= 1; when exhausted the extreme is not certified.
  long max_patches = 2'000'000;
  /// A patch with more mixed units than this is split without a bound, in [0, 16].
  int max_enumerated_units = 8;
  /// The worst's search stops as soon as it attains an RMS at or above this (then the worst is
  /// kNotCertified with rms >= stop_above): a caller that only asks "below a level?"; not NaN.
  /// The default never stops.
  double stop_above = std::numeric_limits<double>::infinity();

  bool is_valid(std::string* why = nullptr) const;
};

/// The worst (largest) or best (smallest) RMS TRE over the tracked directions.
struct TreExtreme {
  enum class Status {
    kCertified,     ///< every patch closed: |rms_bound - rms| <= relative_tolerance * rms
    kNotCertified,  ///< patch budget exhausted first
    kUntracked,     ///< no direction of the workspace is tracked: the rest means nothing
  };
  Status status = Status::kNotCertified;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< attained, tracked, unit
  double rms = 0.0;                                      ///< RMS TRE at `direction`
  /// Proven: no tracked direction has an RMS above (worst) or below (best) it.
  double rms_bound = 0.0;
  std::vector<int> visible_markers;  ///< V(direction), increasing
  long patches = 0;
  /// No normals and the whole sphere: the top (bottom) eigenvector of M, exact.
  bool closed_form = false;

  bool certified() const { return status == Status::kCertified; }
};

/// "certified", "not_certified" or "untracked".
const char* to_string(TreExtreme::Status status);

struct TreExtremes {
  TreExtreme worst;
  TreExtreme best;
};

/// The worst and best RMS TRE at `target_tool` over the tracked directions of `problem`
/// (docs/math.md §23). With every cone 180 degrees, no occlusion and no workspace, the closed
/// form. Throws InvalidArgument on a bad problem, FLE, options, or more than 63 markers.
TreExtremes tre_extremes(const visibility::VisibilityProblem& problem,
                         const Eigen::Vector3d& target_tool, const FleModel& fle,
                         const TreSearchOptions& options = {});

/// The worst of tre_extremes() alone (the same numbers), with options.stop_above: what a search
/// over layouts needs (docs/math.md §21, "Objectives"). Throws as tre_extremes().
TreExtreme tre_worst(const visibility::VisibilityProblem& problem,
                     const Eigen::Vector3d& target_tool, const FleModel& fle,
                     const TreSearchOptions& options = {});

}  // namespace vantage::tracker
