#pragma once

/// The target registration error report of a tool (`vantage tre`, docs/math.md §23): per
/// target, Fitzpatrick's isotropic RMS, the TRE at a given line of sight, the certified worst and
/// best over the tracked directions and a Monte Carlo check. The command, the figures and the
/// tests all start from tre_report().

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/tracker/tre_search.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::tracker {

/// Options of tre_report().
struct TreOptions {
  FleModel fle;
  /// Also the TRE at this line of sight (tool frame, tool toward tracker; normalised), if given.
  std::optional<Eigen::Vector3d> direction;
  long monte_carlo_trials = 0;  ///< 0: no Monte Carlo; otherwise >= 1000
  std::uint64_t seed = 1;
  int threads = 0;  ///< Monte Carlo threads (0: all cores); the result does not depend on it
  TreSearchOptions search;
  /// Called during the Monte Carlo check with its stage ("Monte Carlo 2097152/10000000 trials",
  /// "target 2/3, " before it with several targets), e.g. to show progress; empty: nothing.
  std::function<void(const std::string& stage)> progress;

  /// Names "fle.sigma_perp", "direction", "monte_carlo_trials" or the search's field.
  bool is_valid(std::string* why = nullptr) const;
};

/// The TRE at one line of sight.
struct TreAtDirection {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit
  bool tracked = false;  ///< min_visible visible, not collinear, in the workspace
  double rms = 0.0;      ///< sqrt(trace covariance); 0 when not tracked
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< tool frame, Eq. (23.2)
  std::vector<int> visible_markers;
};

/// A point layout ready to answer "what TRE does target r have from line of sight a?"
/// (docs/math.md §23): its visibility problem (tre_visibility_problem(); with a body, the
/// occlusion grid, owned here) and the FLE. The report, the sweeps and the figures evaluate the
/// TRE through one.
class TreModel {
 public:
  /// Throws InvalidArgument for a layout that is not in point mode ("points"), a bad layout or
  /// a bad FLE ("fle.sigma_perp", "fle.sigma_axial").
  TreModel(const Layout& layout, const FleModel& fle);

  const visibility::VisibilityProblem& problem() const { return problem_; }
  const FleModel& fle() const { return fle_; }
  /// The layout has visibility (normals, cones); without, every marker is seen from everywhere.
  bool with_normals() const { return visibility_.has_value(); }
  bool with_body() const { return visibility_ && visibility_->has_body(); }
  /// a (unit) lies in the layout's workspace (always without one).
  bool in_workspace(const Eigen::Vector3d& a) const;
  /// The centroid of every marker.
  Eigen::Vector3d centroid() const { return problem_.points.rowwise().mean(); }
  /// The TRE at target_tool from unit line of sight a: V(a) of §20 and, where tracked, Eq. (23.2)
  /// with Sigma(a) of every visible marker.
  TreAtDirection at(const Eigen::Vector3d& target_tool, const Eigen::Vector3d& a) const;

 private:
  std::optional<visibility::VisibilityModel>
      visibility_;  // owns the occlusion grid problem_ points to
  visibility::VisibilityProblem problem_;
  FleModel fle_;
};

/// One target's report.
struct TreTargetReport {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< tool frame
  /// Eq. (23.3), every marker registered: with an isotropic FLE (FleModel::from_rms) only.
  std::optional<double> rms_isotropic;
  std::optional<TreAtDirection> at_direction;
  TreExtremes extremes;
  /// At `direction` when given, else at the worst direction.
  std::optional<TreMonteCarlo> monte_carlo;
  Eigen::Vector3d monte_carlo_direction = Eigen::Vector3d::UnitZ();
};

struct TreReport {
  std::vector<TreTargetReport> targets;
  FleModel fle;
  int markers = 0;
  int min_visible = 3;
  bool with_normals = false;  ///< the layout has visibility (normals, cones)
  bool with_body = false;     ///< occlusion by a body mesh
  /// Every marker on one line: a 5-DoF tool (docs/math.md §23, "Five degrees of freedom"),
  /// whose targets are on `axis` (through `axis_point`); the rotation about it is not measured.
  bool five_dof = false;
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
};

/// The report for a point layout (with or without visibility) and targets in its frame.
/// Throws InvalidArgument for a layout that is not in point mode ("points"), no targets
/// ("target"), a non-finite target ("target[i]") or bad options (named by their field:
/// "monte_carlo_trials", "threads", "fle.sigma_perp", ...).
TreReport tre_report(const Layout& layout, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& options);

/// The visibility problem of a layout for the TRE: its own with normals, otherwise every marker
/// seen from everywhere (180-degree cones) inside the layout's workspace.
visibility::VisibilityProblem tre_visibility_problem(const Layout& layout);

/// tre_report() of the model's layout and FLE (options.fle is ignored): for callers that also
/// evaluate the model (the sweeps), so that a body's occlusion grid is cast once.
TreReport tre_report(const TreModel& model, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& options);

}  // namespace vantage::tracker
