// The TRE map (tre_figures.h): the two equal-area discs of lines of sight shaded by the RMS TRE
// of the first target (linear scale, layout units), untracked grey, the worst and best marked.

#include <algorithm>
#include <cmath>
#include <limits>

#include "canvas.h"
#include "output_file.h"
#include "sphere_map_drawing.h"
#include "sphere_value_cells.h"
#include "style.h"
#include "tre_figure_text.h"
#include "vantage/analysis/common.h"
#include "vantage/plot/sphere_map.h"
#include "vantage/plot/tre_figures.h"
#include "vantage/plot/viewpoint_map.h"
#include "vantage/plot/visibility_maps.h"

namespace vantage::plot {
namespace {

using internal::Canvas;
using tracker::TreAtDirection;
using tracker::TreExtreme;

// The best direction's marker: white, apart from the red worst and from every viridis colour.
constexpr Rgb kTreMapBestColour{255, 255, 255};
// Count regions smaller than this fraction of a disc carry no number (too small to read).
constexpr double kTreMapLabelledFraction = 0.006;
// A map whose RMS varies by less than this fraction of its largest value still spans it (a flat
// map would otherwise divide by zero).
constexpr double kTreMapMinSpan = 1e-3;

// The cells of the picture, and the RMS TRE of the first target as their value (NaN: not
// tracked).
internal::ValueCells sample_tre_cells(const tracker::TreModel& model, const Eigen::Vector3d& target,
                                      int n, int threads) {
  return internal::sample_value_cells(n, threads, [&](const Eigen::Vector3d& a) {
    const TreAtDirection at = model.at(target, a);
    return internal::CellValue{static_cast<int>(at.visible_markers.size()), at.tracked,
                               model.in_workspace(a), at.rms};
  });
}

struct TreMapScale {
  double lo = 0.0;
  double hi = 1.0;
};

TreMapScale tre_map_scale(const internal::ValueCells& cells, const tracker::TreExtremes& extremes) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  internal::widen_to_cells(cells, &lo, &hi);
  for (const TreExtreme* e : {&extremes.worst, &extremes.best}) {
    if (e->status == TreExtreme::Status::kUntracked) continue;
    lo = std::min(lo, e->rms);
    hi = std::max(hi, e->rms);
  }
  if (!(hi > 0.0) || !std::isfinite(lo)) return {};
  return {lo, std::max(hi, lo + kTreMapMinSpan * hi)};
}

internal::Raster tre_raster(const internal::ValueCells& cells, int d, const TreMapScale& scale) {
  return internal::trackable_raster(cells.samples, d, [&](int r, int c) {
    return value_colour(cells.value[d](r, c), scale.lo, scale.hi);
  });
}

void write_tre_map_row(internal::CsvWriter& csv, const char* kind, int disc,
                       const Eigen::Vector3d& a, const TreAtDirection& at) {
  csv << kind << disc << a.x() << a.y() << a.z() << static_cast<long>(at.visible_markers.size())
      << (at.tracked ? 1 : 0);
  if (at.tracked) {
    csv << at.rms;
  } else {
    csv << "";
  }
  csv.end_row();
}

void write_tre_map_csv(const TreMapData& data, const std::filesystem::path& path) {
  internal::CsvWriter csv(path, "kind,disc,x,y,z,visible,tracked,rms");
  const tracker::TreTargetReport& first = data.sweeps->report.targets.front();
  const std::pair<const char*, const TreExtreme*> extremes[] = {{"worst", &first.extremes.worst},
                                                                {"best", &first.extremes.best}};
  for (const auto& [kind, e] : extremes) {
    if (e->status == TreExtreme::Status::kUntracked) continue;
    TreAtDirection at;
    at.tracked = true;
    at.rms = e->rms;
    at.visible_markers = e->visible_markers;
    write_tre_map_row(csv, kind, sphere_map_from_direction(e->direction).disc, e->direction, at);
  }
  const int n = std::min(data.csv_samples_per_axis, data.samples_per_axis);
  for (int d = 0; d < 2; ++d) {
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const Eigen::Vector2d xy(SphereSamples::cell_centre(c, n),
                                 SphereSamples::cell_centre(n - 1 - r, n));
        if (xy.squaredNorm() > 1.0) continue;
        const Eigen::Vector3d a = direction_from_sphere_map(d, xy);
        write_tre_map_row(csv, "cell", d, a, data.model->at(first.target, a));
      }
    }
  }
  csv.commit();
}

std::string tre_extreme_text(const char* what, const TreExtreme& e) {
  return std::string(what) + " line of sight " + internal::tre_vector_text(e.direction, 3) +
         ": RMS " + internal::tre_number_text(e.rms) + ", " +
         std::to_string(e.visible_markers.size()) + " markers, " +
         (e.closed_form ? "exact" : tracker::to_string(e.status));
}

