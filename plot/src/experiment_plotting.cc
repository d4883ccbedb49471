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

// Page-fraction gaps: between the legend and the frame, and around the legend, where no drawn
// point may be either.
constexpr double kLegendInset = 0.012;
constexpr double kLegendMargin = 0.012;
// Places tried per axis between the corners.
constexpr int kLegendPlaces = 9;
// A segment is sampled at least this often, and at most this far apart (page fraction), so that
// no line crosses a legend between two samples.
constexpr int kMinSamplesPerSegment = 16;
constexpr double kSampleSpacing = 0.004;

}  // namespace

void LegendPlacer::record(double wx, double wy) {
  page_x_.push_back(viewport_.left + (wx - x0_) / (x1_ - x0_) * viewport_.width);
  page_y_.push_back(viewport_.bottom + (wy - y0_) / (y1_ - y0_) * viewport_.height);
}

void LegendPlacer::add_line(const std::vector<double>& x, const std::vector<double>& y) {
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double page_length = std::hypot((x[k + 1] - x[k]) / (x1_ - x0_) * viewport_.width,
                                          (y[k + 1] - y[k]) / (y1_ - y0_) * viewport_.height);
    const int samples =
        std::max(kMinSamplesPerSegment, static_cast<int>(std::ceil(page_length / kSampleSpacing)));
    for (int j = 0; j < samples; ++j) {
      const double f = static_cast<double>(j) / samples;
      record(x[k] + f * (x[k + 1] - x[k]), y[k] + f * (y[k + 1] - y[k]));
    }
  }
  if (!x.empty()) record(x.back(), y.back());
}

void LegendPlacer::add_points(const std::vector<double>& x, const std::vector<double>& y) {
  for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) record(x[k], y[k]);
}

std::pair<double, double> LegendPlacer::corner(const Eigen::Vector2d& size) const {
  const double left0 = viewport_.left + kLegendInset;
  const double left1 = std::max(left0, viewport_.left + viewport_.width - kLegendInset - size.x());
  const double top1 = viewport_.bottom + viewport_.height - kLegendInset;
  const double top0 = std::min(top1, viewport_.bottom + kLegendInset + size.y());
  std::vector<std::pair<double, double>> places{
      {left0, top1}, {left1, top1}, {left0, top0}, {left1, top0}};
  for (int i = 0; i < kLegendPlaces; ++i) {
    for (int j = 0; j < kLegendPlaces; ++j) {
      const double fx = static_cast<double>(j) / (kLegendPlaces - 1);
      const double fy = static_cast<double>(i) / (kLegendPlaces - 1);
      places.emplace_back(left0 + fx * (left1 - left0), top1 - fy * (top1 - top0));
    }
  }
  std::pair<double, double> best = places.front();
  std::size_t best_count = page_x_.size() + 1;
  for (const auto& [left, top] : places) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < page_x_.size(); ++k) {
      count += page_x_[k] >= left - kLegendMargin &&
               page_x_[k] <= left + size.x() + kLegendMargin &&
               page_y_[k] >= top - size.y() - kLegendMargin && page_y_[k] <= top + kLegendMargin;
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
