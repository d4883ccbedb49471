#include "vantage/plot/placement_figure.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "body_drawing.h"
#include "canvas.h"
#include "experiment_plotting.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

constexpr double kViewMargin = 1.12;    // a view's half-width over the scene's largest extent
constexpr double kFlattestView = 0.45;  // least height / width of a view
constexpr double kViewTop = 0.88;       // page fractions of the views' band
constexpr double kViewBottom = 0.40;
constexpr double kSiteNormalLength = 0.12;  // of a view's half-width
constexpr double kKChartTick = 0.2;         // p-bar_min grid of the chart
constexpr Rgb kSiteColour{150, 150, 150};
constexpr Rgb kChosenColour{215, 48, 39};
constexpr Rgb kRandomColour{33, 113, 181};
constexpr Rgb kPlacementInk{25, 25, 25};

// An orthographic view from azimuth az (from +x towards +y) and elevation el, +z up.
struct PlacementView {
  Eigen::Vector3d right, up, toward;
  Eigen::Vector2d operator()(const Eigen::Vector3d& p) const { return {p.dot(right), p.dot(up)}; }
};

PlacementView placement_view_from(double az_deg, double el_deg) {
  const double az = az_deg / kDegreesPerRadian, el = el_deg / kDegreesPerRadian;
  PlacementView v;
  v.right = Eigen::Vector3d(-std::sin(az), std::cos(az), 0.0);
  v.up = Eigen::Vector3d(-std::sin(el) * std::cos(az), -std::sin(el) * std::sin(az), std::cos(el));
  v.toward =
      Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  return v;
}

// Centre and scale of the scene: the body's (or the sites') bounding box, to unit radius.
struct PlacementFrame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double scale = 1.0;
  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return (p - centre) * scale; }
};

PlacementFrame placement_frame(const PlacementFigureData& data) {
  const Eigen::Matrix3Xd& cloud = data.body != nullptr && data.body->vertices.cols() > 0
                                      ? data.body->vertices
                                      : data.placement.site_points;
  PlacementFrame f;
  if (cloud.cols() == 0) return f;
  f.centre = 0.5 * (cloud.rowwise().minCoeff() + cloud.rowwise().maxCoeff());
  const double radius = (cloud.colwise() - f.centre).colwise().norm().maxCoeff();
  if (radius > 0.0) f.scale = 1.0 / radius;
  return f;
}

void draw_site_arrow(Canvas& canvas, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  canvas.pls().join(a.x(), a.y(), b.x(), b.y());
  const Eigen::Vector2d along = b - a;
  const double length = along.norm();
  if (length < 1e-3) return;
  const Eigen::Vector2d back = -along / length * std::min(0.06, 0.5 * length);
  for (const double turn : {0.45, -0.45}) {
    const Eigen::Vector2d wing(std::cos(turn) * back.x() - std::sin(turn) * back.y(),
                               std::sin(turn) * back.x() + std::cos(turn) * back.y());
    canvas.pls().join(b.x(), b.y(), b.x() + wing.x(), b.y() + wing.y());
  }
}

// One view of the body: candidate sites faint, the chosen ones with normals and labels; only
// sites whose normal faces the camera.
// The half-extents (x, y) of both views: the largest projected extent of the body (or the
// sites) in either, with a margin.
Eigen::Vector2d placement_window(const PlacementFigureData& data,
                                 const std::vector<PlacementView>& views) {
  const PlacementFrame frame = placement_frame(data);
  const Eigen::Matrix3Xd& cloud = data.body != nullptr && data.body->vertices.cols() > 0
                                      ? data.body->vertices
                                      : data.placement.site_points;
  Eigen::Vector2d extent = Eigen::Vector2d::Zero();
  for (const PlacementView& view : views) {
    for (Eigen::Index i = 0; i < cloud.cols(); ++i) {
      extent = extent.cwiseMax(view(frame(cloud.col(i))).cwiseAbs());
    }
  }
  // Not flatter than kFlattestView, so that normals and labels above and below the body fit.
  extent.y() = std::max(extent.y(), kFlattestView * extent.x());
  extent.x() = std::max(extent.x(), extent.y());
  return extent.x() > 0.0 ? Eigen::Vector2d(kViewMargin * extent) : Eigen::Vector2d(1.0, 1.0);
}

