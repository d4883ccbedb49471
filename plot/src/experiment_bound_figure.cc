// Figure `bound` of `vantage experiment bound`: do the bounds hold? The largest per-vector
// orientation error of each trial (and every data vector's error) against p̄(a), under the
// curve arccos p̄(a) of Eq. 30, with the affine estimator's rotation error beside it. The x
// axis is 1 - p̄(a) on a log scale, where arccos p̄ ≈ sqrt(2 (1 - p̄)) is a straight line and the
// many views with p̄(a) near 1 spread out.

#include <algorithm>
#include <cmath>

#include "experiment_csv.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"

namespace vantage::plot::internal {
namespace {

constexpr double kSmallestDeg = 1e-3;  // errors below this are drawn on the bottom axis
constexpr double kSmallestGap = 1e-7;  // 1 - p̄ below this is drawn on the left axis
// A trial is "above the curve" when its error exceeds arccos p̄(a) by more than rounding.
constexpr double kAboveToleranceDeg = 1e-6;
constexpr Rgb kVectorColour{150, 150, 150};
constexpr Rgb kMaxColour{33, 113, 181};
constexpr Rgb kAffineColour{228, 26, 28};

struct Series {
  std::vector<double> pbar;
  std::vector<double> deg;
};

struct BoundData {
  Series vectors;     // every data vector
  Series max_vector;  // largest per-vector error of a trial
  Series affine;      // affine estimator's rotation error of a trial
};

BoundData read_bound(const std::filesystem::path& directory) {
  BoundData data;
  const ExperimentCsv trials(directory / "bound_trials.csv");
  const std::size_t pbar = trials.column("pbar_a"), max = trials.column("max_vector_err_deg"),
                    affine = trials.column("affine_rot_err_deg");
  for (std::size_t r = 0; r < trials.rows(); ++r) {
    const double p = trials.number(r, pbar);
    data.max_vector.pbar.push_back(p);
    data.max_vector.deg.push_back(trials.number(r, max));
    const double a = trials.number(r, affine);
    if (std::isfinite(a)) {
      data.affine.pbar.push_back(p);
      data.affine.deg.push_back(a);
    }
  }
  const ExperimentCsv vectors(directory / "bound_vectors.csv");
  const std::size_t vp = vectors.column("pbar"), vd = vectors.column("measured_deg");
  for (std::size_t r = 0; r < vectors.rows(); ++r) {
    data.vectors.pbar.push_back(vectors.number(r, vp));
    data.vectors.deg.push_back(vectors.number(r, vd));
  }
  return data;
}

void write_csv(const BoundData& data, const std::vector<double>& curve_x,
               const std::vector<double>& curve_deg, const std::filesystem::path& path) {
  CsvWriter csv(path, "series,pbar_a,error_deg");
  auto rows = [&csv](const char* name, const std::vector<double>& x, const std::vector<double>& y) {
    for (std::size_t k = 0; k < x.size(); ++k) {
      csv << name << x[k] << y[k];
      csv.end_row();
    }
  };
  rows("vector", data.vectors.pbar, data.vectors.deg);
  rows("max_vector", data.max_vector.pbar, data.max_vector.deg);
  rows("affine", data.affine.pbar, data.affine.deg);
  rows("eq30", curve_x, curve_deg);
  csv.commit();
}

double x_of(double pbar, const Decades& x) {
  return std::max(x.lo, log_clamped(1.0 - pbar, kSmallestGap));
}

void draw_points(Canvas& canvas, const Series& series, const Decades& x, const Decades& y,
                 double radius_px, Rgb colour, Canvas::Shape shape) {
  const double s = page_scale(canvas);
  for (std::size_t k = 0; k < series.pbar.size(); ++k) {
    if (!std::isfinite(series.pbar[k]) || !std::isfinite(series.deg[k])) continue;
    canvas.marker(x_of(series.pbar[k], x), std::max(y.lo, log_clamped(series.deg[k], kSmallestDeg)),
                  radius_px * s, colour, shape, colour);
  }
}

long above_curve(const Series& series) {
  long above = 0;
  for (std::size_t k = 0; k < series.pbar.size(); ++k) {
    const double bound = std::acos(std::min(1.0, series.pbar[k])) * kDegreesPerRadian;
    above += series.deg[k] > bound + kAboveToleranceDeg;
  }
  return above;
}

}  // namespace

void write_bound_figure(const std::filesystem::path& directory, const FigureOptions& options,
                        std::vector<FigureFiles>& files) {
  const BoundData data = read_bound(directory);
  std::vector<double> gaps;
  for (const Series* series : {&data.max_vector, &data.vectors}) {
    for (double p : series->pbar) gaps.push_back(1.0 - p);
  }
  Decades x = decades(gaps, kSmallestGap);
  x.hi = std::min(x.hi, 0.0);
  x.lo = std::min(std::max(x.lo, x.hi - 7.0), x.hi - 1.0);

  constexpr int kCurvePoints = 400;
  std::vector<double> curve_x(kCurvePoints), curve_deg(kCurvePoints), curve_lx(kCurvePoints),
      curve_ly(kCurvePoints);
  for (int k = 0; k < kCurvePoints; ++k) {
    curve_lx[k] = x.lo + (x.hi - x.lo) * k / (kCurvePoints - 1);
    curve_x[k] = 1.0 - std::pow(10.0, curve_lx[k]);
    curve_deg[k] = std::acos(std::min(1.0, curve_x[k])) * kDegreesPerRadian;
    curve_ly[k] = log_clamped(curve_deg[k], kSmallestDeg);
  }
  std::vector<double> all_deg = data.max_vector.deg;
  all_deg.insert(all_deg.end(), data.affine.deg.begin(), data.affine.deg.end());
  all_deg.insert(all_deg.end(), curve_deg.begin(), curve_deg.end());
  Decades y = decades(all_deg, kSmallestDeg);
  y.lo = std::max(y.lo, y.hi - 6.0);

  const FigureFiles out = figure_files("bound", directory, options.format);
  Canvas canvas(out.image, options);
  const double s = page_scale(canvas);
  draw_title(canvas, figure_title(options, "Do the bounds hold?"),
             "orientation error against p̄(a), the Eq. 30 curve arccos p̄(a) above it (vantage "
             "experiment bound)");
  plot_area(canvas, x.lo, x.hi, y.lo, y.hi, "gl", 1.0, "gl", 1.0);

  const double r = data.max_vector.pbar.size() > 2000 ? 1.6 : 3.0;
  draw_points(canvas, data.vectors, x, y, r * 0.8, kVectorColour, Canvas::Shape::kCircle);
  draw_points(canvas, data.affine, x, y, r, kAffineColour, Canvas::Shape::kSquare);
  std::vector<double> line_x, line_y;
  for (int k = 0; k < kCurvePoints; ++k) {
    if (curve_ly[k] < y.lo) continue;
    line_x.push_back(curve_lx[k]);
    line_y.push_back(curve_ly[k]);
  }
  draw_line(canvas, line_x, line_y, {25, 25, 25}, 2.2);
  draw_points(canvas, data.max_vector, x, y, r, kMaxColour, Canvas::Shape::kCircle);
  draw_axes(canvas, "bcnstl", "bcnstlv", 0.0, 0,
            "1 − p̄(a)  (log scale; p̄(a) is the layout's p̄ from viewpoint a)", 3.2,
            "orientation error (degrees, log scale)", 4.2);

  using Entry = Canvas::LegendEntry;
  canvas.legend(
      0.115, 0.83,
      {Entry::line("Eq. 30: arccos p̄(a), the bound on every data vector's error", {25, 25, 25},
                   2.2 * s),
       Entry::marker("largest per-vector error of a trial (" +
                         std::to_string(above_curve(data.max_vector)) + " of " +
                         std::to_string(data.max_vector.pbar.size()) + " above the curve)",
                     kMaxColour),
       Entry::marker(
           "each data vector's error (" + std::to_string(data.vectors.pbar.size()) + " vectors)",
           kVectorColour),
       Entry::marker("affine estimator's rotation error (" +
                         std::to_string(above_curve(data.affine)) + " of " +
                         std::to_string(data.affine.pbar.size()) + " above the curve)",
                     kAffineColour, Canvas::Shape::kSquare)},
      kSmallSize * s);
  canvas.finish();
  write_csv(data, curve_x, curve_deg, out.csv);
  files.push_back(out);
}

}  // namespace vantage::plot::internal
