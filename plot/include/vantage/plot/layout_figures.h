#pragma once

/// All figures of one layout in one call, drawn from its report (report::analyze_layout(), the
/// report `vantage analyze` prints): the figures compute no analysis of their own. This is what
/// `vantage plot` and `make figures` run.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/plot/design_curve.h"
#include "vantage/plot/figure.h"
#include "vantage/report/layout_report.h"

namespace vantage::plot {

/// The figures, in the order they are written (file names <name>.<ext>, <name>.csv). For a
/// layout with normals (on its body, docs/math.md §20) viewpoint_map and dropout are drawn under
/// visibility (visibility_maps.h, visibility_dropout_chart.h) and "visibility" is added; for
/// other layouts "visibility" does not apply. "placement" (placement_figure.h) applies to a
/// layout written by `vantage place` (Layout::placement).
inline constexpr std::array<const char*, 7> kFigureNames = {
    "viewpoint_map", "visibility", "dropout", "error_surface", "vectors", "placement", "design"};

/// True for a name in kFigureNames.
bool is_figure_name(const std::string& name);

/// Options of write_layout_figures().
struct LayoutFiguresOptions {
  FigureOptions figure;
  /// Figures to write (names from kFigureNames, no repeats); empty = all, where "design" is
  /// included only when a design curve is given.
  std::vector<std::string> only;
  double threshold_deg = 5.0;  ///< viewpoint_map contour, in (0, 90) degrees
  int map_samples = 400;       ///< viewpoint_map grid per axis, in [400, 4000]

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// Result of write_layout_figures().
struct LayoutFigures {
  enum class Status {
    kCertified,     ///< the report behind the figures is usable (LayoutReport::is_usable())
    kNotCertified,  ///< it is not; figures drawn anyway (message says why)
  };
  Status status = Status::kNotCertified;
  std::vector<FigureFiles> files;  ///< in kFigureNames order
  double pbar_min = 1.0;           ///< of the layout seen whole
  double max_worst_case_error_deg = 0.0;
  /// On its body (a layout with normals): the worst-case error with visibility and the
  /// trackable fraction of the workspace.
  std::optional<double> visibility_max_worst_case_error_deg;
  std::optional<double> trackable_fraction;
  /// The layout has a body mesh: a usable report is certified on its occlusion grid
  /// ("certified_at_resolution", docs/math.md §20).
  bool with_body = false;
  std::string message;
};

/// The figure names write_layout_figures() will write for these options (checks `only`);
/// has_visibility: the layout has normals (Layout::visibility); has_placement: it was placed
/// (Layout::placement). Throws InvalidArgument naming "only" for an unknown or repeated name,
/// for "design" without a design curve, "visibility" without normals or "placement" without a
/// placement.
std::vector<std::string> selected_figures(const LayoutFiguresOptions& options, bool has_design,
                                          bool has_visibility = false, bool has_placement = false);

/// True when the figures `options` select need the report's dropout analysis (the dropout
/// figure): run report::analyze_layout() with LayoutReportOptions::dropout then.
bool needs_dropout(const LayoutFiguresOptions& options, bool has_design,
                   bool has_visibility = false, bool has_placement = false);

/// Writes the selected figures of the layout of `report` into `directory` (which must exist).
/// design may be null (no design figure). Throws InvalidArgument on invalid options or curve, a
/// dropout figure without the report's dropout analysis, or a visibility figure for a layout
/// without normals; RenderError when drawing or writing
/// fails.
LayoutFigures write_layout_figures(const report::LayoutReport& report,
                                   const std::filesystem::path& directory,
                                   const LayoutFiguresOptions& options,
                                   const DesignCurve* design = nullptr);

}  // namespace vantage::plot
