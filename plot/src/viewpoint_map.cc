#include "vantage/plot/viewpoint_map.h"

#include <algorithm>
#include <cmath>

#include "canvas.h"
#include "output_file.h"
#include "style.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/analysis/parallel.h"

namespace vantage::plot {
namespace {

using internal::Canvas;

// Worst viewpoints closer than this (pixels at the default size) share one label.
constexpr double kLabelSpacingPx = 140.0;
// Points per great circle n_i^perp (half circle in the upper hemisphere).
constexpr int kCirclePoints = 241;

double error_deg(double pbar) { return kDegreesPerRadian * std::acos(std::clamp(pbar, -1.0, 1.0)); }

// Cell centre coordinate of index k of N over [-1, 1].
double cell_centre(int k, int n) { return -1.0 + (2.0 * k + 1.0) / n; }

void check_data(const ViewpointMapData& data) {
  if (data.worst_viewpoints.empty()) {
    throw InvalidArgument("write_viewpoint_map: worst_viewpoints is empty");
  }
  if (!(data.threshold_deg > 0.0 && data.threshold_deg < 90.0)) {
    throw InvalidArgument("write_viewpoint_map: threshold_deg must be in (0, 90) degrees");
  }
  if (!(data.pbar_min >= 0.0 && data.pbar_min <= 1.0)) {
    throw InvalidArgument("write_viewpoint_map: pbar_min must be in [0, 1]");
  }
  if (data.csv_samples_per_axis < kMinMapSamples || data.csv_samples_per_axis > kMaxMapSamples) {
    throw InvalidArgument("write_viewpoint_map: csv_samples_per_axis must be in [" +
                          std::to_string(kMinMapSamples) + ", " + std::to_string(kMaxMapSamples) +
                          "]");
  }
}

void write_csv(const ViewpointSamples& samples, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "x,y,z,pbar,max_error_deg");
  for (Eigen::Index k = 0; k < samples.viewpoints.cols(); ++k) {
    const Eigen::Vector3d a = samples.viewpoints.col(k);
    csv << a.x() << a.y() << a.z() << samples.pbar(k) << error_deg(samples.pbar(k));
    csv.end_row();
  }
  csv.commit();
}

// The great circle n^perp in the upper hemisphere, from u to -u (u horizontal).
void draw_great_circle(Canvas& canvas, const Eigen::Vector3d& n) {
  const Eigen::Vector3d unit = n.normalized();
  Eigen::Vector3d u = unit.cross(Eigen::Vector3d::UnitZ());
  std::vector<double> x(kCirclePoints), y(kCirclePoints);
  if (u.norm() < 1e-12) return;  // n along z: the circle is the rim, drawn anyway
  u.normalize();
  Eigen::Vector3d v = unit.cross(u);
  if (v.z() < 0.0) v = -v;
  for (int k = 0; k < kCirclePoints; ++k) {
    const double phi = kPi * k / (kCirclePoints - 1);
    const Eigen::Vector2d p = lambert_from_viewpoint(std::cos(phi) * u + std::sin(phi) * v);
    x[k] = p.x();
    y[k] = p.y();
  }
  canvas.pls().line(kCirclePoints, x.data(), y.data());
}

void draw_threshold_contour(Canvas& canvas, const ViewpointSamples& samples, double threshold) {
  const int n = samples.samples_per_axis;
  std::vector<double> values(static_cast<std::size_t>(n) * n);
  std::vector<const double*> columns(n);
  std::vector<double> grid(n);
  for (int i = 0; i < n; ++i) {
    grid[i] = cell_centre(i, n);
    for (int j = 0; j < n; ++j) {
      // f[i][j] at x = grid[i], y = grid[j]; row r of error_deg is at y = grid[n - 1 - r].
      values[static_cast<std::size_t>(i) * n + j] = samples.error_deg(n - 1 - j, i);
    }
    columns[i] = values.data() + static_cast<std::size_t>(i) * n;
  }
  PLcGrid coordinates{grid.data(), grid.data(), nullptr, n, n, 0};
  const double level = threshold;
  canvas.clip_to_unit_disc();
  canvas.pls().cont(columns.data(), n, n, 1, n, 1, n, &level, 1, plcallback::tr1, &coordinates);
  canvas.unclip();
}

// The worst viewpoints (tied ones close together share one label) and the paper's LMI one.
void draw_viewpoints(Canvas& canvas, const ViewpointMapData& data, const std::string& worst_text) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const Rgb ink{25, 25, 25};
  const double small = internal::kSmallSize * s;
  const Eigen::Vector2d lmi = lambert_from_viewpoint(data.paper_lmi_viewpoint);
  canvas.marker(lmi.x(), lmi.y(), 9.0 * s, kPaperLmiColour, Canvas::Shape::kDiamond);
  for (const Eigen::Vector3d& a : data.worst_viewpoints) {
    const Eigen::Vector2d p = lambert_from_viewpoint(a);
    canvas.marker(p.x(), p.y(), 6.0 * s, kWorstViewpointColour);
  }
  // Tied viewpoints close together share one label (above the first of them).
  std::vector<Eigen::Vector2d> labelled;
  for (const Eigen::Vector3d& a : data.worst_viewpoints) {
    const Eigen::Vector2d p = lambert_from_viewpoint(a);
    const Eigen::Vector2d at = canvas.device(p.x(), p.y());
    const bool near = std::any_of(labelled.begin(), labelled.end(), [&](const Eigen::Vector2d& q) {
      return (q - at).norm() < kLabelSpacingPx * s;
    });
    if (near) continue;
    labelled.push_back(at);
    canvas.label(p.x(), p.y(), worst_text, 0.0, -19 * s, 0.5, small, ink, {255, 255, 255}, 0.85);
  }
  canvas.label(lmi.x(), lmi.y(), "LMI p̄ " + fixed(data.paper_lmi_pbar, 4), 16 * s, 0.0, 0.0, small,
               ink, {255, 220, 255}, 0.85);
}