void draw_body_view(Canvas& canvas, const PlacementFigureData& data, const PlacementView& view,
                    const Eigen::Vector2d& window, const std::string& caption, double vx0,
                    double vx1) {
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  // Top-aligned under the title; as tall as the aspect asks, down to kViewBottom at most.
  const double aspect = window.y() / window.x();
  const double height =
      std::min(kViewTop - kViewBottom, (vx1 - vx0) * canvas.width() * aspect / canvas.height());
  const double width = height * canvas.height() / (aspect * canvas.width());
  const double mid = 0.5 * (vx0 + vx1);
  pls.vpor(mid - 0.5 * width, mid + 0.5 * width, kViewTop - height, kViewTop);
  pls.wind(-window.x(), window.x(), -window.y(), window.y());
  const PlacementFrame frame = placement_frame(data);
  if (data.body != nullptr) {
    internal::draw_body(canvas, *data.body, frame, view, view.toward);
  }
  const Eigen::Matrix3Xd& sites = data.placement.site_points;
  const Eigen::Matrix3Xd& site_normals = data.placement.site_normals;
  for (Eigen::Index i = 0; i < sites.cols(); ++i) {
    if (site_normals.col(i).dot(view.toward) <= 0.0) continue;
    const Eigen::Vector2d p = view(frame(sites.col(i)));
    canvas.marker(p.x(), p.y(), 1.8 * s, kSiteColour, Canvas::Shape::kCircle, kSiteColour);
  }
  pls.col0(internal::kPenNormal);
  pls.width(2.0 * s);
  for (Eigen::Index k = 0; k < data.markers.cols(); ++k) {
    if (data.normals.col(k).dot(view.toward) <= 0.0) continue;
    const Eigen::Vector3d p = frame(data.markers.col(k));
    draw_site_arrow(canvas, view(p),
                    view(p + kSiteNormalLength * window.x() * data.normals.col(k).normalized()));
  }
  for (Eigen::Index k = 0; k < data.markers.cols(); ++k) {
    if (data.normals.col(k).dot(view.toward) <= 0.0) continue;
    const Eigen::Vector2d p = view(frame(data.markers.col(k)));
    canvas.marker(p.x(), p.y(), 5.5 * s, kChosenColour);
    const int site = data.placement.chosen[static_cast<std::size_t>(k)];
    canvas.label(p.x(), p.y(), site < 0 ? "kept" : "s" + std::to_string(site), 8 * s, 12 * s, 0.0,
                 internal::kSmallSize * s, kPlacementInk, {255, 255, 255}, 0.75);
  }
  canvas.label(0.0, -window.y(), caption, 0.0, 2 * s, 0.5, internal::kLabelSize * s, kPlacementInk);
}

struct KChartRange {
  double k_lo, k_hi, lo;
};

KChartRange k_chart_range(const PlacementFigureData& data) {
  const int markers = static_cast<int>(data.markers.cols());
  KChartRange r{static_cast<double>(markers), static_cast<double>(markers), data.pbar_min};
  for (const LayoutPlacement::Step& step : data.placement.steps) {
    r.k_lo = std::min(r.k_lo, static_cast<double>(step.k));
    if (step.coverage > 0.0) r.lo = std::min(r.lo, step.pbar_min);
  }
  if (data.placement.random_trials > 0)
    r.lo = std::min(r.lo, data.placement.random_median_pbar_min);
  r.lo = std::max(0.0, std::floor((r.lo - 0.05) * 10.0) / 10.0);
  if (r.k_hi <= r.k_lo) r.k_lo = r.k_hi - 1.0;
  return r;
}

