#pragma once

/// Figure `dropout`: markers get occluded. For each marker (point mode) or vector (direction
/// mode), the worst-case error of the layout without it (report::dropout_analysis, certified global
/// analysis each time), as bars sorted by harm, with the intact layout as a reference line.

#include <filesystem>
#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/plot/figure.h"
#include "vantage/report/dropout.h"

namespace vantage::plot {

/// What the dropout chart draws.
struct DropoutChartData {
  std::string layout_name;
  LayoutMode mode = LayoutMode::kPoints;  ///< unnamed bars are p<k> (markers) or v<k> (vectors)
  /// One name per entry (Layout::entry_name: its name, or p<k> / v<k>).
  std::vector<std::string> names;
  double intact_pbar_min = 1.0;       ///< of the whole layout
  double intact_max_error_deg = 0.0;  ///< of the whole layout (Eq. 30, as analyze reports)
  report::DropoutAnalysis dropout;
};

/// Writes dropout.<ext> and dropout.csv into `directory`. CSV columns
/// entry,index,rank,n_vectors,pbar_min,max_worst_case_error_deg,worst_x,worst_y,worst_z,certified:
/// one row per removed entry in order of harm (rank 1 = most harmful; entry "p3" or "v3"), then
/// the row "intact" (index -1, rank 0) of the reference line; entry is the entry's name when the
/// layout names them. certified is 1 or 0.
/// Throws InvalidArgument on bad data or options, RenderError when drawing or writing fails.
FigureFiles write_dropout_chart(const DropoutChartData& data,
                                const std::filesystem::path& directory,
                                const FigureOptions& options = {});

}  // namespace vantage::plot
