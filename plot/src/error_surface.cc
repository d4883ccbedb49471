#include "vantage/plot/error_surface.h"

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

constexpr int kMinSamples = 16;
constexpr int kMaxSamples = 2000;
// Contour levels of theta, degrees.
constexpr double kContourStepDeg = 10.0;
// Below this p-bar_min the layout's label goes over its line (under it would leave the plot).
constexpr double kLabelBelowAbove = 0.08;

double theta_deg(double p, double pbar) {
  return kDegreesPerRadian * lub_scale_error_angle(p, pbar);
}
double cell_centre(int k, int n) { return (k + 0.5) / n; }

void check_data(const ErrorSurfaceData& data) {
  if (data.samples_per_axis < kMinSamples || data.samples_per_axis > kMaxSamples) {
    throw InvalidArgument("write_error_surface: samples_per_axis must be in [16, 2000]");
  }
  if (data.p_at_worst.size() == 0) {
    throw InvalidArgument("write_error_surface: p_at_worst is empty");
  }
  for (Eigen::Index i = 0; i < data.p_at_worst.size(); ++i) {
    if (!(data.p_at_worst(i) >= 0.0 && data.p_at_worst(i) <= 1.0)) {
      throw InvalidArgument("write_error_surface: p_at_worst[" + std::to_string(i) +
                            "] must be in [0, 1]");
    }
  }
}

// theta on the grid, row 0 at p_bar = 1; cells with p > p_bar take theta(p_bar, p_bar) so that
// the map is continuous up to the clipped diagonal.
Eigen::MatrixXd theta_grid(int n) {
  Eigen::MatrixXd grid(n, n);
  for (int r = 0; r < n; ++r) {
    const double pbar = cell_centre(n - 1 - r, n);
    for (int c = 0; c < n; ++c) grid(r, c) = theta_deg(std::min(cell_centre(c, n), pbar), pbar);
  }
  return grid;
}

void write_csv(const ErrorSurfaceData& data, const Eigen::MatrixXd& grid,
               const std::filesystem::path& path) {
  const int n = data.samples_per_axis;
  const double pbar_min = data.p_at_worst.maxCoeff();
  internal::CsvWriter csv(path, "series,index,p,pbar,theta_deg");
  for (int r = n - 1; r >= 0; --r) {
    const double pbar = cell_centre(n - 1 - r, n);
    for (int c = 0; c < n; ++c) {
      const double p = cell_centre(c, n);
      if (p > pbar) continue;
      csv << "grid" << -1 << p << pbar << grid(r, c);
      csv.end_row();
    }
  }
  for (Eigen::Index i = 0; i < data.p_at_worst.size(); ++i) {
    const double p = std::min(data.p_at_worst(i), pbar_min);
    csv << "layout" << static_cast<long>(i) << p << pbar_min << theta_deg(p, pbar_min);
    csv.end_row();
  }
  csv.commit();
}

void draw_contours(Canvas& canvas, const Eigen::MatrixXd& grid, int n) {
  std::vector<double> values(static_cast<std::size_t>(n) * n);
  std::vector<const double*> columns(n);
  std::vector<double> axis(n);
  for (int i = 0; i < n; ++i) {
    axis[i] = cell_centre(i, n);
    for (int j = 0; j < n; ++j) values[static_cast<std::size_t>(i) * n + j] = grid(n - 1 - j, i);
    columns[i] = values.data() + static_cast<std::size_t>(i) * n;
  }
  std::vector<double> levels;
  for (double level = kContourStepDeg; level < 90.0; level += kContourStepDeg) {
    levels.push_back(level);
  }
  PLcGrid coordinates{axis.data(), axis.data(), nullptr, n, n, 0};
  plstream& pls = canvas.pls();
  pls.cont(columns.data(), n, n, 1, n, 1, n, levels.data(), static_cast<int>(levels.size()),
           plcallback::tr1, &coordinates);
}