// p-bar_min against K: the greedy steps, the answer, the random baseline.
void draw_k_chart(Canvas& canvas, const PlacementFigureData& data) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  const KChartRange r = k_chart_range(data);
  const internal::Viewport viewport{0.09, 0.42, 0.08, 0.25};
  pls.vpor(viewport.left, viewport.left + viewport.width, viewport.bottom,
           viewport.bottom + viewport.height);
  pls.wind(r.k_lo - 0.5, r.k_hi + 0.5, r.lo, 1.0);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("g", 1.0, 0, "g", kKChartTick, 0);

  std::vector<double> x, y;
  for (const LayoutPlacement::Step& step : data.placement.steps) {
    if (step.coverage <= 0.0) continue;  // nothing trackable: no value to plot
    x.push_back(step.k);
    y.push_back(step.pbar_min);
  }
  if (!x.empty()) {
    pls.col0(internal::kPenWorst);
    pls.width(2.0 * s);
    pls.line(static_cast<int>(x.size()), x.data(), y.data());
  }
  for (const LayoutPlacement::Step& step : data.placement.steps) {
    if (step.coverage <= 0.0) continue;
    const bool complete = step.coverage >= 1.0;
    canvas.marker(step.k, step.pbar_min, 5.0 * s,
                  complete ? kWorstViewpointColour : Rgb{255, 255, 255}, Canvas::Shape::kCircle,
                  kWorstViewpointColour);
  }
  const double k = static_cast<double>(data.markers.cols());
  if (data.placement.random_trials > 0) {
    canvas.marker(k, data.placement.random_best_pbar_min, 6.0 * s, kRandomColour,
                  Canvas::Shape::kSquare);
    canvas.marker(k, data.placement.random_median_pbar_min, 6.0 * s, {255, 255, 255},
                  Canvas::Shape::kSquare, kRandomColour);
  }
  canvas.marker(k, data.pbar_min, 8.0 * s, kChosenColour, Canvas::Shape::kDiamond);
  canvas.label(k, data.pbar_min, fixed(data.pbar_min, 4), -14 * s, 14 * s, 1.0,
               internal::kSmallSize * s, kPlacementInk, {255, 255, 255}, 0.8);
  internal::draw_axes(canvas, "bcnst", "bcnstv", 0.0, 0, "K: markers placed", 2.6,
                      "certified p̄_min", 4.6);
}

// A camera or tracker placement: its objective is charted instead of p-bar_min.
bool charts_objective(const PlacementFigureData& data) {
  return data.sensor && !std::isnan(data.placement.objective_value);
}

// The objective in a few words, and a value of it with its unit.
std::string objective_name(const LayoutSensor& sensor) {
  return sensor.kind == LayoutSensor::Kind::kCamera ? "camera, " + sensor.statistic + " rot_rms"
                                                    : std::string("tracker, worst RMS TRE");
}

std::string objective_text(const LayoutSensor& sensor, double value) {
  if (!std::isfinite(value)) {
    return sensor.kind == LayoutSensor::Kind::kCamera ? "incomplete or unbounded" : "incomplete";
  }
  // Four significant digits: a TRE in metres is a few 1e-4.
  std::ostringstream out;
  out.precision(4);
  out << value << (sensor.kind == LayoutSensor::Kind::kCamera ? "°" : "");
  return out.str();
}

