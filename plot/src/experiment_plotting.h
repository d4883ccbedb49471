#pragma once

// What the experiment figures share: series colours, lines in any colour, log-axis ranges and
// the per-experiment drawing functions. Private to vantage::plot.

#include <filesystem>
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

/// The plot area of every experiment figure: the viewport, the world window [x0, x1] x [y0, y1]
/// and the pale grid (PLplot box options xopt/yopt with major tick spacing xtick/ytick).
void plot_area(Canvas& canvas, double x0, double x1, double y0, double y1, const char* xopt,
               double xtick, const char* yopt, double ytick);

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
void write_mcinroy_orientation_figure(const std::filesystem::path& directory,
                                      const FigureOptions& options,
                                      std::vector<FigureFiles>& files);
/// The knee plot of the sweep CSV `sweep_csv`, written as figure `figure` (in the directory of
/// `sweep_csv`) titled `title`.
void write_haralick_figure(const std::filesystem::path& sweep_csv, const std::string& figure,
                           const std::string& title, const FigureOptions& options,
                           std::vector<FigureFiles>& files);

}  // namespace vantage::plot::internal
