// Empirical CDFs of the per-trial rotation errors (`vantage experiment mcinroy-orientation` and
// `mcinroy-pose`): one line per estimator and, when the file has an n column, number of vectors
// n, on a log error axis. The paper's two estimators keep fixed colours: standard red, the new
// (affine) one blue.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "experiment_csv.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"

namespace vantage::plot::internal {
namespace {

// Errors below kSmallestDeg, or more than kMaxDecades below the largest, are drawn at the left
// edge.
constexpr double kSmallestDeg = 1e-12;
constexpr double kMaxDecades = 14.0;
constexpr std::size_t kCurvePoints = 300;
// A curve whose median is below kExactDeg is an exact estimator on noise-free data (~1e-10
// degrees): it is drawn at the left edge, so that the axis spans the curves that differ, from the
// decade below the smallest kLeftQuantile-quantile of the others.
constexpr double kExactDeg = 1e-6;
constexpr double kLeftQuantile = 0.01;

// Sorted finite errors of each (n, estimator).
using Samples = std::map<std::pair<long, std::string>, std::vector<double>>;

// Without an n column every sample has n = 0.
Samples read_samples(const std::filesystem::path& path) {
  const ExperimentCsv csv(path);
  const bool has_n = csv.has_column("n");
  const std::size_t n = has_n ? csv.column("n") : 0, estimator = csv.column("estimator"),
                    error = csv.column("rot_err_deg");
  Samples samples;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const double e = csv.number(r, error);
    auto& list = samples[{has_n ? std::lround(csv.number(r, n)) : 0L, csv.text(r, estimator)}];
    if (std::isfinite(e)) list.push_back(e);
  }
  for (auto& entry : samples) std::sort(entry.second.begin(), entry.second.end());
  return samples;
}

std::string estimator_label(const std::string& name) {
  if (name == "standard") return "standard";
  if (name == "affine") return "new (affine)";
  return name;
}

// Estimator colour: standard red, the new estimator blue, others from the series colours.
Rgb estimator_colour(const std::string& name, std::size_t index) {
  if (name == "standard") return {228, 26, 28};
  if (name == "affine") return {33, 113, 181};
  return series_colour(index + 2);
}

bool is_exact(const std::vector<double>& sorted) {
  return !sorted.empty() && sorted[sorted.size() / 2] < kExactDeg;
}

// The error axis (log10 degrees): up to 180 degrees, down to the decade below the curves that
// differ (all curves when every one is exact).
Decades error_axis(const Samples& samples) {
  std::vector<double> all, lows;
  for (const auto& [key, errors] : samples) {
    all.insert(all.end(), errors.begin(), errors.end());
    if (errors.empty() || is_exact(errors)) continue;
    lows.push_back(errors[static_cast<std::size_t>(kLeftQuantile * (errors.size() - 1))]);
  }
  Decades x = decades(all, kSmallestDeg);
  if (!lows.empty()) x.lo = decades(lows, kSmallestDeg).lo;
  x.hi = std::min(x.hi, std::ceil(std::log10(180.0) * 10.0) / 10.0);
  x.lo = std::min(std::max(x.lo, x.hi - kMaxDecades), x.hi - 1.0);
  return x;
}

std::string median_text(double degrees) {
  if (degrees >= 1.0) return fixed(degrees, 1);
  if (degrees >= 1e-3) return fixed(degrees, 3);
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1e", degrees);
  return buffer;
}

}  // namespace

void write_error_cdf_figure(const ErrorCdfFigure& spec, const FigureOptions& options,
                            std::vector<FigureFiles>& files) {
  const Samples samples = read_samples(spec.csv);
  if (samples.empty()) throw InvalidArgument(spec.csv.string() + ": no rows");
  std::vector<long> ns;
  std::vector<std::string> estimators;
  bool clamped = false;
  for (const auto& [key, errors] : samples) {
    if (std::find(ns.begin(), ns.end(), key.first) == ns.end()) ns.push_back(key.first);
    if (std::find(estimators.begin(), estimators.end(), key.second) == estimators.end()) {
      estimators.push_back(key.second);
    }
  }
  const Decades x = error_axis(samples);

  const FigureFiles out = figure_files(spec.figure, spec.csv.parent_path(), options.format);
  Canvas canvas(out.image, options);
  const double s = page_scale(canvas);
  draw_title(canvas, figure_title(options, spec.title), spec.subtitle);
  plot_area(canvas, x.lo, x.hi, 0.0, 1.0, "gl", 1.0, "g", 0.1);

  CsvWriter csv(out.csv, "n,estimator,rot_err_deg,fraction");
  using Entry = Canvas::LegendEntry;
  std::vector<Entry> legend;
  LegendPlacer placer(x.lo, x.hi, 0.0, 1.0);
  for (const auto& [key, errors] : samples) {
    if (errors.empty()) continue;
    const std::size_t e = static_cast<std::size_t>(
        std::find(estimators.begin(), estimators.end(), key.second) - estimators.begin());
    const bool dashed = key.first != ns.back();
    const Rgb colour = estimator_colour(key.second, e);
    // The CDF is drawn through at most kCurvePoints of its steps so that a dashed line stays
    // visibly dashed; the CSV has every step.
    std::vector<double> px{x.lo}, py{0.0};
    const double count = static_cast<double>(errors.size());
    const std::size_t stride = std::max<std::size_t>(1, errors.size() / kCurvePoints);
    for (std::size_t k = 0; k < errors.size(); ++k) {
      csv << key.first << key.second << errors[k] << (k + 1) / count;
      csv.end_row();
      if (k % stride != 0 && k + 1 != errors.size()) continue;
      px.push_back(std::min(x.hi, std::max(x.lo, log_clamped(errors[k], kSmallestDeg))));
      py.push_back((k + 1) / count);
    }
    px.push_back(x.hi);
    py.push_back(1.0);
    draw_line(canvas, px, py, colour, dashed ? 2.0 : 2.6, dashed);
    placer.add_line(px, py);
    const double median = errors[errors.size() / 2];
    const bool at_edge = log_clamped(median, kSmallestDeg) < x.lo;
    clamped = clamped || at_edge;
    const std::string series =
        (ns.size() > 1 || key.first != 0 ? "n = " + std::to_string(key.first) + ", "
                                         : std::string()) +
        estimator_label(key.second);
    legend.push_back(Entry::line(series + " (median " + median_text(median) + "°, " +
                                     std::to_string(errors.size()) + " trials" +
                                     (at_edge ? "; at the left edge" : "") + ")",
                                 colour, (dashed ? 2.0 : 2.6) * s, dashed));
  }
  draw_axes(canvas, "bcnstl", "bcnstv", 0.0, 0,
            clamped ? "rotation error (degrees, log scale; smaller errors at the left edge)"
                    : "rotation error (degrees, log scale)",
            3.2, "fraction of trials with error ≤ x", 4.2);
  const auto [legend_x, legend_y] = placer.corner(canvas.legend_size(legend, kSmallSize * s));
  canvas.legend(legend_x, legend_y, legend, kSmallSize * s);
  canvas.finish();
  csv.commit();
  files.push_back(out);
}

}  // namespace vantage::plot::internal
