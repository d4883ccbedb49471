#include "vantage/plot/dropout_chart.h"

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

// Bars up to this count carry their p-bar_min as text.
constexpr std::size_t kMaxAnnotatedBars = 24;
// Two bars whose errors differ by less than this (degrees) are equally harmful.
constexpr double kHarmTieDeg = 1e-9;

void check_data(const DropoutChartData& data) {
  const std::size_t n = data.dropout.entries.size();
  if (n == 0) throw InvalidArgument("write_dropout_chart: dropout has no entries");
  if (data.names.size() != n) {
    throw InvalidArgument("write_dropout_chart: names needs one per entry");
  }
  if (data.dropout.by_harm.size() != n) {
    throw InvalidArgument("write_dropout_chart: dropout.by_harm must list every entry");
  }
  for (int k : data.dropout.by_harm) {
    if (k < 0 || static_cast<std::size_t>(k) >= n) {
      throw InvalidArgument("write_dropout_chart: dropout.by_harm has an index out of range");
    }
  }
}

void write_csv(const DropoutChartData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path,
                          "entry,index,rank,n_vectors,pbar_min,max_worst_case_error_deg,worst_x,"
                          "worst_y,worst_z,certified");
  long rank = 1;
  for (int k : data.dropout.by_harm) {
    const report::DropoutEntry& e = data.dropout.entries[k];
    csv << data.names[static_cast<std::size_t>(e.index)] << static_cast<long>(e.index) << rank++
        << static_cast<long>(e.n_vectors) << e.worst.pbar_min << e.worst.max_worst_case_error_deg
        << e.worst.viewpoint.x() << e.worst.viewpoint.y() << e.worst.viewpoint.z()
        << static_cast<long>(e.worst.certified ? 1 : 0);
    csv.end_row();
  }
  csv << "intact" << -1 << 0 << -1 << data.intact_pbar_min << data.intact_max_error_deg << 0.0
      << 0.0 << 0.0 << 1;
  csv.end_row();
  csv.commit();
}

void draw_chart(Canvas& canvas, const DropoutChartData& data, const FigureOptions& options) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const auto& entries = data.dropout.entries;
  const std::size_t n = entries.size();
  const char* unit = data.mode == LayoutMode::kPoints ? "marker" : "vector";
  internal::draw_title(
      canvas,
      internal::figure_title(options, "Dropout: " + internal::layout_label(data.layout_name)),
      std::string("worst-case error with one ") + unit +
          " lost (certified global worst viewpoint each time), most harmful first");

  double top = data.intact_max_error_deg;
  for (const report::DropoutEntry& e : entries)
    top = std::max(top, e.worst.max_worst_case_error_deg);
  top = std::min(90.0, std::max(1.0, top * 1.3));
  const double worst_error = entries[data.dropout.by_harm.front()].worst.max_worst_case_error_deg;

  plstream& pls = canvas.pls();
  pls.vpor(0.09, 0.97, 0.14, 0.84);
  pls.wind(0.4, n + 0.6, 0.0, top);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("", 0.0, 0, "g", 0.0, 0);

  const double half = std::min(0.38, 0.5 - 0.5 / (n + 1.0));
  for (std::size_t slot = 0; slot < n; ++slot) {
    const report::DropoutEntry& e = entries[data.dropout.by_harm[slot]];
    const double x = slot + 1.0;
    const double h = e.worst.max_worst_case_error_deg;
    const bool most_harmful = std::abs(h - worst_error) <= kHarmTieDeg;
    const std::vector<double> bx{x - half, x + half, x + half, x - half};
    const std::vector<double> by{0.0, 0.0, h, h};
    canvas.fill_polygon(bx, by, most_harmful ? kWorstViewpointColour : Rgb{49, 104, 142}, 1.0);
    if (n <= kMaxAnnotatedBars) {
      canvas.label(x, h, "p̄ " + fixed(e.worst.pbar_min, 3), 0.0, -10 * s, 0.5,
                   internal::kSmallSize * s * (n > 14 ? 0.8 : 1.0), {25, 25, 25});
    }
    const std::size_t label_every = std::max<std::size_t>(1, n / 40 + 1);
    if (slot % label_every == 0) {
      canvas.label(x, 0.0, internal::page_label(data.names[static_cast<std::size_t>(e.index)]), 0.0,
                   12 * s, 0.5, internal::kSmallSize * s, {25, 25, 25});
    }
  }

  pls.col0(internal::kPenInk);
  pls.width(1.8 * s);
  pls.lsty(2);
  pls.join(0.4, data.intact_max_error_deg, n + 0.6, data.intact_max_error_deg);
  pls.lsty(1);

  internal::draw_axes(canvas, "bc", "bcnstv", 0.0, 0,
                      std::string(unit) + " removed (sorted by harm; p̄ = p̄_min without it)", 3.2,
                      "max worst-case error without it  [deg]", 3.6);

  using Entry = Canvas::LegendEntry;
  canvas.legend(
      0.96, 0.83,
      {Entry::marker(std::string("the ") + unit + "(s) the layout can least afford to lose",
                     kWorstViewpointColour, Canvas::Shape::kSquare),
       Entry::marker(std::string("another ") + unit, {49, 104, 142}, Canvas::Shape::kSquare),
       Entry::line("intact layout: " + fixed(data.intact_max_error_deg, 2) + "°, p̄_min " +
                       fixed(data.intact_pbar_min, 4),
                   {25, 25, 25}, 1.8 * s, true)},
      internal::kSmallSize * s, 1.0);
}

}  // namespace

FigureFiles write_dropout_chart(const DropoutChartData& data,
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
