#include "experiment_plotting.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "style.h"

namespace vantage::plot::internal {

Rgb series_colour(std::size_t k) {
  static constexpr std::array<Rgb, 8> kColours{{{33, 113, 181},
                                                {228, 26, 28},
                                                {77, 175, 74},
                                                {152, 78, 163},
                                                {255, 127, 0},
                                                {166, 86, 40},
                                                {247, 129, 191},
                                                {90, 90, 90}}};
  return kColours[k % kColours.size()];
}

void draw_line(Canvas& canvas, const std::vector<double>& x, const std::vector<double>& y,
               Rgb colour, double width_px, bool dashed) {
  if (x.size() < 2) return;
  plstream& pls = canvas.pls();
  pls.scol0(kPenBar, colour.r, colour.g, colour.b);
  pls.col0(kPenBar);
  pls.width(width_px * page_scale(canvas));
  pls.lsty(dashed ? 2 : 1);
  pls.line(static_cast<int>(x.size()), x.data(), y.data());
  pls.lsty(1);
}

void plot_area(Canvas& canvas, double x0, double x1, double y0, double y1, const char* xopt,
               double xtick, const char* yopt, double ytick) {
  plstream& pls = canvas.pls();
  pls.vpor(kPlotLeft, kPlotLeft + kPlotWidth, kPlotBottom, kPlotBottom + kPlotHeight);
  pls.wind(x0, x1, y0, y1);
  pls.col0(kPenGrid);
  pls.width(0.8 * page_scale(canvas));
  set_text_size(canvas, kSmallSize);
  pls.box(xopt, xtick, 0, yopt, ytick, 0);
}

namespace {

// The legend's approximate size (page fractions) at the default text size, and the places tried.
constexpr double kLegendWidth = 0.32;
constexpr double kLegendRowHeight = 0.025;
constexpr std::pair<double, double> kLegendCorners[] = {
    {0.12, 0.82}, {0.62, 0.82}, {0.36, 0.82}, {0.12, 0.42}, {0.62, 0.42}};
constexpr int kSamplesPerSegment = 16;

}  // namespace

void LegendPlacer::add_line(const std::vector<double>& x, const std::vector<double>& y) {
  auto record = [this](double wx, double wy) {
    page_x_.push_back(kPlotLeft + (wx - x0_) / (x1_ - x0_) * kPlotWidth);
    page_y_.push_back(kPlotBottom + (wy - y0_) / (y1_ - y0_) * kPlotHeight);
  };
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    for (int j = 0; j < kSamplesPerSegment; ++j) {
      const double f = static_cast<double>(j) / kSamplesPerSegment;
      record(x[k] + f * (x[k + 1] - x[k]), y[k] + f * (y[k + 1] - y[k]));
    }
  }
  if (!x.empty()) record(x.back(), y.back());
}

std::pair<double, double> LegendPlacer::corner(std::size_t rows) const {
  const double height = kLegendRowHeight * static_cast<double>(rows) + 0.02;
  std::pair<double, double> best = kLegendCorners[0];
  std::size_t best_count = page_x_.size() + 1;
  for (const auto& [left, top] : kLegendCorners) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < page_x_.size(); ++k) {
      count += page_x_[k] >= left && page_x_[k] <= left + kLegendWidth &&
               page_y_[k] >= top - height && page_y_[k] <= top;
    }
    if (count < best_count) {
      best_count = count;
      best = {left, top};
    }
  }
  return best;
}

double log_clamped(double value, double smallest) { return std::log10(std::max(value, smallest)); }

Decades decades(const std::vector<double>& values, double smallest) {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, log_clamped(v, smallest));
    hi = std::max(hi, log_clamped(v, smallest));
  }
  if (lo > hi) return {};
  Decades d{std::floor(lo), std::ceil(hi)};
  if (d.hi <= d.lo) d.hi = d.lo + 1.0;
  return d;
}

}  // namespace vantage::plot::internal
