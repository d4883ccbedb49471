#pragma once

/// The worst viewpoint of markers on a body (docs/math.md §20): each marker is seen only from
/// within its cone and where the body does not shadow it, so the data vectors at a viewing
/// direction a are the free vectors between the markers visible from a, and a and -a differ.
///
/// Frames: a is a unit vector in the object frame from the body toward the camera (the optical
/// axis reversed). Marker i (point p_i, outward unit normal nu_i, cone cosine c_i) is visible
/// from a iff nu_i.a >= c_i and, with a body, its occlusion grid says the direction is clear.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/occlusion_grid.h"

namespace vantage::visibility {

/// A cap of directions {a : a.axis >= cos_half_angle} (a docking approach, a fixed tracker).
struct Workspace {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit
  double cos_half_angle = -1.0;                     ///< cos of the half-angle, in [-1, 1)
};

/// The markers of a body and what hides them.
struct VisibilityProblem {
  Eigen::Matrix3Xd points;   ///< marker positions, 3 x n, n >= 3, distinct, finite
  Eigen::Matrix3Xd normals;  ///< outward unit normals, 3 x n
  Eigen::VectorXd cos_cone;  ///< cos of each marker's cone half-angle, in [-1, 1)
  int min_visible = 3;       ///< markers a trackable direction must see, >= 3
  std::optional<Workspace> workspace;
  /// Occlusion by a body (docs/math.md §20); null without a body.
  const OcclusionGrid* occlusion = nullptr;
  /// The grid marker of each point (a subset of a larger grid's markers: marker placement,
  /// docs/math.md §21), or empty: point i is grid marker i.
  std::vector<int> occlusion_markers;

  /// The grid marker of point i.
  int occlusion_marker(int i) const {
    return occlusion_markers.empty() ? i : occlusion_markers[static_cast<std::size_t>(i)];
  }

  /// Throws InvalidArgument naming the field ("normals[2]", "min_visible", ...) on bad input.
  void validate() const;
};

/// What a direction sees.
struct DirectionVisibility {
  std::vector<int> visible;  ///< visible markers, increasing
  /// At least min_visible visible, not collinear, and inside the workspace.
  bool trackable = false;
  /// min |a.u_ij| over the visible pairs (1 with fewer than two visible markers).
  double t = 1.0;
};

/// The visibility of direction a (unit) in the search's model: the cone test, the occlusion
/// grid and t (exact_visibility.h casts exact rays instead of the grid).
DirectionVisibility direction_visibility(const VisibilityProblem& problem,
                                         const Eigen::Vector3d& a);

/// What direction a (unit) gives when `visible` (increasing) are the markers it sees: t and
/// whether it is trackable (min_visible, not collinear, inside the workspace).
DirectionVisibility seen_set(const VisibilityProblem& problem, const Eigen::Vector3d& a,
                             std::vector<int> visible);

/// Options of visibility_worst_viewpoint().
struct VisibilitySearchOptions {
  /// Required t_upper - t_lower of the certificate, in [1e-15, 1e-3].
  double certificate_tolerance = 1e-7;
  /// Attained values within this of the best are reported as further worst viewpoints, in
  /// [0, 1e-3].
  double tie_tolerance = 1e-9;
  /// Patch budget of the branch and bound, >= 1; when exhausted the result is not certified.
  long max_patches = 4'000'000;
  /// The search stops as soon as an attained value reaches this (a caller that only needs to
  /// know whether t*_vis is below a level: marker placement, docs/math.md §21). The result is
  /// then not certified, and its t_lower is at least stop_above. Default: never.
  double stop_above = 2.0;

  bool is_valid(std::string* why = nullptr) const;
};

/// The worst viewpoint under visibility, with its certificate (docs/math.md §20).
struct VisibilityWorstViewpoint {
  enum class Status {
    kCertified,     ///< t_upper - t_lower <= certificate_tolerance
    kNotCertified,  ///< patch budget exhausted first, or stopped at options.stop_above
    kUntrackable,   ///< no direction of the workspace is trackable: t, viewpoint mean nothing
  };
  Status status = Status::kNotCertified;
  /// The best attained worst viewpoint (signed, unit); among values equal to rounding, the
  /// first by largest z, then y, then x.
  Eigen::Vector3d viewpoint = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> viewpoints;  ///< every optimum within tie_tolerance, viewpoint first
  std::vector<int> visible_markers;         ///< the markers visible from `viewpoint`
  double t = 0.0;                           ///< t(viewpoint) = t_lower
  double pbar_min = 1.0;                    ///< sqrt(1 - t^2)
  double t_upper = 1.0;                     ///< proven: no trackable direction has t above it
  double t_lower = 0.0;                     ///< attained at `viewpoint`
  long patches = 0;
  long cells_solved = 0;
  std::string message;

  bool certified() const { return status == Status::kCertified; }
};

/// "certified", "not_certified" or "untrackable".
const char* to_string(VisibilityWorstViewpoint::Status status);

/// The search of docs/math.md §20. Throws InvalidArgument on a bad problem or options.
VisibilityWorstViewpoint visibility_worst_viewpoint(const VisibilityProblem& problem,
                                                    const VisibilitySearchOptions& options = {});

/// `count` directions of the Fibonacci lattice on the sphere (3 x count, unit): the coverage's
/// lattice without a workspace (workspace_lattice.h). count >= 1.
Eigen::Matrix3Xd fibonacci_directions(int count);

/// How much of the workspace is trackable (docs/math.md §20, "Coverage").
struct VisibilityCoverage {
  int samples = 0;                  ///< directions of the workspace's lattice
  double trackable_fraction = 0.0;  ///< of the workspace's area
  double lost_fraction = 0.0;       ///< 1 - trackable_fraction
  /// The largest connected untrackable region: its centre (unit) and angular radius.
  std::optional<Eigen::Vector3d> largest_region_center;
  double largest_region_radius_deg = 0.0;
};

/// Coverage estimated on the workspace's lattice at the density of `samples` directions on the
/// whole sphere (workspace_lattice.h), samples >= 100.
VisibilityCoverage visibility_coverage(const VisibilityProblem& problem, int samples = 20000);

}  // namespace vantage::visibility
