#include "vantage/plot/visibility_dropout_chart.h"

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {
namespace {

using internal::Canvas;
using Status = visibility::VisibilityWorstViewpoint::Status;

// Bars up to this count carry their p-bar_min as text.
constexpr std::size_t kMaxAnnotatedBars = 24;
// Two bars whose errors differ by less than this (degrees) are equally harmful.
constexpr double kHarmTieDeg = 1e-9;
// The error bars fill at most this fraction of their panel's height.
constexpr double kBarRoom = 0.62;
constexpr Rgb kBarColour{49, 104, 142};
constexpr Rgb kUntrackableBarColour{150, 150, 150};
constexpr Rgb kSeenWholeColour{255, 255, 255};

void check_data(const VisibilityDropoutChartData& data) {
  if (data.report == nullptr) throw InvalidArgument("write_visibility_dropout_chart: no report");
  const auto& entries = data.report->dropout;
  const std::size_t n = entries.size();
  if (n == 0) {
    throw InvalidArgument("write_visibility_dropout_chart: the report has no dropout analysis");
  }
  if (data.names.size() != n) {
    throw InvalidArgument("write_visibility_dropout_chart: names needs one per marker");
  }
  if (data.report->dropout_by_harm.size() != n) {
    throw InvalidArgument("write_visibility_dropout_chart: dropout_by_harm must list every entry");
  }
  for (int k : data.report->dropout_by_harm) {
    if (k < 0 || static_cast<std::size_t>(k) >= n) {
      throw InvalidArgument("write_visibility_dropout_chart: dropout_by_harm out of range");
    }
  }
  if (!data.seen_whole_error_deg.empty() && data.seen_whole_error_deg.size() != n) {
    throw InvalidArgument(
        "write_visibility_dropout_chart: seen_whole_error_deg needs one per marker");
  }
}

double seen_whole(const VisibilityDropoutChartData& data, int lost) {
  return data.seen_whole_error_deg.empty()
             ? -1.0
             : data.seen_whole_error_deg[static_cast<std::size_t>(lost)];
}

void write_csv(const VisibilityDropoutChartData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path,
                          "entry,index,rank,status,pbar_min,max_worst_case_error_deg,"
                          "trackable_fraction,seen_whole_error_deg");
  const visibility::VisibilityReport& report = *data.report;
  long rank = 1;
  for (int k : report.dropout_by_harm) {
    const visibility::VisibilityDropoutEntry& e = report.dropout[static_cast<std::size_t>(k)];
    csv << data.names[static_cast<std::size_t>(e.lost)] << static_cast<long>(e.lost) << rank++
        << report.entry_status(e) << e.pbar_min << e.max_worst_case_error_deg
        << e.trackable_fraction;
    const double whole = seen_whole(data, e.lost);
    if (whole >= 0.0) {
      csv << whole;
    } else {
      csv << "";
    }
    csv.end_row();
  }
  csv << "intact" << -1 << 0 << report.certificate_status() << report.worst.pbar_min
      << report.max_worst_case_error_deg << report.coverage.trackable_fraction << "";
  csv.end_row();
  csv.commit();
}

void bar(Canvas& canvas, double x, double half, double y0, double y1, Rgb colour) {
  canvas.fill_polygon({x - half, x + half, x + half, x - half}, {y0, y0, y1, y1}, colour, 1.0);
}

void dashed_level(Canvas& canvas, double x0, double x1, double y) {
  canvas.pls().col0(internal::kPenInk);
  canvas.pls().width(1.8 * internal::page_scale(canvas));
  canvas.pls().lsty(2);
  canvas.pls().join(x0, y, x1, y);
  canvas.pls().lsty(1);
}

void draw_error_panel(Canvas& canvas, const VisibilityDropoutChartData& data, double half) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const visibility::VisibilityReport& report = *data.report;
  const std::size_t n = report.dropout.size();
  double top = report.max_worst_case_error_deg;
  for (const visibility::VisibilityDropoutEntry& e : report.dropout) {
    top = std::max(top, e.max_worst_case_error_deg);
  }
  // The legend takes the panel's top third: the bars stay below it.
  top = std::min(90.0 / kBarRoom, std::max(1.0, top / kBarRoom));
  const double worst = report.dropout[static_cast<std::size_t>(report.dropout_by_harm.front())]
                           .max_worst_case_error_deg;
  plstream& pls = canvas.pls();
  pls.vpor(0.09, 0.97, 0.42, 0.84);
  pls.wind(0.4, n + 0.6, 0.0, top);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("", 0.0, 0, "g", 0.0, 0);
  const double text = internal::kSmallSize * s * (n > 14 ? 0.8 : 1.0);
  for (std::size_t slot = 0; slot < n; ++slot) {
    const visibility::VisibilityDropoutEntry& e =
        report.dropout[static_cast<std::size_t>(report.dropout_by_harm[slot])];
    const double x = slot + 1.0;
    const bool untrackable = e.status == Status::kUntrackable;
    const double h = std::min(top, e.max_worst_case_error_deg);
    const bool most = std::abs(e.max_worst_case_error_deg - worst) <= kHarmTieDeg;
    bar(canvas, x, half, 0.0, h,
        untrackable ? kUntrackableBarColour
        : most      ? kWorstViewpointColour
                    : kBarColour);
    if (n <= kMaxAnnotatedBars) {
      const std::string note = untrackable                         ? "lost"
                               : e.status == Status::kNotCertified ? "not cert."
                                                                   : "p̄ " + fixed(e.pbar_min, 3);
      canvas.label(x, h, note, 0.0, -10 * s, 0.5, text, {25, 25, 25});
    }
    const double whole = seen_whole(data, e.lost);
    if (whole >= 0.0) canvas.marker(x, whole, 4.5 * s, kSeenWholeColour, Canvas::Shape::kDiamond);
  }
  dashed_level(canvas, 0.4, n + 0.6, report.max_worst_case_error_deg);
  internal::draw_axes(canvas, "bc", "bcnstv", 0.0, 0, "", 0.0, "max worst-case error  [deg]", 3.6);
}