// The objective against K: the greedy steps' search values, the answer and the random baseline
// (only finite values: +inf is a choice that tracks nothing, or past the camera's limit).
void draw_objective_chart(Canvas& canvas, const PlacementFigureData& data) {
  const LayoutPlacement& p = data.placement;
  const double s = internal::page_scale(canvas);
  plstream& pls = canvas.pls();
  const double k = static_cast<double>(data.markers.cols());
  double k_lo = k, hi = 0.0;
  const auto include = [&hi](double v) {
    if (std::isfinite(v)) hi = std::max(hi, v);
  };
  for (const LayoutPlacement::Step& step : p.steps) {
    k_lo = std::min(k_lo, static_cast<double>(step.k));
    include(step.objective);
  }
  include(p.objective_value);
  if (p.random_trials > 0) {
    include(p.random_best_objective);
    include(p.random_median_objective);
  }
  if (k_lo >= k) k_lo = k - 1.0;
  hi = hi > 0.0 ? 1.15 * hi : 1.0;
  const internal::Viewport viewport{0.09, 0.42, 0.08, 0.25};
  pls.vpor(viewport.left, viewport.left + viewport.width, viewport.bottom,
           viewport.bottom + viewport.height);
  pls.wind(k_lo - 0.5, k + 0.5, 0.0, hi);
  pls.col0(internal::kPenGrid);
  pls.width(0.8 * s);
  internal::set_text_size(canvas, internal::kSmallSize);
  pls.box("g", 1.0, 0, "g", 0.0, 0);
  std::vector<double> x, y;
  for (const LayoutPlacement::Step& step : p.steps) {
    if (!std::isfinite(step.objective)) continue;
    x.push_back(step.k);
    y.push_back(step.objective);
  }
  if (!x.empty()) {
    pls.col0(internal::kPenWorst);
    pls.width(2.0 * s);
    pls.line(static_cast<int>(x.size()), x.data(), y.data());
  }
  for (const LayoutPlacement::Step& step : p.steps) {
    if (!std::isfinite(step.objective)) continue;
    canvas.marker(step.k, step.objective, 5.0 * s,
                  step.coverage >= 1.0 ? kWorstViewpointColour : Rgb{255, 255, 255},
                  Canvas::Shape::kCircle, kWorstViewpointColour);
  }
  if (p.random_trials > 0) {
    if (std::isfinite(p.random_best_objective)) {
      canvas.marker(k, p.random_best_objective, 6.0 * s, kRandomColour, Canvas::Shape::kSquare);
    }
    if (std::isfinite(p.random_median_objective)) {
      canvas.marker(k, p.random_median_objective, 6.0 * s, {255, 255, 255}, Canvas::Shape::kSquare,
                    kRandomColour);
    }
  }
  if (std::isfinite(p.objective_value)) {
    canvas.marker(k, p.objective_value, 8.0 * s, kChosenColour, Canvas::Shape::kDiamond);
    canvas.label(k, p.objective_value, objective_text(*data.sensor, p.objective_value), -14 * s,
                 14 * s, 1.0, internal::kSmallSize * s, kPlacementInk, {255, 255, 255}, 0.8);
  }
  const bool camera = data.sensor->kind == LayoutSensor::Kind::kCamera;
  internal::draw_axes(canvas, "bcnst", "bcnstv", 0.0, 0, "K: markers placed", 2.6,
                      camera ? data.sensor->statistic + " rot_rms (°)" : "worst RMS TRE", 4.6);
}

void draw_placement_legend(Canvas& canvas, const PlacementFigureData& data) {
  using internal::fixed;
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const LayoutPlacement& p = data.placement;
  const double error_deg = std::acos(std::clamp(data.pbar_min, 0.0, 1.0)) * kDegreesPerRadian;
  const bool objective = charts_objective(data);
  const std::string answer =
      objective
          ? objective_name(*data.sensor) + " " + objective_text(*data.sensor, p.objective_value)
          : "p̄_min " + fixed(data.pbar_min, 4) + " (" + fixed(error_deg, 2) + "°)";
  std::vector<Entry> legend{
      Entry::marker(std::to_string(p.site_points.cols()) + " candidate sites", kSiteColour),
      Entry::marker(std::to_string(data.markers.cols()) + " chosen sites, outward normals",
                    kChosenColour),
      Entry::marker("answer: " + answer + ", coverage " + fixed(100.0 * data.coverage, 1) + " %",
                    kChosenColour, Canvas::Shape::kDiamond)};
  if (!p.steps.empty()) {
    legend.push_back(Entry::line_marker("greedy steps (hollow: workspace not yet covered)",
                                        kWorstViewpointColour, 2.0 * s, Canvas::Shape::kCircle));
  }
  if (p.random_trials > 0 && objective) {
    legend.push_back(Entry::marker(
        "best of " + std::to_string(p.random_trials) +
            " random subsets: " + objective_text(*data.sensor, p.random_best_objective),
        kRandomColour, Canvas::Shape::kSquare));
    legend.push_back(Entry::text_only("  median " +
                                      objective_text(*data.sensor, p.random_median_objective) +
                                      " (hollow square)"));
  } else if (p.random_trials > 0) {
    legend.push_back(Entry::marker("best of " + std::to_string(p.random_trials) +
                                       " random subsets: " + fixed(p.random_best_pbar_min, 4),
                                   kRandomColour, Canvas::Shape::kSquare));
    legend.push_back(Entry::text_only("  median " + fixed(p.random_median_pbar_min, 4) +
                                      " (hollow square; 0: untrackable somewhere)"));
  }
  if (data.body != nullptr) {
    legend.push_back(
        Entry::marker("body mesh (" + std::to_string(data.body->triangles.cols()) + " triangles)",
                      {200, 204, 208}, Canvas::Shape::kSquare));
  }
  canvas.legend(0.56, 0.33, legend, internal::kSmallSize * s);
}

