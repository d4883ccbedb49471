// The CRB map (crb_figures.h): the two equal-area discs shaded by the pose bound rot_rms_deg of
// a pinhole camera at each viewing direction, on a log colour scale, untrackable grey.

#include <algorithm>
#include <cmath>
#include <limits>

#include "canvas.h"
#include "output_file.h"
#include "sphere_map_drawing.h"
#include "sphere_value_cells.h"
#include "style.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/crb_figures.h"
#include "vantage/plot/sphere_map.h"
#include "vantage/plot/viewpoint_map.h"
#include "vantage/plot/visibility_maps.h"

namespace vantage::plot {
namespace {

using camera::PoseCrbAt;
using camera::PoseCrbMap;
using internal::Canvas;

// The best direction's marker: white, apart from the red worst and from every viridis colour.
constexpr Rgb kBestColour{255, 255, 255};
// A map whose bound varies by less than this factor still spans this much of the colour scale
// (a flat map would otherwise divide by zero).
constexpr double kMinDecades = 0.1;
// Count regions smaller than this fraction of a disc carry no number (too small to read).
constexpr double kLabelledRegionFraction = 0.006;

// The bound at every cell centre of both discs: the cells, and rot_rms_deg as their value
// (NaN: not trackable).
internal::ValueCells sample_cells(const camera::PoseCrbModel& model, int n, int threads) {
  return internal::sample_value_cells(n, threads, [&](const Eigen::Vector3d& a) {
    const PoseCrbAt at = model.at(a);
    return internal::CellValue{static_cast<int>(at.visible_markers.size()), at.trackable,
                               model.in_workspace(a), at.rot_rms_deg};
  });
}

// The colour scale's decades: from the smallest cell (or the best direction) to the worst.
struct LogScale {
  double lo = 0.0;
  double hi = 1.0;
};

LogScale log_scale(const internal::ValueCells& cells, const PoseCrbMap& map) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  internal::widen_to_cells(cells, &lo, &hi);
  if (map.status == PoseCrbMap::Status::kOk) {
    lo = std::min(lo, map.best.rot_rms_deg);
    // An unbounded worst: the scale ends at the largest figure reported.
    hi = std::max(hi, map.worst.unbounded ? PoseCrbAt::kMaxRotRmsDeg : map.worst.rot_rms_deg);
  }
  if (!(hi > 0.0) || !std::isfinite(lo)) return {};
  LogScale scale{std::floor(std::log10(lo) * 10.0) / 10.0, std::log10(hi)};
  scale.hi = std::max(scale.hi, scale.lo + kMinDecades);
  return scale;
}

internal::Raster bound_raster(const internal::ValueCells& cells, int d, const LogScale& scale) {
  return internal::trackable_raster(cells.samples, d, [&](int r, int c) {
    return value_colour(std::log10(cells.value[d](r, c)), scale.lo, scale.hi);
  });
}

void write_row(internal::CsvWriter& csv, const char* kind, int disc, const PoseCrbAt& at) {
  csv << kind << disc << at.direction.x() << at.direction.y() << at.direction.z()
      << static_cast<long>(at.visible_markers.size()) << (at.trackable ? 1 : 0);
  if (at.trackable) {
    csv << at.rot_rms_deg << at.trans_rms;
  } else {
    csv << ""
        << "";
  }
  csv.end_row();
}

void write_csv(const CrbMapData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "kind,disc,x,y,z,visible,trackable,rot_rms_deg,trans_rms");
  const PoseCrbMap& map = data.report->map;
  if (map.status == PoseCrbMap::Status::kOk) {
    write_row(csv, "worst", sphere_map_from_direction(map.worst.direction).disc, map.worst);
    write_row(csv, "best", sphere_map_from_direction(map.best.direction).disc, map.best);
  }
  const int n = std::min(data.csv_samples_per_axis, data.samples_per_axis);
  for (int d = 0; d < 2; ++d) {
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const Eigen::Vector2d xy(SphereSamples::cell_centre(c, n),
                                 SphereSamples::cell_centre(n - 1 - r, n));
        if (xy.squaredNorm() > 1.0) continue;
        write_row(csv, "cell", d, data.model->at(direction_from_sphere_map(d, xy)));
      }
    }
  }
  csv.commit();
}

std::string degrees(double value) {
  return internal::fixed(value, value >= 100.0 ? 0 : (value >= 1.0 ? 2 : 4)) + "°";
}

std::string at_summary(const PoseCrbAt& at) {
  if (at.unbounded) {
    return "unbounded (> 45°), " + std::to_string(at.visible_markers.size()) + " markers seen";
  }
  return degrees(at.rot_rms_deg) + ", trans_rms " + internal::fixed(at.trans_rms, 4) + ", " +
         std::to_string(at.visible_markers.size()) + " markers seen";
}

