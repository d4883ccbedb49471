#include "vantage/plot/layout_figures.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/plot/dropout_chart.h"
#include "vantage/plot/error_surface.h"
#include "vantage/plot/vectors_figure.h"
#include "vantage/plot/viewpoint_map.h"

namespace vantage::plot {
namespace {

constexpr int kMinLayoutMapSamples = 400;

bool wants(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

bool is_figure_name(const std::string& name) {
  return std::find(kFigureNames.begin(), kFigureNames.end(), name) != kFigureNames.end();
}

bool LayoutFiguresOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!figure.is_valid(&inner)) {
    if (why) *why = "figure." + inner;
    return false;
  }
  if (!(threshold_deg > 0.0 && threshold_deg < 90.0)) {
    if (why) *why = "threshold_deg must be in (0, 90) degrees";
    return false;
  }
  if (map_samples < kMinLayoutMapSamples || map_samples > kMaxMapSamples) {
    if (why) *why = "map_samples must be in [400, 4000]";
    return false;
  }
  return true;
}

std::vector<std::string> selected_figures(const LayoutFiguresOptions& options, bool has_design) {
  if (options.only.empty()) {
    std::vector<std::string> all;
    for (const char* name : kFigureNames) {
      if (has_design || std::string(name) != "design") all.push_back(name);
    }
    return all;
  }
  for (std::size_t k = 0; k < options.only.size(); ++k) {
    const std::string& name = options.only[k];
    if (!is_figure_name(name)) {
      throw InvalidArgument("only: unknown figure \"" + name +
                            "\" (viewpoint_map, dropout, error_surface, vectors, design)");
    }
    if (std::find(options.only.begin(), options.only.begin() + k, name) !=
        options.only.begin() + k) {
      throw InvalidArgument("only", "figure \"" + name + "\" given twice");
    }
    if (name == "design" && !has_design) {
      throw InvalidArgument("only", "the design figure needs a design result");
    }
  }
  std::vector<std::string> ordered;
  for (const char* name : kFigureNames) {
    if (wants(options.only, name)) ordered.push_back(name);
  }
  return ordered;
}

bool needs_dropout(const LayoutFiguresOptions& options, bool has_design) {
  return wants(selected_figures(options, has_design), "dropout");
}

LayoutFigures write_layout_figures(const sdp::LayoutReport& report,
                                   const std::filesystem::path& directory,
                                   const LayoutFiguresOptions& options, const DesignCurve* design) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options", why);
  const std::vector<std::string> names = selected_figures(options, design != nullptr);
  if (wants(names, "dropout") && !report.dropout) {
    throw InvalidArgument("report", "the dropout figure needs the report's dropout analysis");
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec)) {
    throw InvalidArgument("directory", directory.string() + " is not a directory");
  }
  const Layout& layout = report.layout;
  const sdp::LayoutAnalysis& r = report.analysis;
  LayoutFigures result;
  result.pbar_min = r.pbar_min;
  result.max_worst_case_error_deg = r.max_worst_case_error_deg;
  if (!report.is_usable()) result.message = report.message();
  const FigureOptions& figure = options.figure;

  if (wants(names, "viewpoint_map")) {
    ViewpointMapData map;
    map.layout_name = layout.name;
    map.vectors = report.data.vectors;
    map.worst_viewpoints = r.worst_viewpoints;
    map.pbar_min = r.pbar_min;
    map.paper_lmi_viewpoint = r.paper_lmi.viewpoint;
    map.paper_lmi_pbar = r.paper_lmi.pbar_at;
    map.threshold_deg = options.threshold_deg;
    map.samples_per_axis = options.map_samples;
    result.files.push_back(write_viewpoint_map(map, directory, figure));
  }
  if (wants(names, "dropout")) {
    DropoutChartData chart;
    chart.layout_name = layout.name;
    chart.mode = layout.mode;
    chart.intact_pbar_min = r.pbar_min;
    chart.intact_max_error_deg = r.max_worst_case_error_deg;
    chart.dropout = *report.dropout;
    result.files.push_back(write_dropout_chart(chart, directory, figure));
  }
  if (wants(names, "error_surface")) {
    ErrorSurfaceData surface;
    surface.layout_name = layout.name;
    surface.p_at_worst = projected_fractions(report.data.vectors, r.worst_viewpoint);
    result.files.push_back(write_error_surface(surface, directory, figure));
  }
  if (wants(names, "vectors")) {
    VectorsFigureData vectors;
    vectors.layout_name = layout.name;
    vectors.mode = layout.mode;
    vectors.entries = layout.entries;
    vectors.worst_viewpoints = r.worst_viewpoints;
    vectors.pbar_min = r.pbar_min;
    vectors.paper_lmi_viewpoint = r.paper_lmi.viewpoint;
    vectors.paper_lmi_pbar = r.paper_lmi.pbar_at;
    result.files.push_back(write_vectors_figure(vectors, directory, figure));
  }
  if (wants(names, "design")) {
    result.files.push_back(write_design_curve(*design, directory, figure));
  }
  result.status =
      report.is_usable() ? LayoutFigures::Status::kCertified : LayoutFigures::Status::kNotCertified;
  return result;
}

}  // namespace vantage::plot
