#include "vantage/plot/design_curve.h"

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

struct Range {
  int m_lo = 1;
  int m_hi = 2;
};

Range m_range(const DesignCurve& curve) {
  int lo = *std::min_element(curve.n_vectors.begin(), curve.n_vectors.end());
  int hi = *std::max_element(curve.n_vectors.begin(), curve.n_vectors.end());
  if (curve.has_direct) hi = std::max(hi, curve.direct_n_vectors);
  return {lo, std::max(hi, lo + 1)};
}

void write_csv(const DesignCurve& curve, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "series,step,n_vectors,pbar_min");
  for (std::size_t k = 0; k < curve.n_vectors.size(); ++k) {
    csv << "greedy" << static_cast<long>(k) << static_cast<long>(curve.n_vectors[k])
        << curve.pbar_min[k];
    csv.end_row();
  }
  if (curve.has_direct) {
    csv << "direct" << static_cast<long>(curve.n_vectors.size() - 1)
        << static_cast<long>(curve.direct_n_vectors) << curve.direct_pbar_min;
    csv.end_row();
  }
  const Range range = m_range(curve);
  for (int m = range.m_lo; m <= range.m_hi; ++m) {
    csv << "ceiling" << -1 << static_cast<long>(m) << design::pbar_ceiling(m);
    csv.end_row();
  }
  csv.commit();
}

// The ceiling cos(pi/(2m)) for m in [m0, m1], dashed.
void draw_ceiling(Canvas& canvas, double m0, double m1, internal::LegendPlacer& placer) {
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  constexpr int kCeilingPoints = 200;
  std::vector<double> cx(kCeilingPoints), cy(kCeilingPoints);
  for (int k = 0; k < kCeilingPoints; ++k) {
    cx[k] = m0 + (m1 - m0) * k / (kCeilingPoints - 1);
    cy[k] = std::cos(kPi / (2.0 * cx[k]));
  }
  pls.col0(internal::kPenInk);
  pls.width(1.6 * s);
  pls.lsty(2);
  pls.line(kCeilingPoints, cx.data(), cy.data());
  pls.lsty(1);
  placer.add_line(cx, cy);
}

// The greedy steps: a line with labelled markers; label_drop is the height of a step label in
// p-bar (the labels hang below their markers).
void draw_steps(Canvas& canvas, const DesignCurve& curve, double label_drop,
                internal::LegendPlacer& placer) {
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  const int steps = static_cast<int>(curve.n_vectors.size());
  std::vector<double> gx(steps), gy(steps);
  for (int k = 0; k < steps; ++k) {
    gx[k] = curve.n_vectors[k];
    gy[k] = curve.pbar_min[k];
  }
  pls.col0(internal::kPenWorst);
  pls.width(2.2 * s);
  pls.line(steps, gx.data(), gy.data());
  placer.add_line(gx, gy);
  std::vector<double> label_y(gy);
  for (double& v : label_y) v -= label_drop;
  placer.add_points(gx, label_y);
  for (int k = 0; k < steps; ++k) {
    canvas.marker(gx[k], gy[k], 6.0 * s, kWorstViewpointColour);
    canvas.label(gx[k], gy[k], k == 0 ? "initial" : "step " + std::to_string(k), 0.0, 18 * s, 0.5,
                 internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.8);
  }
}

void draw_legend(Canvas& canvas, const DesignCurve& curve, internal::LegendPlacer& placer) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  using Entry = Canvas::LegendEntry;
  std::vector<Entry> legend{
      Entry::marker("greedy augmenter, p̄_min after each step (" + fixed(curve.pbar_min.front(), 4) +
                        " → " + fixed(curve.pbar_min.back(), 4) + ")",
                    kWorstViewpointColour),
      Entry::line("ceiling cos(π/(2m)) (zone covering bound)", {25, 25, 25}, 1.6 * s, true)};
  if (curve.has_direct) {
    legend.insert(legend.begin() + 1, Entry::marker("direct optimiser, all additions at once (" +
                                                        fixed(curve.direct_pbar_min, 4) + ")",
                                                    {33, 113, 181}, Canvas::Shape::kDiamond));
  }
  const auto [legend_x, legend_y] =
      placer.corner(canvas.legend_size(legend, internal::kSmallSize * s));
  canvas.legend(legend_x, legend_y, legend, internal::kSmallSize * s);
}