void draw_trackable_panel(Canvas& canvas, const VisibilityDropoutChartData& data, double half) {
  const double s = internal::page_scale(canvas);
  const visibility::VisibilityReport& report = *data.report;
  const std::size_t n = report.dropout.size();
  double lowest = report.coverage.trackable_fraction;
  for (const visibility::VisibilityDropoutEntry& e : report.dropout) {
    lowest = std::min(lowest, e.trackable_fraction);
  }
  const double lo = std::max(0.0, 10.0 * std::floor(10.0 * lowest - 0.5));
  plstream& pls = canvas.pls();
  pls.vpor(0.09, 0.97, 0.12, 0.34);
  pls.wind(0.4, n + 0.6, lo, 100.0);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("", 0.0, 0, "g", 0.0, 0);
  const std::size_t label_every = std::max<std::size_t>(1, n / 40 + 1);
  for (std::size_t slot = 0; slot < n; ++slot) {
    const visibility::VisibilityDropoutEntry& e =
        report.dropout[static_cast<std::size_t>(report.dropout_by_harm[slot])];
    const double x = slot + 1.0;
    const double h = std::max(lo, 100.0 * e.trackable_fraction);
    bar(canvas, x, half, lo, h,
        e.status == Status::kUntrackable ? kUntrackableBarColour : kBarColour);
    if (n <= kMaxAnnotatedBars) {
      canvas.label(x, h, internal::fixed(100.0 * e.trackable_fraction, 1), 0.0, -10 * s, 0.5,
                   internal::kSmallSize * s * (n > 14 ? 0.8 : 1.0), {25, 25, 25});
    }
    if (slot % label_every == 0) {
      canvas.label(x, lo, internal::page_label(data.names[static_cast<std::size_t>(e.lost)]), 0.0,
                   12 * s, 0.5, internal::kSmallSize * s, {25, 25, 25});
    }
  }
  dashed_level(canvas, 0.4, n + 0.6, 100.0 * report.coverage.trackable_fraction);
  internal::draw_axes(canvas, "bc", "bcnstv", 0.0, 0,
                      "marker lost (sorted by harm: error, then trackable fraction)", 3.2,
                      "trackable  [%]", 3.6);
}

void draw_chart(Canvas& canvas, const VisibilityDropoutChartData& data,
                const FigureOptions& options) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const visibility::VisibilityReport& report = *data.report;
  internal::draw_title(
      canvas,
      internal::figure_title(options,
                             "Dropout on the body: " + internal::layout_label(data.layout_name)),
      "one marker lost: the certified worst-case error with the markers visible from each "
      "direction, and the trackable part of " +
          std::string(report.workspace ? "the workspace" : "the sphere"));
  const std::size_t n = report.dropout.size();
  const double half = std::min(0.38, 0.5 - 0.5 / (n + 1.0));
  draw_error_panel(canvas, data, half);
  draw_trackable_panel(canvas, data, half);

  using Entry = Canvas::LegendEntry;
  std::vector<Entry> legend{
      Entry::marker("the marker(s) the layout can least afford to lose", kWorstViewpointColour,
                    Canvas::Shape::kSquare),
      Entry::marker("another marker", kBarColour, Canvas::Shape::kSquare),
      Entry::marker("lost: no direction trackable without it", kUntrackableBarColour,
                    Canvas::Shape::kSquare),
      Entry::line("intact: " + fixed(report.max_worst_case_error_deg, 2) + "°, " +
                      fixed(100.0 * report.coverage.trackable_fraction, 1) + " % trackable",
                  {25, 25, 25}, 1.8 * s, true)};
  if (!data.seen_whole_error_deg.empty()) {
    legend.push_back(Entry::marker("seen whole without it (every marker from everywhere)",
                                   kSeenWholeColour, Canvas::Shape::kDiamond));
  }
  canvas.legend(0.965, 0.835, legend, internal::kSmallSize * s, 1.0);
}

}  // namespace

FigureFiles write_visibility_dropout_chart(const VisibilityDropoutChartData& data,
                                           const std::filesystem::path& directory,
                                           const FigureOptions& options) {
  check_data(data);
  const FigureFiles files = figure_files("dropout", directory, options.format);
  Canvas canvas(files.image, options);
  draw_chart(canvas, data, options);
  canvas.finish();
  write_csv(data, files.csv);
  return files;
}

}  // namespace vantage::plot
