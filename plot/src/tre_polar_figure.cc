// NDI-style polar plots of the TRE (tre_figures.h): RMS TRE of a target on a circle of radius R
// about each tool axis through the markers' centroid, at the first target's worst line of sight,
// three panels on one radial scale.

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"
#include "tre_figure_text.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/tre_figures.h"

namespace vantage::plot {
namespace {

using internal::Canvas;
using tracker::TreCurve;
using tracker::TrePolarSweep;

// The three panels' boxes (page fractions x0, x1; all share y0, y1 in pixels made square).
constexpr double kPolarLeft[3] = {0.02, 0.345, 0.67};
constexpr double kPolarWidth = 0.31;
constexpr double kPolarTop = 0.86;
// World window around the outermost ring: room for the angle labels.
constexpr double kPolarWindow = 1.33;
constexpr int kPolarRings = 4;  // rings at most; the step is 1, 2 or 5 times a power of ten
// A target this close to a circle (relative to R) is marked on its panel.
constexpr double kPolarOnCircle = 1e-9;
const char* const kPolarAxisNames[3] = {"x", "y", "z"};
// The curve about each axis: x red, y green, z blue (the usual colours of the axes).
constexpr Rgb kPolarAxisColours[3] = {{228, 26, 28}, {51, 160, 44}, {31, 120, 180}};
// The strip under the polar panels: RMS against the angle, all three axes (page fractions).
constexpr internal::Viewport kPolarStrip{0.09, 0.87, 0.075, 0.17};

void write_polar_csv(const tracker::TreSweeps& sweeps, const std::filesystem::path& path) {
  internal::CsvWriter csv(path,
                          "series,axis,direction_x,direction_y,direction_z,visible,angle_deg,"
                          "target_x,target_y,target_z,rms");
  const TrePolarSweep& polar = sweeps.polar;
  auto rows = [&](const std::string& series, int axis, const TreCurve* curve,
                  const std::vector<double>& rms) {
    for (std::size_t k = 0; k < rms.size(); ++k) {
      const Eigen::Vector3d r = polar.target(axis, k);
      csv << series << kPolarAxisNames[axis];
      internal::write_tre_direction(csv, curve, sweeps.report.markers);
      csv << polar.angle_deg[k] << r.x() << r.y() << r.z() << rms[k];
      csv.end_row();
    }
  };
  for (int axis = 0; axis < 3; ++axis) {
    const TreCurve& curve = polar.curves[static_cast<std::size_t>(axis)];
    if (curve.tracked) rows(curve.label, axis, &curve, curve.rms);
  }
  for (int axis = 0; axis < 3; ++axis) {
    rows("isotropic", axis, nullptr, polar.rms_isotropic[static_cast<std::size_t>(axis)]);
  }
  csv.commit();
}

// The ring step: the 1-2-5 number that puts at most kPolarRings rings up to `largest`.
double polar_ring_step(double largest) {
  const double raw = largest / kPolarRings;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * decade >= raw) return m * decade;
  }
  return 10.0 * decade;
}

void select_polar_panel(Canvas& canvas, int axis, double outer) {
  const double side_px = kPolarWidth * canvas.width();
  const double top = kPolarTop;
  const double height = side_px / canvas.height();
  const double x0 = kPolarLeft[axis];
  canvas.pls().vpor(x0, x0 + kPolarWidth, top - height, top);
  canvas.pls().wind(-kPolarWindow * outer, kPolarWindow * outer, -kPolarWindow * outer,
                    kPolarWindow * outer);
}

void draw_polar_grid(Canvas& canvas, int axis, double outer, double step) {
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  for (double ring = step; ring <= outer * (1.0 + 1e-9); ring += step) {
    pls.arc(0.0, 0.0, ring, ring, 0.0, 360.0, 0.0, false);
    const double t = 75.0 * kPi / 180.0;
    canvas.label(ring * std::cos(t), ring * std::sin(t), internal::tre_number_text(ring), 2 * s,
                 0.0, 0.0, internal::kSmallSize * 0.9 * s, {110, 110, 110});
  }
  const char* names[3][2] = {{"+y", "+z"}, {"+z", "+x"}, {"+x", "+y"}};
  for (int deg = 0; deg < 360; deg += 30) {
    const double t = deg * kPi / 180.0;
    pls.col0(internal::kPenGrid);
    pls.join(0.0, 0.0, outer * std::cos(t), outer * std::sin(t));
    // e_j's name beside 90 degrees, where the label has room above the rim.
    const std::string text =
        std::to_string(deg) + "°" + (deg == 90 ? " " + std::string(names[axis][1]) : "");
    const double c = std::cos(t), sn = std::sin(t);
    const double align = c > 0.3 ? 0.0 : (c < -0.3 ? 1.0 : 0.5);
    canvas.label(outer * c, outer * sn, text, 6 * s * c, (-8 * sn + 4) * s, align,
                 internal::kSmallSize * s, {40, 40, 40});
  }
  // e_i's name under the 0-degree label, outside the curve.
  canvas.label(outer, 0.0, names[axis][0], 6 * s, 18 * s, 0.0, internal::kSmallSize * s,
               {25, 25, 25});
}