void draw_legends(Canvas& canvas, const camera::PoseCrbReport& report,
                  const internal::ValueCells& cells) {
  using internal::fixed;
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const PoseCrbMap& map = report.map;
  std::vector<Entry> left;
  if (map.status != PoseCrbMap::Status::kOk) {
    left.push_back(Entry::text_only(
        map.status == PoseCrbMap::Status::kIllConditioned
            ? "no sampled direction is trackable: the pose is not determined to first order"
            : (map.status == PoseCrbMap::Status::kUnbounded
                   ? "no sampled direction is trackable: the bound is unbounded (above 45°)"
                   : "no sampled direction is trackable")));
  } else {
    left.push_back(Entry::marker("worst direction: " + at_summary(map.worst) + " (refined)",
                                 kWorstViewpointColour));
    left.push_back(Entry::marker("best direction: " + at_summary(map.best), kBestColour,
                                 Canvas::Shape::kDiamond));
  }
  left.push_back(Entry::marker("untrackable: < 3 (min_visible) seen, F singular, or unbounded",
                               kUntrackableColour, Canvas::Shape::kSquare));
  left.push_back(
      Entry::line("visible-marker count changes (numbers: markers seen)", {25, 25, 25}, 1.0 * s));
  canvas.legend(0.02, 0.215, left, internal::kSmallSize * s, 0.0);

  std::vector<Entry> right;
  if (map.status == PoseCrbMap::Status::kOk) {
    right.push_back(Entry::text_only("rot_rms p50 " + degrees(map.percentiles.p50) + ", p95 " +
                                     degrees(map.percentiles.p95) + ", p99 " +
                                     degrees(map.percentiles.p99)));
    right.push_back(Entry::text_only(
        std::string("sliver: ") + (map.sliver ? "yes" : "no") +
        (map.worst_region_fills_workspace
             ? std::string(" (within 2× of the worst: the whole workspace)")
             : " (within 2× of the worst: " + fixed(map.worst_region_width_deg, 2) + "° across)")));
  }
  right.push_back(Entry::text_only("trackable: " + fixed(100.0 * map.trackable_fraction, 1) +
                                   " % (" + std::to_string(map.samples.size()) +
                                   " directions), unbounded " +
                                   fixed(100.0 * map.unbounded_fraction, 1) + " %; on this map " +
                                   fixed(100.0 * cells.samples.trackable_fraction(), 1) + " %"));
  right.push_back(
      Entry::text_only("affine bound arccos p̄_min: " + degrees(report.affine_bound_deg)));
  canvas.legend(0.98, 0.215, right, internal::kSmallSize * s, 1.0);
}

void draw_extremes(Canvas& canvas, const PoseCrbMap& map) {
  if (map.status != PoseCrbMap::Status::kOk) return;
  const double s = internal::page_scale(canvas);
  internal::mark_direction(canvas, map.best.direction, 6.0 * s, kBestColour,
                           Canvas::Shape::kDiamond);
  internal::mark_direction(canvas, map.worst.direction, 6.5 * s, kWorstViewpointColour);
  const SphereMapPoint p = sphere_map_from_direction(map.worst.direction);
  internal::select_disc(canvas, p.disc);
  // Beside the marker, toward the disc's centre: the rim's axis names stay clear.
  const bool right_half = p.xy.x() > 0.0;
  canvas.label(p.xy.x(), p.xy.y(),
               map.worst.unbounded ? std::string("unbounded") : degrees(map.worst.rot_rms_deg),
               (right_half ? -12 : 12) * s, (p.xy.y() > 0.0 ? 14 : -14) * s, right_half ? 1.0 : 0.0,
               internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.85);
}

void draw_map(Canvas& canvas, const CrbMapData& data, const internal::ValueCells& cells,
              const FigureOptions& options) {
  const camera::PoseCrbReport& report = *data.report;
  const camera::PoseCrbOptions& camera = report.camera;
  internal::draw_title(
      canvas,
      internal::figure_title(options,
                             "Pose Cramér–Rao bound: " + internal::layout_label(data.layout_name)),
      "rot_rms of an efficient estimator from direction a (body → camera); pinhole, D " +
          internal::fixed(camera.distance, 3) + ", f " + internal::fixed(camera.focal_length, 0) +
          " px, noise " + internal::fixed(camera.noise_px, 2) + " px; equal-area");
  const LogScale scale = log_scale(cells, report.map);
  for (int d = 0; d < 2; ++d) internal::paint_disc(canvas, d, bound_raster(cells, d, scale));
  internal::draw_count_boundaries(canvas, cells.samples, 0.7, internal::kPenInk);
  for (int d = 0; d < 2; ++d) internal::draw_disc_frame(canvas, d);
  internal::label_count_regions(canvas, cells.samples, kLabelledRegionFraction);
  draw_extremes(canvas, report.map);
  internal::draw_colour_bar(canvas, 0.905, 0.925, 0.30, 0.84, scale.lo, scale.hi,
                            "rot_rms  [deg, log scale]", true);
  draw_legends(canvas, report, cells);
}

void check(const CrbMapData& data) {
  if (data.model == nullptr) throw InvalidArgument("model", "is null");
  if (data.report == nullptr) throw InvalidArgument("report", "is null");
  const std::pair<const char*, int> grids[] = {{"samples_per_axis", data.samples_per_axis},
                                               {"csv_samples_per_axis", data.csv_samples_per_axis}};
  for (const auto& [field, n] : grids) {
    if (n < kMinMapSamples || n > kMaxMapSamples) {
      throw InvalidArgument(field, "must be in [" + std::to_string(kMinMapSamples) + ", " +
                                       std::to_string(kMaxMapSamples) + "], got " +
                                       std::to_string(n));
    }
  }
}

}  // namespace

FigureFiles write_crb_map(const CrbMapData& data, const std::filesystem::path& directory,
                          const FigureOptions& options) {
  check(data);
  const internal::ValueCells cells =
      sample_cells(*data.model, data.samples_per_axis, options.threads);
  const FigureFiles files = figure_files("crb_map", directory, options.format);
  Canvas canvas(files.image, options);
  draw_map(canvas, data, cells, options);
  canvas.finish();
  write_csv(data, files.csv);
  return files;
}

}  // namespace vantage::plot