void draw_map_legend(Canvas& canvas, const ViewpointMapData& data, bool has_contour) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const double max_error = error_deg(data.pbar_min);
  const std::size_t ties = data.worst_viewpoints.size();
  using Entry = Canvas::LegendEntry;
  const std::vector<Entry> legend{
      Entry::marker(ties == 1 ? "global worst viewpoint (Theorem 6)"
                              : std::to_string(ties) + " tied global worst viewpoints",
                    kWorstViewpointColour),
      Entry::text_only("p̄_min " + fixed(data.pbar_min, 4) + ", error " + fixed(max_error, 2) + "°"),
      Entry::marker("paper's single LMI (one cell)", kPaperLmiColour, Canvas::Shape::kDiamond),
      Entry::text_only("p̄ " + fixed(data.paper_lmi_pbar, 4) + ", error " +
                       fixed(error_deg(data.paper_lmi_pbar), 2) + "°"),
      Entry::line(has_contour ? "error = " + fixed(data.threshold_deg, 1) + "° contour"
                              : "no direction exceeds " + fixed(data.threshold_deg, 1) + "°",
                  kThresholdColour, 2.4 * s),
      Entry::line("planes nᵢ⊥ (error 0), " + std::to_string(data.vectors.cols()) + " vectors",
                  {150, 150, 150}, 1.0 * s)};
  canvas.legend(0.99, 0.82, legend, internal::kSmallSize * s, 1.0);
}

void draw_map(Canvas& canvas, const ViewpointMapData& data, const ViewpointSamples& samples,
              const FigureOptions& options) {
  using internal::fixed;
  const double s = internal::page_scale(canvas);
  const double max_error = error_deg(data.pbar_min);
  const std::string worst_text = "p̄ " + fixed(data.pbar_min, 4) + ", " + fixed(max_error, 2) + "°";
  internal::draw_title(
      canvas,
      internal::figure_title(options, "Viewpoint map: " + internal::layout_label(data.layout_name)),
      "worst-case error arccos p̄(a) for every viewing direction a; upper hemisphere (a ≡ −a), "
      "Lambert equal-area");

  plstream& pls = canvas.pls();
  pls.vpas(0.01, 0.59, 0.04, 0.87, 1.0);
  pls.wind(-1.1, 1.1, -1.1, 1.1);
  canvas.clip_to_unit_disc();
  canvas.paint_raster(internal::value_raster(samples.error_deg, 0.0, max_error), -1.0, 1.0, -1.0,
                      1.0);
  canvas.unclip();

  pls.col0(internal::kPenGreatCircle);
  pls.width(0.8 * s);
  for (Eigen::Index i = 0; i < data.vectors.cols(); ++i)
    draw_great_circle(canvas, data.vectors.col(i));

  const bool has_contour = data.threshold_deg < max_error;
  if (has_contour) {
    pls.col0(internal::kPenThreshold);
    pls.width(2.4 * s);
    draw_threshold_contour(canvas, samples, data.threshold_deg);
  }

  pls.col0(internal::kPenInk);
  pls.width(1.6 * s);
  pls.arc(0.0, 0.0, 1.0, 1.0, 0.0, 360.0, 0.0, false);
  const Rgb ink{25, 25, 25};
  const double small = internal::kSmallSize * s;
  canvas.label(1.0, 0.0, "+x", 8 * s, 0.0, 0.0, small, ink);
  canvas.label(-1.0, 0.0, "−x", -8 * s, 0.0, 1.0, small, ink);
  canvas.label(0.0, 1.0, "+y", 0.0, -10 * s, 0.5, small, ink);
  canvas.label(0.0, -1.0, "−y", 0.0, 11 * s, 0.5, small, ink);
  canvas.label(0.0, 0.0, "+z", 0.0, 14 * s, 0.5, small, {255, 255, 255}, {25, 25, 25}, 0.55);

  draw_viewpoints(canvas, data, worst_text);

  internal::draw_colour_bar(canvas, 0.625, 0.65, 0.10, 0.82, 0.0, max_error,
                            "worst-case error arccos p̄(a)  [deg]");

  draw_map_legend(canvas, data, has_contour);
}

}  // namespace

