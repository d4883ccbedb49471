// Line plots of the sweep CSVs (Haralick's knee plots, Wu & Wu's accuracy and time curves): one
// column of the sweep on the x axis (SNR or the number of points n), a statistic on a log y axis,
// one line per combination of the other sweep columns. Colour tells the estimators apart when a
// file has several, else the numbers of points; dashes mark the second noise model. Lines of
// different colours that coincide (orthogonal iteration with FOAM or SVD, and the perspective
// estimator, agree to a few per cent) are told apart by nested markers of decreasing size and
// dashes over the first line, and the legend says which they coincide with.

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

// Two lines coincide when they are within this many decades at every x (about a marker's
// diameter on a 4-decade axis); a point this close to the top or bottom of the axis gets one
// more decade of room.
constexpr double kCoincideDecades = 0.05;
constexpr double kEdgeDecades = 0.1;
constexpr double kMaxDecades = 6.0;
// Marker radius (pixels at the default page), and how much larger each marker under another
// one of its coincidence group is.
constexpr double kMarkerPx = 3.5;
constexpr double kNestedMarkerGrowth = 0.9;
// Nested from the outside in, each fits inside the one before at these sizes.
constexpr Canvas::Shape kNestedShapes[] = {Canvas::Shape::kCircle, Canvas::Shape::kDiamond,
                                           Canvas::Shape::kSquare};

bool coincide(const std::vector<double>& xa, const std::vector<double>& ya,
              const std::vector<double>& xb, const std::vector<double>& yb) {
  if (xa != xb) return false;
  for (std::size_t k = 0; k < ya.size(); ++k) {
    if (std::abs(ya[k] - yb[k]) > kCoincideDecades) return false;
  }
  return true;
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

// One curve as drawn: its key and points, log values clamped to the axis, style, and its
// coincidence group (the index of the group's first curve, its rank there, the group's size).
struct Drawn {
  const Key* key = nullptr;
  const Curve* curve = nullptr;
  std::vector<double> ly;
  Rgb colour;
  std::size_t colour_index = 0;
  Canvas::Shape shape = Canvas::Shape::kCircle;
  bool dashed = false;
  std::size_t first = 0;
  std::size_t rank = 0;
  std::size_t group_size = 1;
};

// [lo, hi] decades of the values (and of 1 with the 1-degree line), with room for markers at
// either end and at most kMaxDecades.
Decades y_axis(const std::vector<double>& values, double smallest, bool one_degree_line) {
  std::vector<double> all = values;
  if (one_degree_line) all.push_back(1.0);
  Decades y = decades(all, smallest);
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (log_clamped(*lo, smallest) - y.lo < kEdgeDecades) y.lo -= 1.0;
  if (y.hi - log_clamped(*hi, smallest) < kEdgeDecades) y.hi += 1.0;
  y.lo = std::max(y.lo, y.hi - kMaxDecades);
  return y;
}

std::vector<Drawn> style_curves(const std::map<Key, Curve>& curves, Levels& levels,
                                const Decades& y, double smallest, bool x_is_n) {
  const bool colour_by_estimator = levels.estimators.size() > 1;
  constexpr Canvas::Shape kShapes[] = {Canvas::Shape::kCircle, Canvas::Shape::kSquare,
                                       Canvas::Shape::kDiamond};
  std::vector<Drawn> drawn;
  for (const auto& [key, curve] : curves) {
    const std::size_t n_index =
        x_is_n ? index_of(levels.snrs, key.snr_db) : index_of(levels.ns, key.n);
    const std::size_t e_index = index_of(levels.estimators, key.estimator);
    Drawn d;
    d.key = &key;
    d.curve = &curve;
    for (double v : curve.y) d.ly.push_back(std::max(y.lo, log_clamped(v, smallest)));
    d.colour_index = colour_by_estimator ? e_index : n_index;
    d.colour = series_colour(d.colour_index);
    d.shape = kShapes[(colour_by_estimator ? n_index : e_index) % 3];
    d.dashed = index_of(levels.noises, key.noise) != 0;
    drawn.push_back(std::move(d));
  }
  // Curves of different colours that coincide join the group of the first one; each later
  // member is dashed over it with the next marker shape.
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    drawn[i].first = i;
    for (std::size_t j = 0; j < i; ++j) {
      Drawn& head = drawn[j];
      if (head.first != j || head.colour_index == drawn[i].colour_index) continue;
      if (!coincide(head.curve->x, head.ly, drawn[i].curve->x, drawn[i].ly)) continue;
      drawn[i].first = j;
      drawn[i].rank = head.group_size++;
      drawn[i].shape = kNestedShapes[drawn[i].rank % 3];
      drawn[i].dashed = true;
      break;
    }
  }
  for (Drawn& d : drawn) {
    d.group_size = drawn[d.first].group_size;
    if (d.rank == 0 && d.group_size > 1) d.shape = kNestedShapes[0];
  }
  return drawn;
}