void write_csv(const PlacementFigureData& data, const std::filesystem::path& path) {
  // A camera or tracker placement adds its objective (empty: untracked or unbounded).
  const bool objective = charts_objective(data);
  const LayoutPlacement& p = data.placement;
  internal::CsvWriter csv(
      path, objective ? "series,k,pbar_min,coverage,objective" : "series,k,pbar_min,coverage");
  const auto end_row = [&](double value) {
    if (objective) {
      if (std::isfinite(value)) {
        csv << value;
      } else {
        csv << "";
      }
    }
    csv.end_row();
  };
  for (const LayoutPlacement::Step& step : p.steps) {
    csv << "step" << step.k << step.pbar_min << step.coverage;
    end_row(step.objective);
  }
  const int k = static_cast<int>(data.markers.cols());
  csv << "answer" << k << data.pbar_min << data.coverage;
  end_row(p.objective_value);
  if (p.random_trials > 0) {
    csv << "random_best" << k << p.random_best_pbar_min << "";
    end_row(p.random_best_objective);
    csv << "random_median" << k << p.random_median_pbar_min << "";
    end_row(p.random_median_objective);
  }
  csv.commit();
}

void check_data(const PlacementFigureData& data) {
  const LayoutPlacement& p = data.placement;
  if (data.normals.cols() != data.markers.cols()) {
    throw InvalidArgument("write_placement_figure: normals: expected one per marker");
  }
  if (p.chosen.size() != static_cast<std::size_t>(data.markers.cols())) {
    throw InvalidArgument("write_placement_figure: placement.chosen: expected one per marker");
  }
  if (p.site_normals.cols() != p.site_points.cols()) {
    throw InvalidArgument("write_placement_figure: placement.site_normals: expected one per site");
  }
  for (int c : p.chosen) {
    if (c < -1 || c >= p.site_points.cols()) {
      throw InvalidArgument("write_placement_figure: placement.chosen: not a site index");
    }
  }
  if (!(data.pbar_min >= 0.0 && data.pbar_min <= 1.0)) {
    throw InvalidArgument("write_placement_figure: pbar_min must be in [0, 1]");
  }
}

}  // namespace

FigureFiles write_placement_figure(const PlacementFigureData& data,
                                   const std::filesystem::path& directory,
                                   const FigureOptions& options) {
  check_data(data);
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options", why);
  const FigureFiles files = figure_files("placement", directory, options.format);
  Canvas canvas(files.image, options);
  internal::draw_title(
      canvas,
      internal::figure_title(options, "Placement: " + internal::layout_label(data.layout_name)),
      std::to_string(data.markers.cols()) + " of " +
          std::to_string(data.placement.site_points.cols()) + " candidate sites (vantage place" +
          (charts_objective(data) ? ", objective " + objective_name(*data.sensor) : "") +
          "); orthographic views, +z up");
  const double az = kPlacementAzimuthDeg, el = kPlacementElevationDeg;
  const std::vector<PlacementView> views{placement_view_from(az, el),
                                         placement_view_from(az + 180.0, el)};
  const Eigen::Vector2d window = placement_window(data, views);
  draw_body_view(canvas, data, views[0], window, "front: azimuth " + internal::fixed(az, 0) + "°",
                 0.02, 0.49);
  draw_body_view(canvas, data, views[1], window,
                 "back: azimuth " + internal::fixed(az + 180.0, 0) + "°", 0.51, 0.98);
  if (charts_objective(data)) {
    draw_objective_chart(canvas, data);
  } else {
    draw_k_chart(canvas, data);
  }
  draw_placement_legend(canvas, data);
  canvas.finish();
  write_csv(data, files.csv);
  return files;
}

}  // namespace vantage::plot
