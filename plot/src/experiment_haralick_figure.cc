// Knee plots of the Haralick experiments: mean rotation error against SNR on a log axis, one
// line per number of pairs n (colour), noise model (solid gaussian, dashed otherwise) and
// estimator (marker), with the 1° line.

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "experiment_csv.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"

namespace vantage::plot::internal {
namespace {

constexpr double kSmallestDeg = 1e-4;

struct Key {
  long n = 0;
  std::string noise;
  std::string estimator;
  bool operator<(const Key& o) const {
    return std::tie(n, noise, estimator) < std::tie(o.n, o.noise, o.estimator);
  }
};

struct Curve {
  std::vector<double> snr_db;
  std::vector<double> error_deg;
};

template <typename T>
std::size_t index_of(std::vector<T>& list, const T& value) {
  auto it = std::find(list.begin(), list.end(), value);
  if (it == list.end()) {
    list.push_back(value);
    return list.size() - 1;
  }
  return static_cast<std::size_t>(it - list.begin());
}

}  // namespace

void write_haralick_figure(const std::filesystem::path& sweep_csv, const std::string& figure,
                           const std::string& title, const FigureOptions& options,
                           std::vector<FigureFiles>& files) {
  const ExperimentCsv csv(sweep_csv);
  const std::size_t cn = csv.column("n"), cnoise = csv.column("noise"), csnr = csv.column("snr_db"),
                    cest = csv.column("estimator"), cerr = csv.column("rot_err_deg_mean");
  std::map<Key, Curve> curves;
  std::vector<double> all_err;
  double snr_lo = HUGE_VAL, snr_hi = -HUGE_VAL;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const double snr = csv.number(r, csnr), err = csv.number(r, cerr);
    if (!std::isfinite(snr) || !std::isfinite(err)) continue;
    Curve& c = curves[{std::lround(csv.number(r, cn)), csv.text(r, cnoise), csv.text(r, cest)}];
    c.snr_db.push_back(snr);
    c.error_deg.push_back(err);
    all_err.push_back(err);
    snr_lo = std::min(snr_lo, snr);
    snr_hi = std::max(snr_hi, snr);
  }
  if (curves.empty()) throw InvalidArgument(sweep_csv.string() + ": no finite rows");
  if (snr_hi <= snr_lo) snr_hi = snr_lo + 1.0;
  all_err.push_back(1.0);
  Decades y = decades(all_err, kSmallestDeg);
  y.lo = std::max(y.lo, y.hi - 6.0);
  const double pad = 0.02 * (snr_hi - snr_lo);

  const FigureFiles out = figure_files(figure, sweep_csv.parent_path(), options.format);
  Canvas canvas(out.image, options);
  const double s = page_scale(canvas);
  draw_title(canvas, figure_title(options, title),
             "mean rotation error against SNR, one line per number of pairs n and noise model");
  plot_area(canvas, snr_lo - pad, snr_hi + pad, y.lo, y.hi, "g", 0.0, "gl", 1.0);
  draw_line(canvas, {snr_lo - pad, snr_hi + pad}, {0.0, 0.0}, {25, 25, 25}, 1.6, true);
  canvas.label(snr_lo - pad, 0.0, "1°", 6 * s, -10 * s, 0.0, kSmallSize * s, {25, 25, 25});

  std::vector<long> ns;
  std::vector<std::string> noises, estimators;
  for (const auto& [key, curve] : curves) index_of(ns, key.n);
  for (const auto& [key, curve] : curves) index_of(noises, key.noise);
  for (const auto& [key, curve] : curves) index_of(estimators, key.estimator);
  constexpr Canvas::Shape kShapes[] = {Canvas::Shape::kCircle, Canvas::Shape::kSquare,
                                       Canvas::Shape::kDiamond};
  CsvWriter table(out.csv, "n,noise,estimator,snr_db,rot_err_deg_mean");
  using Entry = Canvas::LegendEntry;
  std::vector<Entry> legend;
  for (const auto& [key, curve] : curves) {
    const Rgb colour = series_colour(index_of(ns, key.n));
    const bool dashed = index_of(noises, key.noise) != 0;
    const Canvas::Shape shape = kShapes[index_of(estimators, key.estimator) % 3];
    std::vector<double> ly(curve.error_deg.size());
    for (std::size_t k = 0; k < ly.size(); ++k) {
      ly[k] = std::max(y.lo, log_clamped(curve.error_deg[k], kSmallestDeg));
      table << key.n << key.noise << key.estimator << curve.snr_db[k] << curve.error_deg[k];
      table.end_row();
    }
    draw_line(canvas, curve.snr_db, ly, colour, 2.0, dashed);
    for (std::size_t k = 0; k < ly.size(); ++k) {
      canvas.marker(curve.snr_db[k], ly[k], 3.5 * s, colour, shape);
    }
    std::string text = "n = " + std::to_string(key.n) + ", " + key.noise;
    if (estimators.size() > 1) text += ", " + key.estimator;
    legend.push_back(Entry::line(text, colour, 2.0 * s, dashed));
  }
  draw_axes(canvas, "bcnst", "bcnstlv", 0.0, 0, "SNR (dB)", 3.2,
            "mean rotation error (degrees, log scale)", 4.2);
  canvas.legend(0.955, 0.82, legend, kSmallSize * s, 1.0);
  canvas.finish();
  table.commit();
  files.push_back(out);
}

}  // namespace vantage::plot::internal
