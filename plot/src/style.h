#pragma once

// Page furniture shared by the figures: sizes scaled to the page, titles, number formatting.
// Private to vantage::plot.

#include <cmath>
#include <string>

#include "canvas.h"
#include "vantage/analysis/common.h"

namespace vantage::plot::internal {

/// Font sizes (pixels at the default 1000 x 800 page; multiplied by page_scale()).
inline constexpr double kTitleSize = 22.0;
inline constexpr double kSubtitleSize = 14.5;
inline constexpr double kLabelSize = 14.0;
inline constexpr double kSmallSize = 12.0;

/// min(width / 1000, height / 800): how much larger than the default page this one is.
double page_scale(const Canvas& canvas);

/// A label short enough for the page: its first 14 bytes (never half a UTF-8 character) and
/// "..." when longer; the CSV keeps the whole name.
std::string page_label(const std::string& label);

/// x with `decimals` digits after the point ("-0.000" printed as "0.000").
std::string fixed(double x, int decimals);

/// options.title when set, else `fallback`.
std::string figure_title(const FigureOptions& options, const std::string& fallback);

/// The title (and a smaller subtitle line under it) centred at the top of the page.
void draw_title(Canvas& canvas, const std::string& title, const std::string& subtitle);

/// Sets PLplot's character height to `size_px` pixels at this page's scale.
void set_text_size(Canvas& canvas, double size_px);

/// A vertical colour bar of the value map in the page rectangle [vx0, vx1] x [vy0, vy1]
/// (fractions of the page) for values lo..hi, ticks and numbers on its right, `label` beside.
/// With `log10_scale`, lo and hi are decades and the numbers read 10^k.
void draw_colour_bar(Canvas& canvas, double vx0, double vx1, double vy0, double vy1, double lo,
                     double hi, const std::string& label, bool log10_scale = false);

/// The frame of the current viewport: PLplot's box with options xopt/yopt (major tick spacing
/// `tick`, 0 = automatic, with `subticks` minor ticks), numbers in kSmallSize, and the axis labels
/// in kLabelSize below (offset x_offset character heights) and left (y_offset).
void draw_axes(Canvas& canvas, const char* xopt, const char* yopt, double tick, int subticks,
               const std::string& xlabel, double x_offset, const std::string& ylabel,
               double y_offset);

/// "name" or, when empty, the fallback "layout".
std::string layout_label(const std::string& name);

}  // namespace vantage::plot::internal