// Every curve's markers after all lines, the largest of each coincidence group first.
void draw_markers(Canvas& canvas, const std::vector<Drawn>& drawn) {
  const double s = page_scale(canvas);
  auto radius = [&](const Drawn& d) {
    return kMarkerPx * s *
           (1.0 + kNestedMarkerGrowth * static_cast<double>(d.group_size - 1 - d.rank));
  };
  std::vector<const Drawn*> order;
  for (const Drawn& d : drawn) order.push_back(&d);
  std::stable_sort(order.begin(), order.end(),
                   [&](const Drawn* a, const Drawn* b) { return radius(*a) > radius(*b); });
  for (const Drawn* d : order) {
    for (std::size_t k = 0; k < d->ly.size(); ++k) {
      canvas.marker(d->curve->x[k], d->ly[k], radius(*d), d->colour, d->shape);
    }
  }
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
  const Decades y = y_axis(all_y, spec.y_smallest, spec.one_degree_line);
  const double pad = 0.02 * (x_hi - x_lo);
  Levels levels;
  for (const auto& [key, curve] : curves) {
    index_of(levels.ns, key.n);
    index_of(levels.noises, key.noise);
    index_of(levels.estimators, key.estimator);
    index_of(levels.snrs, key.snr_db);
  }
  const std::vector<Drawn> drawn = style_curves(curves, levels, y, spec.y_smallest, x_is_n);

  const FigureFiles out = figure_files(spec.figure, spec.csv.parent_path(), options.format);
  Canvas canvas(out.image, options);
  const double s = page_scale(canvas);
  draw_title(canvas, figure_title(options, spec.title), spec.subtitle);
  plot_area(canvas, x_lo - pad, x_hi + pad, y.lo, y.hi, "g", 0.0, "gl", 1.0);
  LegendPlacer placer(x_lo - pad, x_hi + pad, y.lo, y.hi);
  if (spec.one_degree_line) {
    draw_line(canvas, {x_lo - pad, x_hi + pad}, {0.0, 0.0}, {25, 25, 25}, 1.6, true);
    canvas.label(x_lo - pad, 0.0, "1°", 6 * s, -10 * s, 0.0, kSmallSize * s, {25, 25, 25});
    placer.add_line({x_lo - pad, x_hi + pad}, {0.0, 0.0});
  }
  CsvWriter table(out.csv, "n,noise,estimator,snr_db," + spec.y_column);
  using Entry = Canvas::LegendEntry;
  std::vector<Entry> legend;
  for (const Drawn& d : drawn) {
    for (std::size_t k = 0; k < d.ly.size(); ++k) {
      table << (x_is_n ? std::lround(d.curve->x[k]) : d.key->n) << d.key->noise << d.key->estimator
            << (x_is_n ? d.key->snr_db : d.curve->x[k]) << d.curve->y[k];
      table.end_row();
    }
    draw_line(canvas, d.curve->x, d.ly, d.colour, 2.0, d.dashed);
    placer.add_line(d.curve->x, d.ly);
    std::string text = legend_text(*d.key, levels, x_is_n);
    if (d.rank > 0) text += " (≈ " + legend_text(*drawn[d.first].key, levels, x_is_n) + ")";
    legend.push_back(Entry::line_marker(text, d.colour, 2.0 * s, d.shape, d.dashed));
  }
  draw_markers(canvas, drawn);
  draw_axes(canvas, "bcnst", "bcnstlv", 0.0, 0, spec.x_label, 3.2, spec.y_label, 4.2);
  const auto [legend_x, legend_y] = placer.corner(canvas.legend_size(legend, kSmallSize * s));
  canvas.legend(legend_x, legend_y, legend, kSmallSize * s);
  canvas.finish();
  table.commit();
  files.push_back(out);
}

}  // namespace vantage::plot::internal
