#pragma once

/// Figure `dropout` of a layout on its body (docs/math.md §20): which marker, if lost, costs the
/// most. For each marker, the certified worst-case error with the markers visible from each
/// direction of the layout without it (bars, most harmful first, as
/// visibility::VisibilityReport::dropout_by_harm orders them), and the trackable fraction it leaves
/// (a second panel), each against the intact layout; the same error seen whole (every marker
/// from everywhere) beside each bar when the report has it.

#include <filesystem>
#include <string>
#include <vector>

#include "vantage/plot/figure.h"
#include "vantage/visibility/visibility_report.h"

namespace vantage::plot {

/// What the chart draws.
struct VisibilityDropoutChartData {
  std::string layout_name;
  /// One name per marker (Layout::entry_name: its name, or p<k>).
  std::vector<std::string> names;
  /// The layout on its body, with its dropout (VisibilityReportOptions::dropout).
  const visibility::VisibilityReport* report = nullptr;
  /// By marker: the worst-case error seen whole without it (degrees), or empty.
  std::vector<double> seen_whole_error_deg;
};

/// Writes dropout.<ext> and dropout.csv into `directory`. CSV columns
/// entry,index,rank,status,pbar_min,max_worst_case_error_deg,trackable_fraction,
/// seen_whole_error_deg: one row per lost marker in order of harm (rank 1 = most harmful;
/// entry the marker's name, or "p3" when the layout names none; status certified, not_certified or
/// untrackable; seen_whole_error_deg empty when not given), then the row "intact" (index -1, rank
/// 0). Throws InvalidArgument on bad data or options, RenderError when drawing or writing fails.
FigureFiles write_visibility_dropout_chart(const VisibilityDropoutChartData& data,
                                           const std::filesystem::path& directory,
                                           const FigureOptions& options = {});

}  // namespace vantage::plot
