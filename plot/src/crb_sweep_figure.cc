// The CRB distance sweep (crb_figures.h): rot_rms and trans_rms against the camera distance at
// the worst and at the median direction of each distance, two panels with log y axes.

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/crb_figures.h"

namespace vantage::plot {
namespace {

using camera::PoseCrbMap;
using camera::PoseCrbSweepRow;
using internal::Canvas;

constexpr Rgb kMedianColour{31, 120, 180};  // blue: the median direction
// Smallest value a log axis shows (a bound is never this small at a real distance).
constexpr double kSmallest = 1e-12;
constexpr double kMarkerPx = 3.5;
// The two panels (page fractions): side by side under the title.
constexpr internal::Viewport kPanels[2] = {{0.08, 0.39, 0.12, 0.70}, {0.585, 0.39, 0.12, 0.70}};

// A direction's columns; its values are empty where the bound is unbounded (§22).
void write_direction(internal::CsvWriter& csv, const camera::PoseCrbAt& at, bool ok) {
  if (!ok) {
    for (int k = 0; k < 5; ++k) csv << "";
    return;
  }
  csv << at.direction.x() << at.direction.y() << at.direction.z();
  if (at.unbounded) {
    csv << ""
        << "";
  } else {
    csv << at.rot_rms_deg << at.trans_rms;
  }
}

void write_csv(const std::vector<PoseCrbSweepRow>& rows, const std::filesystem::path& path) {
  internal::CsvWriter csv(path,
                          "distance,status,trackable_fraction,worst_x,worst_y,worst_z,"
                          "worst_rot_rms_deg,worst_trans_rms,median_x,median_y,median_z,"
                          "median_rot_rms_deg,median_trans_rms");
  for (const PoseCrbSweepRow& row : rows) {
    const bool ok = row.status == PoseCrbMap::Status::kOk;
    csv << row.distance << camera::to_string(row.status) << row.trackable_fraction;
    write_direction(csv, row.worst, ok);
    write_direction(csv, row.median, ok);
    csv.end_row();
  }
  csv.commit();
}

struct Series {
  std::vector<double> x;
  std::vector<double> ly;  // log10 of the value
};

// The worst (which 0) or median (1) series of rot_rms (quantity 0) or trans_rms (1).
Series series(const std::vector<PoseCrbSweepRow>& rows, int which, int quantity) {
  Series s;
  for (const PoseCrbSweepRow& row : rows) {
    if (row.status != PoseCrbMap::Status::kOk) continue;
    const camera::PoseCrbAt& at = which == 0 ? row.worst : row.median;
    if (at.unbounded) continue;  // no figure past the first-order limit: a gap in the curve
    s.x.push_back(row.distance);
    s.ly.push_back(internal::log_clamped(quantity == 0 ? at.rot_rms_deg : at.trans_rms, kSmallest));
  }
  return s;
}

void draw_panel(Canvas& canvas, const std::vector<PoseCrbSweepRow>& rows, int quantity,
                double camera_distance) {
  const double s = internal::page_scale(canvas);
  const Series worst = series(rows, 0, quantity), median = series(rows, 1, quantity);
  std::vector<double> values;
  for (const Series* series : {&worst, &median}) {
    for (double ly : series->ly) values.push_back(std::pow(10.0, ly));
  }
  const internal::Decades y = internal::decades(values, kSmallest);
  const double x0 = rows.front().distance, x1 = rows.back().distance;
  const double pad = 0.04 * (x1 - x0);
  const internal::Viewport& v = kPanels[quantity];
  plstream& pls = canvas.pls();
  pls.vpor(v.left, v.left + v.width, v.bottom, v.bottom + v.height);
  pls.wind(x0 - pad, x1 + pad, y.lo, y.hi);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("bcgt", 0.0, 0, "bcglt", 0.0, 0);
  internal::LegendPlacer placer(x0 - pad, x1 + pad, y.lo, y.hi, v);
  using Entry = Canvas::LegendEntry;
  const std::pair<const Series*, Rgb> drawn[] = {{&worst, kWorstViewpointColour},
                                                 {&median, kMedianColour}};
  const double d = camera_distance;
  if (d >= x0 - pad && d <= x1 + pad) {
    internal::draw_line(canvas, {d, d}, {y.lo, y.hi}, {120, 120, 120}, 1.2, true);
    // At the foot of the line: the legend takes a top corner.
    canvas.label(d, y.lo, "D of the map", 4 * s, -18 * s, 0.0, internal::kSmallSize * s,
                 {90, 90, 90});
  }
  for (const auto& [series, colour] : drawn) {
    internal::draw_line(canvas, series->x, series->ly, colour, 2.0);
    placer.add_line(series->x, series->ly);
    for (std::size_t k = 0; k < series->x.size(); ++k) {
      canvas.marker(series->x[k], series->ly[k], kMarkerPx * s, colour);
    }
  }
  internal::draw_axes(canvas, "bcnst", "bcnstlv", 0.0, 0, "camera distance D  [layout units]", 3.2,
                      quantity == 0 ? "rot_rms  [deg]" : "trans_rms  [layout units]", 4.6);
  const auto unbounded = std::count_if(rows.begin(), rows.end(), [](const PoseCrbSweepRow& row) {
    return row.status == PoseCrbMap::Status::kOk && row.worst.unbounded;
  });
  const std::string worst_label = unbounded == 0 ? std::string("worst direction (by rot_rms)")
                                                 : "worst direction: unbounded at " +
                                                       std::to_string(unbounded) + " of " +
                                                       std::to_string(rows.size()) + " D";
  const std::vector<Entry> legend{
      Entry::line_marker(worst_label, kWorstViewpointColour, 2.0 * s, Canvas::Shape::kCircle),
      Entry::line_marker("median direction", kMedianColour, 2.0 * s, Canvas::Shape::kCircle)};
  const auto [lx, ly] = placer.corner(canvas.legend_size(legend, internal::kSmallSize * s));
  canvas.legend(lx, ly, legend, internal::kSmallSize * s);
}

void draw_figure(Canvas& canvas, const std::string& name, const camera::PoseCrbReport& report,
                 const FigureOptions& options) {
  const camera::PoseCrbOptions& camera = report.camera;
  internal::draw_title(canvas,
                       internal::figure_title(options, "Pose Cramér–Rao bound against distance: " +
                                                           internal::layout_label(name)),
                       "at the worst and at the median direction of each distance (its own map); "
                       "pinhole f " +
                           internal::fixed(camera.focal_length, 0) + " px, noise " +
                           internal::fixed(camera.noise_px, 2) + " px per coordinate");
  const std::vector<PoseCrbSweepRow>& rows = report.sweep_distance;
  const bool any = std::any_of(rows.begin(), rows.end(), [](const PoseCrbSweepRow& row) {
    return row.status == PoseCrbMap::Status::kOk;
  });
  if (!any) {
    canvas.pls().vpor(0.0, 1.0, 0.0, 1.0);
    canvas.pls().wind(0.0, 1.0, 0.0, 1.0);
    canvas.label(0.5, 0.5, "no distance of the sweep has a trackable direction", 0.0, 0.0, 0.5,
                 internal::kLabelSize * internal::page_scale(canvas), {25, 25, 25});
    return;
  }
  for (int quantity = 0; quantity < 2; ++quantity)
    draw_panel(canvas, rows, quantity, camera.distance);
}

}  // namespace

FigureFiles write_crb_sweep(const std::string& layout_name, const camera::PoseCrbReport& report,
                            const std::filesystem::path& directory, const FigureOptions& options) {
  if (report.sweep_distance.size() < 2) {
    throw InvalidArgument("sweep_distance", "needs at least 2 distances, got " +
                                                std::to_string(report.sweep_distance.size()));
  }
  const FigureFiles files = figure_files("crb_sweep", directory, options.format);
  Canvas canvas(files.image, options);
  draw_figure(canvas, layout_name, report, options);
  canvas.finish();
  write_csv(report.sweep_distance, files.csv);
  return files;
}

camera::PoseCrbSweep default_crb_sweep(double distance, double radius) {
  return {std::max(0.5 * distance, 1.1 * radius), 2.0 * distance, kDefaultSweepCount};
}

CrbFigures crb_figures(const Layout& layout, const camera::PoseCrbOptions& camera,
                       const CrbFiguresOptions& options) {
  CrbFigures out;
  out.layout_name = layout.name;
  out.model = std::make_shared<const camera::PoseCrbModel>(layout, camera);
  out.report = camera::pose_crb_report(
      layout, camera, std::nullopt,
      options.sweep ? *options.sweep : default_crb_sweep(camera.distance, out.model->radius()),
      options.progress);
  return out;
}

void write_crb_figures(CrbFigures& figures, const CrbFiguresOptions& options,
                       const std::filesystem::path& directory) {
  CrbMapData data;
  data.layout_name = figures.layout_name;
  data.model = figures.model.get();
  data.report = &figures.report;
  data.samples_per_axis = options.samples_per_axis;
  data.csv_samples_per_axis = options.csv_samples_per_axis;
  figures.files.push_back(write_crb_map(data, directory, options.figure));
  figures.files.push_back(
      write_crb_sweep(figures.layout_name, figures.report, directory, options.figure));
}

}  // namespace vantage::plot