void draw_curve(Canvas& canvas, const DesignCurve& curve, const FigureOptions& options) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const Range range = m_range(curve);
  internal::draw_title(
      canvas,
      internal::figure_title(options, "Design: " + internal::layout_label(curve.layout_name)),
      "global p̄_min after each greedy step of vantage design, the direct optimum and the "
      "ceiling cos(π/(2m))");

  double lo = *std::min_element(curve.pbar_min.begin(), curve.pbar_min.end());
  if (curve.has_direct) lo = std::min(lo, curve.direct_pbar_min);
  lo = std::max(0.0, lo - 0.1 * (1.0 - lo) - 0.02);
  const double pad = std::max(0.5, 0.04 * (range.m_hi - range.m_lo));

  plstream& pls = canvas.pls();
  const internal::Viewport viewport{0.115, 0.845, 0.11, 0.73};
  pls.vpor(viewport.left, viewport.left + viewport.width, viewport.bottom,
           viewport.bottom + viewport.height);
  pls.wind(range.m_lo - pad, range.m_hi + pad, lo, 1.0);
  // The legend goes where neither the ceiling nor the points and their labels are.
  internal::LegendPlacer placer(range.m_lo - pad, range.m_hi + pad, lo, 1.0, viewport);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("g", 0.0, 0, "g", 0.0, 0);

  draw_ceiling(canvas, std::max(1.0, range.m_lo - pad), range.m_hi + pad, placer);

  // The step labels hang below their markers: their world height there.
  const double label_drop = (1.0 - lo) * 26.0 * s / (viewport.height * canvas.height());
  draw_steps(canvas, curve, label_drop, placer);
  if (curve.has_direct) {
    placer.add_points({static_cast<double>(curve.direct_n_vectors)}, {curve.direct_pbar_min});
    canvas.marker(curve.direct_n_vectors, curve.direct_pbar_min, 8.0 * s, {33, 113, 181},
                  Canvas::Shape::kDiamond);
    canvas.label(curve.direct_n_vectors, curve.direct_pbar_min,
                 "direct " + fixed(curve.direct_pbar_min, 4), -14 * s, -14 * s, 1.0,
                 internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.8);
  }

  internal::draw_axes(canvas, "bcnst", "bcnstv", 0.0, 0,
                      "m: number of data vectors (free vectors in point mode)", 3.2,
                      "p̄_min: global worst case (higher is better)", 4.8);

  draw_legend(canvas, curve, placer);
}

}  // namespace

bool DesignCurve::is_valid(std::string* why) const {
  auto fail = [why](const std::string& message) {
    if (why) *why = message;
    return false;
  };
  if (n_vectors.empty()) return fail("n_vectors is empty");
  if (n_vectors.size() != pbar_min.size()) return fail("pbar_min must have one entry per step");
  for (std::size_t k = 0; k < n_vectors.size(); ++k) {
    if (n_vectors[k] < 1) return fail("n_vectors[" + std::to_string(k) + "] must be >= 1");
    if (!(pbar_min[k] >= 0.0 && pbar_min[k] <= 1.0)) {
      return fail("pbar_min[" + std::to_string(k) + "] must be in [0, 1]");
    }
  }
  if (has_direct && direct_n_vectors < 1) return fail("direct_n_vectors must be >= 1");
  if (has_direct && !(direct_pbar_min >= 0.0 && direct_pbar_min <= 1.0)) {
    return fail("direct_pbar_min must be in [0, 1]");
  }
  return true;
}

DesignCurve design_curve(const design::AugmentResult& result, const std::string& layout_name) {
  DesignCurve curve;
  curve.layout_name = layout_name;
  curve.n_vectors.push_back(result.initial_vector_count);
  curve.pbar_min.push_back(result.initial.pbar_min);
  for (const design::AugmentStep& step : result.steps) {
    curve.n_vectors.push_back(step.vector_count);
    curve.pbar_min.push_back(step.worst.pbar_min);
  }
  if (result.direct.status == design::DirectResult::Status::kOk) {
    curve.has_direct = true;
    curve.direct_n_vectors = curve.n_vectors.back();
    curve.direct_pbar_min = result.direct.worst.pbar_min;
  }
  return curve;
}

FigureFiles write_design_curve(const DesignCurve& curve, const std::filesystem::path& directory,
                               const FigureOptions& options) {
  std::string why;
  if (!curve.is_valid(&why)) throw InvalidArgument("write_design_curve: curve." + why);
  const FigureFiles files = figure_files("design", directory, options.format);
  Canvas canvas(files.image, options);
  draw_curve(canvas, curve, options);
  canvas.finish();
  write_csv(curve, files.csv);
  return files;
}

}  // namespace vantage::plot