void draw_surface(Canvas& canvas, const ErrorSurfaceData& data, const Eigen::MatrixXd& grid,
                  const FigureOptions& options) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const int n = data.samples_per_axis;
  const double pbar_min = data.p_at_worst.maxCoeff();
  internal::draw_title(
      canvas,
      internal::figure_title(options,
                             "Error surface (Eq. 26): " + internal::layout_label(data.layout_name)),
      "θ(pᵢ, p̄) = arccos[pᵢ²/p̄ + √((1 − pᵢ²)(1 − pᵢ²/p̄²))]: error of vector i under the "
      "least-upper-bound scale");

  plstream& pls = canvas.pls();
  pls.vpor(0.10, 0.74, 0.10, 0.86);
  pls.wind(0.0, 1.0, 0.0, 1.0);
  const std::vector<double> tx{0.0, 0.0, 1.0}, ty{0.0, 1.0, 1.0};
  canvas.clip_to_polygon(tx, ty);
  canvas.paint_raster(internal::value_raster(grid, 0.0, 90.0), 0.0, 1.0, 0.0, 1.0);
  pls.col0(internal::kPenInk);
  pls.width(0.7 * s);
  draw_contours(canvas, grid, n);
  canvas.unclip();

  pls.col0(internal::kPenGrid);
  pls.width(1.0 * s);
  pls.join(0.0, 0.0, 1.0, 1.0);
  canvas.label(0.66, 0.42, "pᵢ > p̄: not possible (p̄ is the largest pⱼ)", 0.0, 0.0, 0.5,
               internal::kLabelSize * s, {110, 110, 110});

  // The frame first: markers on a p-bar_min near 1 reach over the top edge and stay whole.
  internal::draw_axes(canvas, "bcnst", "bcnstv", 0.1, 2,
                      "pᵢ: fraction of data vector i's norm in the image (Eq. 19)", 3.0,
                      "p̄ = maxⱼ pⱼ: largest fraction (Eq. 25)", 3.6);

  pls.col0(internal::kPenWorst);
  pls.width(1.6 * s);
  pls.lsty(2);
  pls.join(0.0, pbar_min, pbar_min, pbar_min);
  pls.lsty(1);
  for (Eigen::Index i = 0; i < data.p_at_worst.size(); ++i) {
    canvas.marker(std::min(data.p_at_worst(i), pbar_min), pbar_min, 5.5 * s, kWorstViewpointColour);
  }
  // Under the line, or over it when the line runs along the bottom of the plot.
  const bool below = pbar_min > kLabelBelowAbove;
  canvas.label(0.02, pbar_min,
               std::string(data.seen_whole_of_a_body
                               ? "layout seen whole (not on its body), its worst viewpoint: "
                               : "layout at its worst viewpoint: ") +
                   "p̄_min " + fixed(pbar_min, 4),
               0.0, (below ? 18 : -18) * s, 0.0, internal::kSmallSize * s, {25, 25, 25},
               {255, 255, 255}, 0.85);

  internal::draw_colour_bar(canvas, 0.80, 0.825, 0.10, 0.86, 0.0, 90.0,
                            "error θ  [deg]  (contours every 10°)");

  using Entry = Canvas::LegendEntry;
  // In the empty triangle p > p-bar, under the diagonal.
  canvas.legend(
      0.735, 0.31,
      {Entry::marker("data vectors (pᵢ, p̄_min) at the worst viewpoint", kWorstViewpointColour),
       Entry::text_only("θ(p̄, p̄) = arccos p̄ on the diagonal: the largest error")},
      internal::kSmallSize * s, 1.0);
}

}  // namespace

FigureFiles write_error_surface(const ErrorSurfaceData& data,
                                const std::filesystem::path& directory,
                                const FigureOptions& options) {
  check_data(data);
  const Eigen::MatrixXd grid = theta_grid(data.samples_per_axis);
  const FigureFiles files = figure_files("error_surface", directory, options.format);
  Canvas canvas(files.image, options);
  draw_surface(canvas, data, grid, options);
  canvas.finish();
  write_csv(data, grid, files.csv);
  return files;
}

}  // namespace vantage::plot