// The first target's angle about `axis` when it lies on the circle.
bool polar_first_target_angle(const tracker::TreSweeps& sweeps, int axis, double* angle) {
  const TrePolarSweep& polar = sweeps.polar;
  const Eigen::Vector3d offset = sweeps.report.targets.front().target - polar.centroid;
  if (std::abs(offset[axis]) > kPolarOnCircle * polar.radius ||
      std::abs(offset.norm() - polar.radius) > kPolarOnCircle * polar.radius) {
    return false;
  }
  *angle = std::atan2(offset[(axis + 2) % 3], offset[(axis + 1) % 3]);
  return true;
}

void draw_polar_panel(Canvas& canvas, const tracker::TreSweeps& sweeps, int axis, double outer,
                      double step) {
  const double s = internal::page_scale(canvas);
  const TrePolarSweep& polar = sweeps.polar;
  const auto index = static_cast<std::size_t>(axis);
  select_polar_panel(canvas, axis, outer);
  draw_polar_grid(canvas, axis, outer, step);
  canvas.label(0.0, kPolarWindow * outer,
               std::string("about ") + kPolarAxisNames[axis] +
                   ", R = " + internal::tre_number_text(polar.radius),
               0.0, -4 * s, 0.5, internal::kLabelSize * s, {25, 25, 25});
  auto xy = [&](const std::vector<double>& rms, std::vector<double>& x, std::vector<double>& y) {
    for (std::size_t k = 0; k < rms.size(); ++k) {
      const double t = polar.angle_deg[k] * kPi / 180.0;
      x.push_back(rms[k] * std::cos(t));
      y.push_back(rms[k] * std::sin(t));
    }
  };
  double t = 0.0;
  if (polar_first_target_angle(sweeps, axis, &t)) {
    internal::draw_line(canvas, {0.0, outer * std::cos(t)}, {0.0, outer * std::sin(t)},
                        {25, 25, 25}, 1.2, true);
  }
  const std::vector<double>& iso = polar.rms_isotropic[index];
  if (!iso.empty()) {
    std::vector<double> x, y;
    xy(iso, x, y);
    internal::draw_line(canvas, x, y, kPolarAxisColours[axis], 1.4, true);
  }
  const TreCurve& curve = polar.curves[index];
  if (curve.tracked) {
    std::vector<double> x, y;
    xy(curve.rms, x, y);
    internal::draw_line(canvas, x, y, kPolarAxisColours[axis], 2.2);
    // The last angle (360) repeats the first.
    const auto [lo, hi] = std::minmax_element(curve.rms.begin(), curve.rms.end() - 1);
    const std::size_t k_hi = static_cast<std::size_t>(hi - curve.rms.begin());
    const std::size_t k_lo = static_cast<std::size_t>(lo - curve.rms.begin());
    canvas.label(0.0, -kPolarWindow * outer,
                 "RMS " + internal::tre_number_text(*lo) + " (" +
                     internal::tre_number_text(polar.angle_deg[k_lo]) + "°) to " +
                     internal::tre_number_text(*hi) + " (" +
                     internal::tre_number_text(polar.angle_deg[k_hi]) + "°)",
                 0.0, 16 * s, 0.5, internal::kSmallSize * s, {25, 25, 25});
  }
}