void draw_tre_map_legends(Canvas& canvas, const tracker::TreSweeps& sweeps,
                          const internal::ValueCells& cells) {
  using Entry = Canvas::LegendEntry;
  const double s = internal::page_scale(canvas);
  const tracker::TreExtremes& x = sweeps.report.targets.front().extremes;
  std::vector<Entry> left;
  if (x.worst.status == TreExtreme::Status::kUntracked) {
    left.push_back(Entry::text_only("no line of sight tracks the tool"));
  } else {
    left.push_back(Entry::marker(tre_extreme_text("worst", x.worst), kWorstViewpointColour));
    left.push_back(Entry::marker(tre_extreme_text("best", x.best), kTreMapBestColour,
                                 Canvas::Shape::kDiamond));
  }
  left.push_back(Entry::marker("not tracked: fewer than min_visible markers seen, or collinear",
                               kUntrackableColour, Canvas::Shape::kSquare));
  left.push_back(
      Entry::line("visible-marker count changes (numbers: markers seen)", {25, 25, 25}, 1.0 * s));
  canvas.legend(0.02, 0.2, left, internal::kSmallSize * s, 0.0);
  std::vector<Entry> right;
  right.push_back(Entry::text_only(internal::tre_fle_text(sweeps.report.fle)));
  right.push_back(Entry::text_only(
      "tracked on this map: " + internal::fixed(100.0 * cells.samples.trackable_fraction(), 1) +
      " %"));
  canvas.legend(0.98, 0.2, right, internal::kSmallSize * s, 1.0);
}

void draw_tre_map_extremes(Canvas& canvas, const tracker::TreExtremes& x) {
  if (x.worst.status == TreExtreme::Status::kUntracked) return;
  const double s = internal::page_scale(canvas);
  internal::mark_direction(canvas, x.best.direction, 6.0 * s, kTreMapBestColour,
                           Canvas::Shape::kDiamond);
  internal::mark_direction(canvas, x.worst.direction, 6.5 * s, kWorstViewpointColour);
  const SphereMapPoint p = sphere_map_from_direction(x.worst.direction);
  internal::select_disc(canvas, p.disc);
  const bool right_half = p.xy.x() > 0.0;
  canvas.label(p.xy.x(), p.xy.y(), internal::tre_number_text(x.worst.rms),
               (right_half ? -12 : 12) * s, (p.xy.y() > 0.0 ? 14 : -14) * s, right_half ? 1.0 : 0.0,
               internal::kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.85);
}

void draw_tre_map(Canvas& canvas, const TreMapData& data, const internal::ValueCells& cells,
                  const FigureOptions& options) {
  const tracker::TreTargetReport& first = data.sweeps->report.targets.front();
  internal::draw_title(
      canvas,
      internal::figure_title(
          options, "TRE over the lines of sight: " + internal::layout_label(data.layout_name)),
      "RMS TRE at target " + internal::tre_vector_text(first.target, 2) +
          " from line of sight a (tool → tracker, tool frame); equal-area");
  const TreMapScale scale = tre_map_scale(cells, first.extremes);
  for (int d = 0; d < 2; ++d) internal::paint_disc(canvas, d, tre_raster(cells, d, scale));
  internal::draw_count_boundaries(canvas, cells.samples, 0.7, internal::kPenInk);
  for (int d = 0; d < 2; ++d) internal::draw_disc_frame(canvas, d);
  internal::label_count_regions(canvas, cells.samples, kTreMapLabelledFraction);
  draw_tre_map_extremes(canvas, first.extremes);
  internal::draw_colour_bar(canvas, 0.905, 0.925, 0.30, 0.84, scale.lo, scale.hi,
                            "RMS TRE  [layout units]");
  draw_tre_map_legends(canvas, *data.sweeps, cells);
}

void check_tre_map_grids(const TreMapData& data) {
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

void check_tre_map(const TreMapData& data) {
  if (data.model == nullptr) throw InvalidArgument("model", "is null");
  if (data.sweeps == nullptr) throw InvalidArgument("sweeps", "is null");
  if (data.sweeps->report.targets.empty()) throw InvalidArgument("sweeps", "has no target");
  check_tre_map_grids(data);
}

}  // namespace

FigureFiles write_tre_map(const TreMapData& data, const std::filesystem::path& directory,
                          const FigureOptions& options) {
  check_tre_map(data);
  const internal::ValueCells cells =
      sample_tre_cells(*data.model, data.sweeps->report.targets.front().target,
                       data.samples_per_axis, options.threads);
  const FigureFiles files = figure_files("tre_map", directory, options.format);
  Canvas canvas(files.image, options);
  draw_tre_map(canvas, data, cells, options);
  canvas.finish();
  write_tre_map_csv(data, files.csv);
  return files;
}

TreFigures tre_figures(const Layout& layout, const std::vector<Eigen::Vector3d>& targets,
                       const tracker::TreOptions& tre, const TreFiguresOptions& options) {
  TreFigures out;
  out.layout_name = layout.name;
  TreMapData grids;
  grids.samples_per_axis = options.samples_per_axis;
  grids.csv_samples_per_axis = options.csv_samples_per_axis;
  check_tre_map_grids(grids);
  out.model = std::make_shared<const tracker::TreModel>(layout, tre.fle);
  out.sweeps = tracker::tre_sweeps(*out.model, targets, tre, options.sweep);
  return out;
}

void write_tre_figures(TreFigures& figures, const TreFiguresOptions& options,
                       const std::filesystem::path& directory) {
  figures.files.push_back(
      write_tre_tip_axis(figures.layout_name, figures.sweeps, directory, options.figure));
  figures.files.push_back(
      write_tre_polar(figures.layout_name, figures.sweeps, directory, options.figure));
  TreMapData data;
  data.layout_name = figures.layout_name;
  data.model = figures.model.get();
  data.sweeps = &figures.sweeps;
  data.samples_per_axis = options.samples_per_axis;
  data.csv_samples_per_axis = options.csv_samples_per_axis;
  figures.files.push_back(write_tre_map(data, directory, options.figure));
}

}  // namespace vantage::plot
