// The TRE along the tip axis (tre_figures.h): RMS TRE against the distance from the markers'
// centroid through the first target, one curve per fixed line of sight.

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"
#include "tre_figure_text.h"
#include "vantage/plot/tre_figures.h"

namespace vantage::plot {
namespace {

using internal::Canvas;
using tracker::TreCurve;
using tracker::TreTipAxisSweep;

// The plot area (page fractions) under the two title lines.
constexpr internal::Viewport kTipAxisPanel{0.09, 0.87, 0.11, 0.72};
// Headroom above the largest value, a fraction of it.
constexpr double kTipAxisHeadroom = 0.08;
constexpr double kTipAxisMarkerPx = 4.5;

void write_tip_axis_csv(const tracker::TreSweeps& sweeps, const std::filesystem::path& path) {
  internal::CsvWriter csv(path,
                          "series,direction_x,direction_y,direction_z,visible,distance,target_x,"
                          "target_y,target_z,rms");
  const TreTipAxisSweep& tip = sweeps.tip_axis;
  auto rows = [&](const std::string& series, const TreCurve* curve,
                  const std::vector<double>& rms) {
    for (std::size_t k = 0; k < rms.size(); ++k) {
      const Eigen::Vector3d r = tip.target(k);
      csv << series;
      internal::write_tre_direction(csv, curve, sweeps.report.markers);
      csv << tip.distance[k] << r.x() << r.y() << r.z() << rms[k];
      csv.end_row();
    }
  };
  for (const TreCurve& curve : tip.curves) {
    if (curve.tracked) rows(curve.label, &curve, curve.rms);
  }
  rows("isotropic", nullptr, tip.rms_isotropic);
  csv.commit();
}

double tip_axis_largest(const TreTipAxisSweep& tip) {
  double hi = 0.0;
  for (const TreCurve& curve : tip.curves) {
    for (double v : curve.rms) hi = std::max(hi, v);
  }
  for (double v : tip.rms_isotropic) hi = std::max(hi, v);
  return hi > 0.0 ? hi : 1.0;
}

// RMS at the first target (s = D1) of a curve, by linear interpolation between the samples that
// bracket it (D1 is a sample when the extent is a multiple of the step; 1.5 with 61 samples).
double tip_axis_value_at(const std::vector<double>& s, const std::vector<double>& v, double x) {
  const auto it = std::lower_bound(s.begin(), s.end(), x);
  if (it == s.begin()) return v.front();
  if (it == s.end()) return v.back();
  const std::size_t k = static_cast<std::size_t>(it - s.begin());
  const double f = (x - s[k - 1]) / (s[k] - s[k - 1]);
  return v[k - 1] + f * (v[k] - v[k - 1]);
}

void draw_tip_axis_panel(Canvas& canvas, const TreTipAxisSweep& tip) {
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const double x1 = tip.distance.back();
  const double y1 = (1.0 + kTipAxisHeadroom) * tip_axis_largest(tip);
  const internal::Viewport& v = kTipAxisPanel;
  plstream& pls = canvas.pls();
  pls.vpor(v.left, v.left + v.width, v.bottom, v.bottom + v.height);
  pls.wind(0.0, x1, 0.0, y1);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("bcgt", 0.0, 0, "bcgt", 0.0, 0);
  internal::LegendPlacer placer(0.0, x1, 0.0, y1, v);
  const double d1 = tip.target_distance;
  internal::draw_line(canvas, {d1, d1}, {0.0, y1}, {120, 120, 120}, 1.2, true);
  placer.add_line({d1, d1}, {0.0, y1});
  canvas.label(d1, 0.0, "first target, s = " + internal::tre_number_text(d1), 5 * s, -10 * s, 0.0,
               internal::kSmallSize * s, {70, 70, 70}, {255, 255, 255}, 0.85);
  std::vector<Entry> legend;
  for (const TreCurve& curve : tip.curves) {
    const Rgb colour = internal::tre_curve_colour(curve.label);
    if (!curve.tracked) {
      legend.push_back(Entry::text_only(internal::tre_curve_text(curve)));
      continue;
    }
    internal::draw_line(canvas, tip.distance, curve.rms, colour, 2.2);
    placer.add_line(tip.distance, curve.rms);
    const double at = tip_axis_value_at(tip.distance, curve.rms, d1);
    canvas.marker(d1, at, kTipAxisMarkerPx * s, colour);
    legend.push_back(Entry::line_marker(
        internal::tre_curve_text(curve) + ": " + internal::tre_number_text(at) + " at the target",
        colour, 2.2 * s, Canvas::Shape::kCircle));
  }
  if (!tip.rms_isotropic.empty()) {
    internal::draw_line(canvas, tip.distance, tip.rms_isotropic, internal::kTreIsotropicColour, 1.8,
                        true);
    placer.add_line(tip.distance, tip.rms_isotropic);
    legend.push_back(Entry::line("Fitzpatrick 1998 (isotropic, every marker)",
                                 internal::kTreIsotropicColour, 1.8 * s, true));
  }
  internal::draw_axes(canvas, "bcnst", "bcnstv", 0.0, 0,
                      "distance s from the markers' centroid along the tip axis  [layout units]",
                      3.2, "RMS TRE  [layout units]", 4.2);
  const auto [lx, ly] = placer.corner(canvas.legend_size(legend, internal::kSmallSize * s));
  canvas.legend(lx, ly, legend, internal::kSmallSize * s);
}

}  // namespace

FigureFiles write_tre_tip_axis(const std::string& layout_name, const tracker::TreSweeps& sweeps,
                               const std::filesystem::path& directory,
                               const FigureOptions& options) {
  const FigureFiles files = figure_files("tre_tip_axis", directory, options.format);
  Canvas canvas(files.image, options);
  const TreTipAxisSweep& tip = sweeps.tip_axis;
  internal::draw_title(
      canvas,
      internal::figure_title(options,
                             "TRE along the tip axis: " + internal::layout_label(layout_name)),
      "targets from the markers' centroid " + internal::tre_vector_text(tip.centroid, 2) +
          " through " + internal::tre_vector_text(sweeps.report.targets.front().target, 2) + "; " +
          internal::tre_fle_text(sweeps.report.fle) + "; first order (docs/math.md §23)");
  draw_tip_axis_panel(canvas, tip);
  canvas.finish();
  write_tip_axis_csv(sweeps, files.csv);
  return files;
}

}  // namespace vantage::plot