Eigen::Vector2d lambert_from_viewpoint(const Eigen::Vector3d& a) {
  const Eigen::Vector3d up = a.z() < 0.0 ? Eigen::Vector3d(-a) : a;
  const double s = std::sqrt(std::max(0.0, 1.0 + up.z()));
  if (s == 0.0) return {0.0, 0.0};
  return {up.x() / s, up.y() / s};
}

Eigen::Vector3d viewpoint_from_lambert(const Eigen::Vector2d& xy) {
  double r2 = xy.squaredNorm();
  Eigen::Vector2d p = xy;
  if (r2 > 1.0) {
    p /= std::sqrt(r2);
    r2 = 1.0;
  }
  const double s = std::sqrt(2.0 - r2);
  return Eigen::Vector3d(p.x() * s, p.y() * s, 1.0 - r2).normalized();
}

ViewpointSamples sample_viewpoints(const Eigen::Matrix3Xd& vectors, int samples_per_axis,
                                   int threads) {
  if (samples_per_axis < kMinMapSamples || samples_per_axis > kMaxMapSamples) {
    throw InvalidArgument("sample_viewpoints: samples_per_axis must be in [" +
                          std::to_string(kMinMapSamples) + ", " + std::to_string(kMaxMapSamples) +
                          "], got " + std::to_string(samples_per_axis));
  }
  const int n = samples_per_axis;
  ViewpointSamples samples;
  samples.samples_per_axis = n;
  samples.error_deg.resize(n, n);
  samples.inside.resize(n, n);
  Eigen::MatrixXd pbar_grid(n, n);
  parallel_blocks(n, threads, [&](long begin, long end) {
    Eigen::Matrix3Xd block(3, (end - begin) * n);
    for (long r = begin; r < end; ++r) {
      for (int c = 0; c < n; ++c) {
        const Eigen::Vector2d xy(cell_centre(c, n), cell_centre(n - 1 - static_cast<int>(r), n));
        block.col((r - begin) * n + c) = viewpoint_from_lambert(xy);
      }
    }
    const Eigen::VectorXd pbar = pbar_at_viewpoints(vectors, block);
    for (long r = begin; r < end; ++r) {
      for (int c = 0; c < n; ++c) {
        const double p = pbar((r - begin) * n + c);
        pbar_grid(r, c) = p;
        samples.error_deg(r, c) = error_deg(p);
        const double x = cell_centre(c, n), y = cell_centre(n - 1 - static_cast<int>(r), n);
        samples.inside(r, c) = x * x + y * y <= 1.0 ? 1 : 0;
      }
    }
  });
  const long count = samples.inside.cast<long>().sum();
  samples.viewpoints.resize(3, count);
  samples.pbar.resize(count);
  long k = 0;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      if (!samples.inside(r, c)) continue;
      samples.viewpoints.col(k) =
          viewpoint_from_lambert({cell_centre(c, n), cell_centre(n - 1 - r, n)});
      samples.pbar(k) = pbar_grid(r, c);
      ++k;
    }
  }
  return samples;
}

FigureFiles write_viewpoint_map(const ViewpointMapData& data,
                                const std::filesystem::path& directory,
                                const FigureOptions& options) {
  check_data(data);
  const ViewpointSamples samples =
      sample_viewpoints(data.vectors, data.samples_per_axis, options.threads);
  const FigureFiles files = figure_files("viewpoint_map", directory, options.format);
  Canvas canvas(files.image, options);
  draw_map(canvas, data, samples, options);
  canvas.finish();
  const int csv_n = std::min(data.csv_samples_per_axis, data.samples_per_axis);
  write_csv(csv_n == samples.samples_per_axis
                ? samples
                : sample_viewpoints(data.vectors, csv_n, options.threads),
            files.csv);
  return files;
}

}  // namespace vantage::plot