// RMS against the angle about each axis, on the panels' radial scale.
void draw_polar_strip(Canvas& canvas, const TrePolarSweep& polar, double outer, double step) {
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const internal::Viewport& v = kPolarStrip;
  plstream& pls = canvas.pls();
  pls.vpor(v.left, v.left + v.width, v.bottom, v.bottom + v.height);
  pls.wind(0.0, 360.0, 0.0, outer);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("bcgt", 30.0, 0, "bcgt", step, 0);
  internal::LegendPlacer placer(0.0, 360.0, 0.0, outer, v);
  std::vector<Entry> legend;
  for (int axis = 0; axis < 3; ++axis) {
    const auto index = static_cast<std::size_t>(axis);
    const TreCurve& curve = polar.curves[index];
    if (curve.tracked) {
      internal::draw_line(canvas, polar.angle_deg, curve.rms, kPolarAxisColours[axis], 2.0);
      placer.add_line(polar.angle_deg, curve.rms);
    }
    if (!polar.rms_isotropic[index].empty()) {
      internal::draw_line(canvas, polar.angle_deg, polar.rms_isotropic[index],
                          kPolarAxisColours[axis], 1.4, true);
      placer.add_line(polar.angle_deg, polar.rms_isotropic[index]);
    }
    legend.push_back(Entry::line(std::string("about ") + kPolarAxisNames[axis],
                                 kPolarAxisColours[axis], 2.0 * s));
  }
  // draw_axes() with one tick spacing per axis: every 30 degrees across, the rings' step up.
  pls.col0(internal::kPenInk);
  pls.width(s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("bcnst", 30.0, 0, "bcnstv", step, 0);
  internal::set_text_size(canvas, internal::kLabelSize);
  pls.mtex("b", 2.8, 0.5, 0.5, "angle θ about the axis  [deg]");
  pls.mtex("l", 3.6, 0.5, 0.5, "RMS TRE");
  const auto [lx, ly] = placer.corner(canvas.legend_size(legend, internal::kSmallSize * s));
  canvas.legend(lx, ly, legend, internal::kSmallSize * s);
}

void draw_polar_legend(Canvas& canvas, const tracker::TreSweeps& sweeps) {
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const TrePolarSweep& polar = sweeps.polar;
  std::vector<Entry> legend;
  const TreCurve& curve = polar.curves[0];
  legend.push_back(Entry::text_only(
      curve.tracked ? internal::tre_curve_text(curve) +
                          " (the first target's); radius = RMS TRE in layout units, one colour "
                          "per axis"
                    : internal::tre_curve_text(curve)));
  if (!polar.rms_isotropic[0].empty()) {
    legend.push_back(Entry::line("dashed: Fitzpatrick 1998 (isotropic, every marker)",
                                 internal::kTreIsotropicColour, 1.4 * s, true));
  }
  double angle = 0.0;
  bool on_a_circle = false;
  for (int axis = 0; axis < 3; ++axis)
    on_a_circle |= polar_first_target_angle(sweeps, axis, &angle);
  if (on_a_circle) {
    legend.push_back(Entry::line("the first target's angle (where it lies on the circle)",
                                 {25, 25, 25}, 1.2 * s, true));
  }
  legend.push_back(Entry::text_only(
      "targets g + R (cos θ e_i + sin θ e_j) about each tool axis through the markers' centroid "
      "g = " +
      internal::tre_vector_text(polar.centroid, 2)));
  canvas.legend(0.03, 0.395, legend, internal::kSmallSize * s);
}

void draw_polar_figure(Canvas& canvas, const std::string& name, const tracker::TreSweeps& sweeps,
                       const FigureOptions& options) {
  const TrePolarSweep& polar = sweeps.polar;
  internal::draw_title(
      canvas,
      internal::figure_title(options, "TRE about the tool axes: " + internal::layout_label(name)),
      "RMS TRE of a target at radius R = " + internal::tre_number_text(polar.radius) +
          " from the markers' centroid, at the worst line of sight; " +
          internal::tre_fle_text(sweeps.report.fle));
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const auto index = static_cast<std::size_t>(axis);
    for (double v : polar.curves[index].rms) largest = std::max(largest, v);
    for (double v : polar.rms_isotropic[index]) largest = std::max(largest, v);
  }
  if (!(largest > 0.0)) largest = 1.0;
  const double step = polar_ring_step(largest);
  const double outer = step * std::ceil(largest / step * (1.0 - 1e-12));
  for (int axis = 0; axis < 3; ++axis) draw_polar_panel(canvas, sweeps, axis, outer, step);
  draw_polar_legend(canvas, sweeps);
  draw_polar_strip(canvas, polar, outer, step);
}

}  // namespace

FigureFiles write_tre_polar(const std::string& layout_name, const tracker::TreSweeps& sweeps,
                            const std::filesystem::path& directory, const FigureOptions& options) {
  const FigureFiles files = figure_files("tre_polar", directory, options.format);
  Canvas canvas(files.image, options);
  draw_polar_figure(canvas, layout_name, sweeps, options);
  canvas.finish();
  write_polar_csv(sweeps, files.csv);
  return files;
}

}  // namespace vantage::plot
