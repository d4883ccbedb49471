// Line plots of the sweep CSVs (Haralick's knee plots, Wu & Wu's accuracy and time curves): one
// column of the sweep on the x axis (SNR or the number of points n), a statistic on a log y axis,
// one line per combination of the other sweep columns. Colour tells the estimators apart when a
// file has several, else the numbers of points; dashes mark the second noise model.

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

// One series: the sweep columns other than the x column (that one is left at its default).
struct Key {
  long n = 0;
  std::string noise;
  std::string estimator;
  double snr_db = 0.0;
  bool operator<(const Key& o) const {
    return std::tie(estimator, n, noise, snr_db) < std::tie(o.estimator, o.n, o.noise, o.snr_db);
  }
};

struct Curve {
  std::vector<double> x;
  std::vector<double> y;
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

std::string number_text(double x) {
  return std::abs(x - std::round(x)) < 1e-9 ? std::to_string(std::lround(x)) : fixed(x, 1);
}

// The values each sweep column takes over all series, in order of first appearance.
struct Levels {
  std::vector<long> ns;
  std::vector<std::string> noises;
  std::vector<std::string> estimators;
  std::vector<double> snrs;
};

std::string legend_text(const Key& key, const Levels& levels, bool x_is_n) {
  std::string text;
  auto add = [&text](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  if (levels.estimators.size() > 1) add(key.estimator);
  if (!x_is_n && (levels.ns.size() > 1 || levels.estimators.size() == 1)) {
    add("n = " + std::to_string(key.n));
  }
  if (x_is_n && levels.snrs.size() > 1) add(number_text(key.snr_db) + " dB");
  if (levels.noises.size() > 1) add(key.noise);
  return text.empty() ? key.estimator : text;
}

}  // namespace

void write_sweep_figure(const SweepFigure& spec, const FigureOptions& options,
                        std::vector<FigureFiles>& files) {
  const ExperimentCsv csv(spec.csv);
  const bool x_is_n = spec.x_column == "n";
  const std::size_t cn = csv.column("n"), cnoise = csv.column("noise"), csnr = csv.column("snr_db"),
                    cest = csv.column("estimator"), cy = csv.column(spec.y_column);
  std::map<Key, Curve> curves;
  std::vector<double> all_y;
  double x_lo = HUGE_VAL, x_hi = -HUGE_VAL;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    const double n = csv.number(r, cn), snr = csv.number(r, csnr), y = csv.number(r, cy);
    const double x = x_is_n ? n : snr;
    if (!std::isfinite(x) || !std::isfinite(y) || (x_is_n && !std::isfinite(snr))) continue;
    Key key{x_is_n ? 0 : std::lround(n), csv.text(r, cnoise), csv.text(r, cest),
            x_is_n ? snr : 0.0};
    Curve& c = curves[key];
    c.x.push_back(x);
    c.y.push_back(y);
    all_y.push_back(y);
    x_lo = std::min(x_lo, x);
    x_hi = std::max(x_hi, x);
  }
  if (curves.empty()) throw InvalidArgument(spec.csv.string() + ": no finite rows");
  if (x_hi <= x_lo) x_hi = x_lo + 1.0;
  if (spec.one_degree_line) all_y.push_back(1.0);
  Decades y = decades(all_y, spec.y_smallest);
  y.lo = std::max(y.lo, y.hi - 6.0);
  const double pad = 0.02 * (x_hi - x_lo);

  Levels levels;
  for (const auto& [key, curve] : curves) {
    index_of(levels.ns, key.n);
    index_of(levels.noises, key.noise);
    index_of(levels.estimators, key.estimator);
    index_of(levels.snrs, key.snr_db);
  }
  const bool colour_by_estimator = levels.estimators.size() > 1;

  const FigureFiles out = figure_files(spec.figure, spec.csv.parent_path(), options.format);
  Canvas canvas(out.image, options);
  const double s = page_scale(canvas);
  draw_title(canvas, figure_title(options, spec.title), spec.subtitle);
  plot_area(canvas, x_lo - pad, x_hi + pad, y.lo, y.hi, "g", 0.0, "gl", 1.0);
  if (spec.one_degree_line) {
    draw_line(canvas, {x_lo - pad, x_hi + pad}, {0.0, 0.0}, {25, 25, 25}, 1.6, true);
    canvas.label(x_lo - pad, 0.0, "1°", 6 * s, -10 * s, 0.0, kSmallSize * s, {25, 25, 25});
  }

  LegendPlacer placer(x_lo - pad, x_hi + pad, y.lo, y.hi);
  constexpr Canvas::Shape kShapes[] = {Canvas::Shape::kCircle, Canvas::Shape::kSquare,
                                       Canvas::Shape::kDiamond};
  CsvWriter table(out.csv, "n,noise,estimator,snr_db," + spec.y_column);
  using Entry = Canvas::LegendEntry;
  std::vector<Entry> legend;
  for (const auto& [key, curve] : curves) {
    const std::size_t n_index =
        x_is_n ? index_of(levels.snrs, key.snr_db) : index_of(levels.ns, key.n);
    const std::size_t e_index = index_of(levels.estimators, key.estimator);
    const Rgb colour = series_colour(colour_by_estimator ? e_index : n_index);
    const Canvas::Shape shape = kShapes[(colour_by_estimator ? n_index : e_index) % 3];
    const bool dashed = index_of(levels.noises, key.noise) != 0;
    std::vector<double> ly(curve.y.size());
    for (std::size_t k = 0; k < ly.size(); ++k) {
      ly[k] = std::max(y.lo, log_clamped(curve.y[k], spec.y_smallest));
      table << (x_is_n ? std::lround(curve.x[k]) : key.n) << key.noise << key.estimator
            << (x_is_n ? key.snr_db : curve.x[k]) << curve.y[k];
      table.end_row();
    }
    draw_line(canvas, curve.x, ly, colour, 2.0, dashed);
    placer.add_line(curve.x, ly);
    for (std::size_t k = 0; k < ly.size(); ++k) {
      canvas.marker(curve.x[k], ly[k], 3.5 * s, colour, shape);
    }
    legend.push_back(Entry::line(legend_text(key, levels, x_is_n), colour, 2.0 * s, dashed));
  }
  draw_axes(canvas, "bcnst", "bcnstlv", 0.0, 0, spec.x_label, 3.2, spec.y_label, 4.2);
  const auto [legend_x, legend_y] = placer.corner(legend.size());
  canvas.legend(legend_x, legend_y, legend, kSmallSize * s);
  canvas.finish();
  table.commit();
  files.push_back(out);
}

}  // namespace vantage::plot::internal
