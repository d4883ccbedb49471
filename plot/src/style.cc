#include "style.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vantage::plot::internal {
namespace {
// PLplot's default character height is given in millimetres; its cairo driver draws at 90 dpi.
constexpr double kPixelsPerMillimetre = 90.0 / 25.4;
// Titles and subtitles fit in this fraction of the page's width.
constexpr double kTitleWidth = 0.97;
}  // namespace

double page_scale(const Canvas& canvas) {
  return std::min(canvas.width() / 1000.0, canvas.height() / 800.0);
}

std::string page_label(const std::string& label) {
  constexpr std::size_t kPageLabelBytes = 14;
  if (label.size() <= kPageLabelBytes) return label;
  std::size_t cut = kPageLabelBytes;
  while (cut > 0 && (static_cast<unsigned char>(label[cut]) & 0xc0) == 0x80) --cut;
  return label.substr(0, cut) + "...";
}

std::string fixed(double x, int decimals) {
  char buffer[64];
  const double shown = std::abs(x) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : x;
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, shown);
  return buffer;
}

std::string figure_title(const FigureOptions& options, const std::string& fallback) {
  return options.title.empty() ? fallback : options.title;
}

void draw_title(Canvas& canvas, const std::string& title, const std::string& subtitle) {
  const double s = page_scale(canvas);
  canvas.pls().vpor(0.0, 1.0, 0.0, 1.0);
  canvas.pls().wind(0.0, 1.0, 0.0, 1.0);
  const Rgb ink{25, 25, 25};
  // A long title or subtitle (a layout's long name) is set smaller to fit the page.
  auto fitted = [&](const std::string& text, double size) {
    const double room = kTitleWidth * canvas.width();
    const double width = canvas.text_width(text, size);
    return width > room ? size * room / width : size;
  };
  canvas.label(0.5, 1.0, title, 0.0, 24.0 * s, 0.5, fitted(title, kTitleSize * s), ink);
  if (!subtitle.empty()) {
    canvas.label(0.5, 1.0, subtitle, 0.0, 52.0 * s, 0.5, fitted(subtitle, kSubtitleSize * s),
                 {80, 80, 80});
  }
}

void set_text_size(Canvas& canvas, double size_px) {
  canvas.pls().schr(size_px * page_scale(canvas) / kPixelsPerMillimetre, 1.0);
}

void draw_colour_bar(Canvas& canvas, double vx0, double vx1, double vy0, double vy1, double lo,
                     double hi, const std::string& label, bool log10_scale) {
  constexpr int kSteps = 256;
  Eigen::MatrixXd ramp(kSteps, 1);
  for (int i = 0; i < kSteps; ++i) ramp(i, 0) = 1.0 - i / double(kSteps - 1);
  plstream& pls = canvas.pls();
  pls.vpor(vx0, vx1, vy0, vy1);
  pls.wind(0.0, 1.0, lo, hi > lo ? hi : lo + 1.0);
  canvas.paint_raster(value_raster(ramp, 0.0, 1.0), 0.0, 1.0, lo, hi > lo ? hi : lo + 1.0);
  set_text_size(canvas, kSmallSize);
  pls.col0(kPenInk);
  pls.width(1.0);
  pls.box("bc", 0.0, 0, log10_scale ? "bcmstvl" : "bcmstv", 0.0, 0);
  set_text_size(canvas, kLabelSize);
  pls.mtex("r", 4.2, 0.5, 0.5, label.c_str());
}

void draw_axes(Canvas& canvas, const char* xopt, const char* yopt, double tick, int subticks,
               const std::string& xlabel, double x_offset, const std::string& ylabel,
               double y_offset) {
  plstream& pls = canvas.pls();
  pls.col0(kPenInk);
  pls.width(page_scale(canvas));
  set_text_size(canvas, kSmallSize);
  pls.box(xopt, tick, subticks, yopt, tick, subticks);
  set_text_size(canvas, kLabelSize);
  pls.mtex("b", x_offset, 0.5, 0.5, xlabel.c_str());
  pls.mtex("l", y_offset, 0.5, 0.5, ylabel.c_str());
}

std::string layout_label(const std::string& name) { return name.empty() ? "layout" : name; }

}  // namespace vantage::plot::internal
