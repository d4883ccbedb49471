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
constexpr double kCountLabelledFraction = 0.004;
// Untrackable cells keep this much of their count's colour, the rest white.
constexpr double kWashedOut = 0.45;

Rgb washed(Rgb c) {
  auto mix = [](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::lround(kWashedOut * v + (1.0 - kWashedOut) * 255.0));
  };
  return {mix(c.r), mix(c.g), mix(c.b)};
}

internal::Raster count_raster(const SphereSamples& s, int d, int markers) {
  const int n = s.samples_per_axis;
  internal::Raster raster;
  raster.width = raster.height = n;
  raster.argb.resize(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      Rgb colour = kOutsideWorkspaceColour;
      if (s.in_workspace[d](r, c)) {
        colour = value_colour(s.visible[d](r, c), 0.0, markers);
        if (!s.trackable[d](r, c)) colour = washed(colour);
      }
      raster.argb[static_cast<std::size_t>(r) * n + c] = internal::opaque_argb(colour);
    }
  }
  return raster;
}

// A vertical bar of the counts 0..markers, one step each, numbers on its right.
void draw_count_bar(Canvas& canvas, double vx0, double vx1, double vy0, double vy1, int markers) {
  const int steps = markers + 1;
  // Rows per step: the bilinear filter blurs only the edge of each step.
  constexpr int kRowsPerStep = 32;
  Eigen::MatrixXd ramp(steps * kRowsPerStep, 1);
  for (int i = 0; i < ramp.rows(); ++i) ramp(i, 0) = markers - i / kRowsPerStep;
  plstream& pls = canvas.pls();
  pls.vpor(vx0, vx1, vy0, vy1);
  pls.wind(0.0, 1.0, -0.5, markers + 0.5);
  internal::Raster raster = internal::value_raster(ramp, 0.0, markers);
  canvas.paint_raster(raster, 0.0, 1.0, -0.5, markers + 0.5);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.col0(internal::kPenInk);
  pls.width(1.0);
  const double tick = markers <= 16 ? 1.0 : std::ceil(markers / 12.0);
  pls.box("bc", 0.0, 0, "bcmstv", tick, 1);
  internal::set_text_size(canvas, internal::kLabelSize);
  pls.mtex("r", 4.2, 0.5, 0.5, "markers visible");
}

void write_count_csv(const VisibilityMapData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "disc,x,y,z,visible,trackable,in_workspace,markers");
  const auto& workspace = data.model->problem().workspace;
  internal::for_each_csv_cell(
      data, [&](int d, const Eigen::Vector3d& a, const visibility::DirectionVisibility& v) {
        std::string markers;
        for (int i : v.visible) markers += (markers.empty() ? "" : " ") + std::to_string(i);
        const bool inside = !workspace || a.dot(workspace->axis) >= workspace->cos_half_angle;
        csv << d << a.x() << a.y() << a.z() << static_cast<long>(v.visible.size())
            << (v.trackable ? 1 : 0) << (inside ? 1 : 0) << markers;
        csv.end_row();
      });
  csv.commit();
}

void draw_legend(Canvas& canvas, const VisibilityMapData& data, const SphereSamples& samples) {
  using internal::fixed;
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const visibility::VisibilityReport& report = *data.report;
  std::vector<Entry> left{Entry::line("trackable boundary (" + std::to_string(report.min_visible) +
                                          " markers seen, not in a line)",
                                      {255, 255, 255}, 2.0 * s),
                          Entry::marker("untrackable side: colours washed out",
                                        washed(value_colour(0.5)), Canvas::Shape::kSquare)};
  if (report.workspace) {
    left.push_back(
        Entry::marker("outside the workspace", kOutsideWorkspaceColour, Canvas::Shape::kSquare));
  }
  if (report.worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
    left.push_back(Entry::marker("worst viewpoint: " + internal::worst_summary(report),
                                 kWorstViewpointColour));
  }
  canvas.legend(0.02, 0.215, left, internal::kSmallSize * s, 0.0);
  const std::vector<Entry> right{
      Entry::text_only("trackable: " + fixed(100.0 * report.coverage.trackable_fraction, 1) +
                       " % of " + (report.workspace ? "the workspace" : "the sphere")),
      Entry::text_only("on this map: " + fixed(100.0 * samples.trackable_fraction(), 1) + " %"),
      Entry::text_only(report.with_body
                           ? "cones and body mesh, occlusion at " +
                                 fixed(report.occlusion_resolution_deg.value_or(0.0), 2) + "°"
                           : "cones only (no body mesh)")};
  canvas.legend(0.98, 0.215, right, internal::kSmallSize * s, 1.0);
}

void draw_figure(Canvas& canvas, const VisibilityMapData& data, const SphereSamples& samples,
                 const FigureOptions& options) {
  const int markers = static_cast<int>(data.model->problem().points.cols());
  internal::draw_title(
      canvas,
      internal::figure_title(options,
                             "Visible markers: " + internal::layout_label(data.layout_name)),
      "how many of the " + std::to_string(markers) +
          " markers each viewing direction a sees (body → camera); Lambert equal-area");
  for (int d = 0; d < 2; ++d) internal::paint_disc(canvas, d, count_raster(samples, d, markers));
  internal::draw_count_boundaries(canvas, samples, 0.5, internal::kPenGrid);
  internal::draw_trackable_boundary(canvas, samples);
  for (int d = 0; d < 2; ++d) internal::draw_disc_frame(canvas, d);
  internal::label_count_regions(canvas, samples, kCountLabelledFraction);
  const visibility::VisibilityReport& report = *data.report;
  if (report.worst.status != visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
    const double s = internal::page_scale(canvas);
    for (const Eigen::Vector3d& a : report.worst.viewpoints) {
      internal::mark_direction(canvas, a, 5.0 * s, kWorstViewpointColour);
    }
  }
  draw_count_bar(canvas, 0.905, 0.925, 0.30, 0.84, markers);
  draw_legend(canvas, data, samples);
}

}  // namespace

FigureFiles write_visibility_figure(const VisibilityMapData& data,
                                    const std::filesystem::path& directory,
                                    const FigureOptions& options) {
  internal::check_map_data(data, "visibility_figure");
  std::unique_ptr<SphereSamples> owned;
  const SphereSamples& samples = internal::picture_samples(data, options, &owned);
  const FigureFiles files = figure_files("visibility", directory, options.format);
  Canvas canvas(files.image, options);
  draw_figure(canvas, data, samples, options);
  canvas.finish();
  write_count_csv(data, files.csv);
  return files;
}

}  // namespace vantage::plot
