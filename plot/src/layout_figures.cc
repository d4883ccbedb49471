#include "vantage/plot/layout_figures.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/plot/dropout_chart.h"
#include "vantage/plot/error_surface.h"
#include "vantage/plot/placement_figure.h"
#include "vantage/plot/vectors_figure.h"
#include "vantage/plot/viewpoint_map.h"
#include "vantage/plot/visibility_dropout_chart.h"
#include "vantage/plot/visibility_maps.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::plot {
namespace {

constexpr int kMinLayoutMapSamples = 400;

bool wants(const std::vector<std::string>& names, const char* name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool applies(const char* name, bool has_design, bool has_visibility, bool has_placement) {
  const std::string n = name;
  return (has_design || n != "design") && (has_visibility || n != "visibility") &&
         (has_placement || n != "placement");
}

FigureFiles write_placement(const report::LayoutReport& report,
                            const std::filesystem::path& directory, const FigureOptions& options) {
  const Layout& layout = report.layout;
  PlacementFigureData data;
  data.layout_name = layout.name;
  data.placement = *layout.placement;
  data.sensor = layout.sensor;
  data.markers = layout.entries;
  if (layout.visibility) {
    data.normals = layout.visibility->normals;
    if (layout.visibility->body) data.body = &*layout.visibility->body;
  } else {
    data.normals = Eigen::Matrix3Xd::Zero(3, layout.entries.cols());
  }
  if (report.visibility) {
    const visibility::VisibilityWorstViewpoint& worst = report.visibility->worst;
    const bool trackable =
        worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable;
    data.pbar_min = trackable ? worst.pbar_min : 0.0;
    data.coverage = report.visibility->coverage.trackable_fraction;
  }
  return write_placement_figure(data, directory, options);
}

// The seen-whole dropout error of each marker, when the report has it.
std::vector<double> seen_whole_dropout(const report::LayoutReport& report) {
  if (!report.dropout) return {};
  std::vector<double> out(static_cast<std::size_t>(report.layout.entries.cols()), -1.0);
  for (const report::DropoutEntry& e : report.dropout->entries) {
    if (e.index >= 0 && static_cast<std::size_t>(e.index) < out.size()) {
      out[static_cast<std::size_t>(e.index)] = e.worst.max_worst_case_error_deg;
    }
  }
  return out;
}

// The figures of a layout on its body that need its visibility at every direction.
void write_body_maps(const report::LayoutReport& report, const std::filesystem::path& directory,
                     const LayoutFiguresOptions& options, const std::vector<std::string>& names,
                     std::vector<FigureFiles>* files) {
  const bool map = wants(names, "viewpoint_map"), count = wants(names, "visibility");
  if (!map && !count) return;
  const visibility::VisibilityReport& visibility = *report.visibility;
  const visibility::VisibilityModel model =
      visibility::VisibilityModel::of(report.layout,
                                      visibility.occlusion_resolution_deg.value_or(
                                          visibility::VisibilityModel::kDefaultResolutionDeg),
                                      options.figure.threads);
  const SphereSamples samples = sample_sphere(model, options.map_samples, options.figure.threads);
  VisibilityMapData data;
  data.layout_name = report.layout.name;
  data.model = &model;
  data.report = &visibility;
  data.seen_whole_max_error_deg = report.analysis.max_worst_case_error_deg;
  data.samples_per_axis = options.map_samples;
  data.samples = &samples;
  if (map) files->push_back(write_visibility_viewpoint_map(data, directory, options.figure));
  if (count) files->push_back(write_visibility_figure(data, directory, options.figure));
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

std::vector<std::string> selected_figures(const LayoutFiguresOptions& options, bool has_design,
                                          bool has_visibility, bool has_placement) {
  if (options.only.empty()) {
    std::vector<std::string> all;
    for (const char* name : kFigureNames) {
      if (applies(name, has_design, has_visibility, has_placement)) all.push_back(name);
    }
    return all;
  }
  for (std::size_t k = 0; k < options.only.size(); ++k) {
    const std::string& name = options.only[k];
    if (!is_figure_name(name)) {
      throw InvalidArgument("only: unknown figure \"" + name +
                            "\" (viewpoint_map, visibility, dropout, error_surface, vectors, "
                            "placement, design)");
    }
    if (std::find(options.only.begin(), options.only.begin() + k, name) !=
        options.only.begin() + k) {
      throw InvalidArgument("only", "figure \"" + name + "\" given twice");
    }
    if (name == "design" && !has_design) {
      throw InvalidArgument("only", "the design figure needs a design result");
    }
    if (name == "visibility" && !has_visibility) {
      throw InvalidArgument("only", "the visibility figure needs a layout with normals");
    }
    if (name == "placement" && !has_placement) {
      throw InvalidArgument("only", "the placement figure needs a layout written by vantage place");
    }
  }
  std::vector<std::string> ordered;
  for (const char* name : kFigureNames) {
    if (wants(options.only, name)) ordered.push_back(name);
  }
  return ordered;
}

bool needs_dropout(const LayoutFiguresOptions& options, bool has_design, bool has_visibility,
                   bool has_placement) {
  return wants(selected_figures(options, has_design, has_visibility, has_placement), "dropout");
}

namespace {

/// The viewpoint map of a layout without a body.
FigureFiles write_free_viewpoint_map(const report::LayoutReport& report,
                                     const std::filesystem::path& directory,
                                     const LayoutFiguresOptions& options) {
  const Layout& layout = report.layout;
  const sdp::LayoutAnalysis& r = report.analysis;
  ViewpointMapData map;
  map.layout_name = layout.name;
  map.vectors = report.data.vectors;
  map.worst_viewpoints = r.worst_viewpoints;
  map.pbar_min = r.pbar_min;
  map.paper_lmi_viewpoint = r.paper_lmi.viewpoint;
  map.paper_lmi_pbar = r.paper_lmi.pbar_at;
  map.threshold_deg = options.threshold_deg;
  map.samples_per_axis = options.map_samples;
  return write_viewpoint_map(map, directory, options.figure);
}

/// Every entry's name as the layout gives it (Layout::entry_name).
std::vector<std::string> entry_names(const Layout& layout) {
  std::vector<std::string> out;
  for (Eigen::Index k = 0; k < layout.entries.cols(); ++k) out.push_back(layout.entry_name(k));
  return out;
}

/// The dropout chart: on the body (seen whole beside it) or of the data vectors.
FigureFiles write_dropout(const report::LayoutReport& report,
                          const std::filesystem::path& directory, const FigureOptions& figure) {
  const Layout& layout = report.layout;
  const sdp::LayoutAnalysis& r = report.analysis;
  if (report.visibility.has_value()) {
    VisibilityDropoutChartData chart;
    chart.layout_name = layout.name;
    chart.names = entry_names(layout);
    chart.report = &*report.visibility;
    chart.seen_whole_error_deg = seen_whole_dropout(report);
    return write_visibility_dropout_chart(chart, directory, figure);
  }
  DropoutChartData chart;
  chart.layout_name = layout.name;
  chart.mode = layout.mode;
  chart.names = entry_names(layout);
  chart.intact_pbar_min = r.pbar_min;
  chart.intact_max_error_deg = r.max_worst_case_error_deg;
  chart.dropout = *report.dropout;
  return write_dropout_chart(chart, directory, figure);
}

/// The figure of the data vectors with the worst viewpoints (and the body's, on a body).
FigureFiles write_vectors(const report::LayoutReport& report,
                          const std::filesystem::path& directory, const FigureOptions& figure) {
  const Layout& layout = report.layout;
  const sdp::LayoutAnalysis& r = report.analysis;
  const bool on_body = report.visibility.has_value();
  VectorsFigureData vectors;
  vectors.layout_name = layout.name;
  vectors.mode = layout.mode;
  vectors.entries = layout.entries;
  vectors.names = entry_names(layout);
  vectors.worst_viewpoints = r.worst_viewpoints;
  vectors.pbar_min = r.pbar_min;
  vectors.paper_lmi_viewpoint = r.paper_lmi.viewpoint;
  vectors.paper_lmi_pbar = r.paper_lmi.pbar_at;
  if (on_body) {
    const visibility::VisibilityReport& v = *report.visibility;
    vectors.normals = layout.visibility->normals;
    if (layout.visibility->body) vectors.body = &*layout.visibility->body;
    if (v.worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
      vectors.body_worst_viewpoint = v.worst.viewpoint;
      vectors.body_visible_markers = v.worst.visible_markers;
      vectors.body_max_error_deg = v.max_worst_case_error_deg;
    }
  }
  return write_vectors_figure(vectors, directory, figure);
}

}  // namespace

LayoutFigures write_layout_figures(const report::LayoutReport& report,
                                   const std::filesystem::path& directory,
                                   const LayoutFiguresOptions& options, const DesignCurve* design) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options", why);
  const bool on_body = report.visibility.has_value();
  const std::vector<std::string> names =
      selected_figures(options, design != nullptr, on_body, report.layout.placement.has_value());
  if (wants(names, "dropout") && (on_body ? report.visibility->dropout.empty() : !report.dropout)) {
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
  if (on_body) {
    result.visibility_max_worst_case_error_deg = report.visibility->max_worst_case_error_deg;
    result.trackable_fraction = report.visibility->coverage.trackable_fraction;
    result.with_body = report.visibility->with_body;
  }
  if (!report.is_usable()) result.message = report.message();
  const FigureOptions& figure = options.figure;

  if (on_body) {
    write_body_maps(report, directory, options, names, &result.files);
  } else if (wants(names, "viewpoint_map")) {
    result.files.push_back(write_free_viewpoint_map(report, directory, options));
  }
  if (wants(names, "dropout")) result.files.push_back(write_dropout(report, directory, figure));
  if (wants(names, "error_surface")) {
    ErrorSurfaceData surface;
    surface.layout_name = layout.name;
    surface.p_at_worst = projected_fractions(report.data.vectors, r.worst_viewpoint);
    surface.seen_whole_of_a_body = report.visibility.has_value();
    result.files.push_back(write_error_surface(surface, directory, figure));
  }
  if (wants(names, "vectors")) {
    result.files.push_back(write_vectors(report, directory, figure));
  }
  if (wants(names, "placement")) result.files.push_back(write_placement(report, directory, figure));
  if (wants(names, "design")) {
    result.files.push_back(write_design_curve(*design, directory, figure));
  }
  result.status =
      report.is_usable() ? LayoutFigures::Status::kCertified : LayoutFigures::Status::kNotCertified;
  return result;
}

}  // namespace vantage::plot
