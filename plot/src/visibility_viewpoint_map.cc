#include <algorithm>
#include <cmath>
#include <memory>

#include "canvas.h"
#include "output_file.h"
#include "sphere_map_drawing.h"
#include "style.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/visibility_maps.h"
#include "visibility_map_data.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

// Count regions smaller than this fraction of a disc carry no number (too small to read).
constexpr double kErrorLabelledFraction = 0.006;

// The error of each trackable cell on the value map, grey elsewhere.
internal::Raster error_raster(const SphereSamples& s, int d, double hi) {
  return internal::trackable_raster(s, d, [&](int r, int c) {
    return value_colour(internal::visibility_error_deg(s.t[d](r, c)), 0.0, hi);
  });
}

void write_error_csv(const VisibilityMapData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "disc,x,y,z,visible,trackable,pbar,max_error_deg");
  internal::for_each_csv_cell(
      data, [&](int d, const Eigen::Vector3d& a, const visibility::DirectionVisibility& v) {
        csv << d << a.x() << a.y() << a.z() << static_cast<long>(v.visible.size())
            << (v.trackable ? 1 : 0);
        if (v.trackable) {
          csv << std::sqrt(std::max(0.0, 1.0 - v.t * v.t)) << internal::visibility_error_deg(v.t);
        } else {
          csv << ""
              << "";
        }
        csv.end_row();
      });
  csv.commit();
}

std::string percent(double fraction) { return internal::fixed(100.0 * fraction, 1) + " %"; }

void draw_legends(Canvas& canvas, const VisibilityMapData& data, const SphereSamples& samples) {
  using internal::fixed;
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const visibility::VisibilityReport& report = *data.report;
  const std::size_t ties = report.worst.viewpoints.size();
  std::vector<Entry> left;
  if (report.worst.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
    left.push_back(Entry::text_only("no direction of the workspace is trackable"));
  } else {
    left.push_back(
        Entry::marker(std::string(!report.worst.certified() ? "NOT certified"
                                  : report.with_body        ? "grid-certified"
                                                            : "certified") +
                          (ties > 1 ? " worst viewpoints (" + std::to_string(ties) + " tied)"
                                    : " worst viewpoint"),
                      kWorstViewpointColour));
    left.push_back(Entry::text_only(internal::worst_summary(report)));
  }
  left.push_back(Entry::marker("untrackable: fewer than " + std::to_string(report.min_visible) +
                                   " markers seen, or all in a line",
                               kUntrackableColour, Canvas::Shape::kSquare));
  if (report.workspace) {
    left.push_back(Entry::marker(
        "outside the workspace (" + fixed(report.workspace->half_angle_deg, 0) + "° cone)",
        kOutsideWorkspaceColour, Canvas::Shape::kSquare));
  }
  left.push_back(
      Entry::line("visible-marker count changes (numbers: markers seen)", {25, 25, 25}, 1.0 * s));
  canvas.legend(0.02, 0.215, left, internal::kSmallSize * s, 0.0);

  std::vector<Entry> right{
      Entry::text_only("trackable: " + percent(report.coverage.trackable_fraction) + " of " +
                       (report.workspace ? "the workspace" : "the sphere") + " (" +
                       std::to_string(report.coverage.samples) + " directions)"),
      Entry::text_only("on this map: " + percent(samples.trackable_fraction()))};
  if (data.seen_whole_max_error_deg >= 0.0) {
    right.push_back(Entry::text_only("seen whole (every marker from everywhere): " +
                                     fixed(data.seen_whole_max_error_deg, 2) + "°"));
  }
  right.push_back(Entry::text_only(
      report.with_body ? "cones and body mesh, occlusion at " +
                             fixed(report.occlusion_resolution_deg.value_or(0.0), 2) + "°"
                       : "cones only (no body mesh)"));
  canvas.legend(0.98, 0.215, right, internal::kSmallSize * s, 1.0);
}

void draw_worst(Canvas& canvas, const visibility::VisibilityReport& report) {
  if (report.worst.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) return;
  const double s = internal::page_scale(canvas);
  for (const Eigen::Vector3d& a : report.worst.viewpoints) {
    internal::mark_direction(canvas, a, 6.5 * s, kWorstViewpointColour);
  }
  const SphereMapPoint p = sphere_map_from_direction(report.worst.viewpoint);
  internal::select_disc(canvas, p.disc);
  canvas.label(p.xy.x(), p.xy.y(), internal::fixed(report.max_worst_case_error_deg, 2) + "°", 0.0,
               -19 * s, 0.5, internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.85);
}

void draw_map(Canvas& canvas, const VisibilityMapData& data, const SphereSamples& samples,
              const FigureOptions& options) {
  const visibility::VisibilityReport& report = *data.report;
  internal::draw_title(
      canvas,
      internal::figure_title(
          options, "Viewpoint map on the body: " + internal::layout_label(data.layout_name)),
      "worst-case error asin t(a) with the markers visible from a, for every viewing direction a "
      "(body → camera); Lambert equal-area");
  const double hi = std::max(report.max_worst_case_error_deg, 1e-6);
  for (int d = 0; d < 2; ++d) internal::paint_disc(canvas, d, error_raster(samples, d, hi));
  internal::draw_count_boundaries(canvas, samples, 0.9, internal::kPenInk);
  for (int d = 0; d < 2; ++d) internal::draw_disc_frame(canvas, d);
  internal::label_count_regions(canvas, samples, kErrorLabelledFraction);
  draw_worst(canvas, report);
  internal::draw_colour_bar(canvas, 0.905, 0.925, 0.30, 0.84, 0.0, hi,
                            "worst-case error asin t(a)  [deg]");
  draw_legends(canvas, data, samples);
}

}  // namespace

FigureFiles write_visibility_viewpoint_map(const VisibilityMapData& data,
                                           const std::filesystem::path& directory,
                                           const FigureOptions& options) {
  internal::check_map_data(data, "visibility_viewpoint_map");
  std::unique_ptr<SphereSamples> owned;
  const SphereSamples& samples = internal::picture_samples(data, options, &owned);
  const FigureFiles files = figure_files("viewpoint_map", directory, options.format);
  Canvas canvas(files.image, options);
  draw_map(canvas, data, samples, options);
  canvas.finish();
  write_error_csv(data, files.csv);
  return files;
}

}  // namespace vantage::plot
