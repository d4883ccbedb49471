#pragma once

/// The visibility part of a layout report (docs/math.md §20): the worst viewpoint over the
/// trackable directions of the workspace, the coverage, and which marker costs most when lost.
/// report::analyze_layout() (layout_report.h) fills it for every layout with normals.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/marker_visibility.h"
#include "vantage/analysis/occlusion_grid.h"
#include "vantage/visibility/visibility.h"

namespace vantage::visibility {

/// Options of the visibility analysis.
struct VisibilityReportOptions {
  VisibilitySearchOptions search;
  /// Occlusion grid cell size with a body, degrees, in [0.45, 30] (docs/math.md §20).
  double occlusion_resolution_deg = 1.0;
  int coverage_samples = 20000;  ///< the coverage lattice's density on the sphere, >= 100
  bool dropout = false;          ///< also analyse the layout without each marker
  int threads = 0;               ///< ray casting and dropout threads, >= 0 (0: all cores)

  bool is_valid(std::string* why = nullptr) const;
};

/// The layout without one marker, under visibility.
struct VisibilityDropoutEntry {
  int lost = 0;  ///< the marker removed
  VisibilityWorstViewpoint::Status status = VisibilityWorstViewpoint::Status::kNotCertified;
  double t = 0.0;
  double pbar_min = 1.0;
  double max_worst_case_error_deg = 0.0;  ///< asin t, degrees (90 when untrackable)
  double trackable_fraction = 0.0;
};

/// What a layout on its body promises.
struct VisibilityReport {
  bool with_body = false;  ///< "cone+mesh" (occlusion by the body) or "cone"
  int min_visible = 3;
  std::optional<LayoutWorkspace> workspace;
  VisibilityWorstViewpoint worst;
  double max_worst_case_error_deg = 90.0;  ///< asin t of the worst viewpoint, degrees
  VisibilityCoverage coverage;
  std::optional<double> occlusion_resolution_deg;  ///< with a body
  /// With a body and a trackable worst: what `worst.viewpoint` sees under exact rays
  /// (exact_visibility.h). The search certifies on the occlusion grid; this checks its answer.
  std::optional<DirectionVisibility> exact_viewpoint;
  /// With a body: each marker's distance to the mesh surface, and the markers farther than
  /// kOffSurface of the mesh's size (plus the radius of a placement's spherical markers) (a
  /// warning: the mesh may not be the markers' body).
  std::vector<double> distance_to_body;
  std::vector<int> off_body;
  /// With a body: the markers whose cones admit a direction of the coverage lattice in the
  /// workspace but which the body hides at every such direction (docs/math.md §20, "Markers the
  /// body hides"), increasing. Sampled on coverage.samples directions, not certified.
  std::vector<int> hidden_by_body;
  std::vector<VisibilityDropoutEntry> dropout;  ///< by marker, when asked
  /// Markers by decreasing harm when lost: largest worst-case error, then smallest trackable
  /// fraction, then index.
  std::vector<int> dropout_by_harm;

  /// A marker farther from the mesh than this fraction of the mesh's size is reported.
  static constexpr double kOffSurface = 0.01;

  /// Certified (or, with dropout, every entry certified or untrackable).
  bool is_usable() const;
  /// The certificate in words (docs/math.md §20, "What the certificate covers"): "certified"
  /// without a body (cones are exact), "certified_at_resolution" with one (certified on the
  /// occlusion grid at occlusion_resolution_deg, not under exact rays), "not_certified" (also
  /// when the exact rays at the worst viewpoint contradict the grid) or "untrackable".
  const char* certificate_status() const;
  /// A dropout entry's status in the same words (only the intact answer is checked by exact
  /// rays).
  const char* entry_status(const VisibilityDropoutEntry& entry) const;
  /// Certified with nothing left to a resolution: certified and without a body.
  bool certified() const { return worst.certified() && !with_body; }
  /// With a body: the exact rays at the reported viewpoint see another set of markers than the
  /// grid does (the grid's cells decided its neighbourhood wrongly).
  bool exact_viewpoint_disagrees() const;
  std::string message() const;
};

/// The visibility problem of a point layout with visibility (points, unit normals, cone
/// cosines, min_visible, workspace) over an optional occlusion grid.
VisibilityProblem visibility_problem(const Layout& layout, const OcclusionGrid* occlusion);

/// The analysis of docs/math.md §20 for a point layout with visibility. Throws InvalidArgument
/// for a layout without visibility or bad options.
VisibilityReport analyze_visibility(const Layout& layout,
                                    const VisibilityReportOptions& options = {});

}  // namespace vantage::visibility
