#pragma once

// What the experiment figures share: series colours, lines in any colour, log-axis ranges, legend
// placement (the design curve uses it too) and the per-experiment drawing functions. Private to
// vantage::plot.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "canvas.h"
#include "vantage/plot/figure.h"

namespace vantage::plot::internal {

/// The k-th of a set of distinguishable series colours (cycles).
Rgb series_colour(std::size_t k);

/// A polyline in world coordinates of colour `colour`, width_px pixels (at the default page),
/// dashed or solid.
void draw_line(Canvas& canvas, const std::vector<double>& x, const std::vector<double>& y,
               Rgb colour, double width_px, bool dashed = false);

/// The viewport of every experiment figure's plot area (page fractions).
inline constexpr double kPlotLeft = 0.10;
inline constexpr double kPlotWidth = 0.86;
inline constexpr double kPlotBottom = 0.11;
inline constexpr double kPlotHeight = 0.73;

/// The plot area of every experiment figure: the viewport, the world window [x0, x1] x [y0, y1]
/// and the pale grid (PLplot box options xopt/yopt with major tick spacing xtick/ytick).
void plot_area(Canvas& canvas, double x0, double x1, double y0, double y1, const char* xopt,
               double xtick, const char* yopt, double ytick);

/// A plot area's place on the page (fractions, y up).
struct Viewport {
  double left = kPlotLeft;
  double width = kPlotWidth;
  double bottom = kPlotBottom;
  double height = kPlotHeight;
};

/// Where the legend goes: the drawn lines and markers of a plot area (world window x0..x1,
/// y0..y1, on the page at `viewport`) are recorded, and the legend takes the place inside the
/// plot area whose box, grown by a margin, covers the fewest of their points: the four corners
/// first, then a grid of places between them (the first of equal ones wins).
class LegendPlacer {
 public:
  LegendPlacer(double x0, double x1, double y0, double y1, Viewport viewport = {})
      : x0_(x0), x1_(x1), y0_(y0), y1_(y1), viewport_(viewport) {}
  /// Records a polyline (world coordinates), sampled densely enough to see every segment.
  void add_line(const std::vector<double>& x, const std::vector<double>& y);
  /// Records single points (markers, labels) in world coordinates.
  void add_points(const std::vector<double>& x, const std::vector<double>& y);
  /// The legend's left edge and top edge (page fractions) for a legend of `size` (width and
  /// height, page fractions: Canvas::legend_size).
  std::pair<double, double> corner(const Eigen::Vector2d& size) const;

 private:
  void record(double x, double y);
  double x0_, x1_, y0_, y1_;
  Viewport viewport_;
  std::vector<double> page_x_, page_y_;
};

/// [floor(log10 lo), ceil(log10 hi)] of the positive finite values (at least one decade);
/// values below `smallest` count as `smallest`.
struct Decades {
  double lo = 0.0;
  double hi = 1.0;
};
Decades decades(const std::vector<double>& values, double smallest);

/// log10(max(value, smallest)).
double log_clamped(double value, double smallest);

/// The figures of each experiment; each reads its CSV files from `directory`, writes
/// <figure>.<ext> and <figure>.csv there and appends them to `files`.
void write_bound_figure(const std::filesystem::path& directory, const FigureOptions& options,
                        std::vector<FigureFiles>& files);

/// An empirical-CDF figure of per-trial rotation errors: reads `csv` (columns estimator,
/// rot_err_deg and optionally n), writes <figure>.<ext> and <figure>.csv beside it.
struct ErrorCdfFigure {
  std::filesystem::path csv;
  std::string figure;
  std::string title;
  std::string subtitle;
};
void write_error_cdf_figure(const ErrorCdfFigure& spec, const FigureOptions& options,
                            std::vector<FigureFiles>& files);

/// A line plot of a sweep CSV (columns n, noise, snr_db, estimator and y_column): x_column ("n"
/// or "snr_db") across, y_column on a log axis (values below y_smallest drawn at y_smallest), one
/// line per combination of the other sweep columns; writes <figure>.<ext> and <figure>.csv
/// beside the input.
struct SweepFigure {
  std::filesystem::path csv;
  std::string figure;
  std::string title;
  std::string subtitle;
  std::string x_column;
  std::string x_label;
  std::string y_column;
  std::string y_label;
  double y_smallest = 1e-4;
  bool one_degree_line = false;  ///< the dashed 1° reference (for errors in degrees)
};
void write_sweep_figure(const SweepFigure& spec, const FigureOptions& options,
                        std::vector<FigureFiles>& files);

}  // namespace vantage::plot::internal
