#pragma once

/// The figures of the pose Cramér–Rao bound of a pinhole camera over the viewpoint sphere
/// (docs/math.md §22; `vantage crb`), drawn from the one library call camera::pose_crb_report():
///
/// - `crb_map`: every viewing direction a of the two equal-area discs of sphere_map.h shaded by
///   the bound rot_rms_deg at a (PoseCrbModel::at), on a logarithmic colour scale (the bound
///   explodes in slivers of nearly collinear visible markers), untrackable directions grey, the
///   visible-marker count boundaries, the worst and the best direction of the report marked, and
///   p50/p95/p99, the sliver flag and the affine bound stated.
/// - `crb_sweep`: rot_rms_deg and trans_rms against the camera distance at the worst and at the
///   median direction of each distance (PoseCrbReport::sweep_distance), log y axes.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/plot/figure.h"

namespace vantage::plot {

/// What the CRB map draws.
struct CrbMapData {
  std::string layout_name;
  const camera::PoseCrbModel* model = nullptr;    ///< the camera and markers (required)
  const camera::PoseCrbReport* report = nullptr;  ///< pose_crb_report() of the same (required)
  /// N of the picture's cells per disc axis, in [kMinMapSamples, kMaxMapSamples].
  int samples_per_axis = 300;
  /// N of the CSV's cells, in [kMinMapSamples, kMaxMapSamples]; the CSV uses
  /// min(csv_samples_per_axis, samples_per_axis).
  int csv_samples_per_axis = 100;
};

/// Writes crb_map.<ext> and crb_map.csv into `directory`. CSV columns kind,disc,x,y,z,visible,
/// trackable,rot_rms_deg,trans_rms: first the row of kind "worst" and of kind "best" (the
/// report's refined directions; only when the map's status is kOk), then one row of kind "cell"
/// per cell inside either disc of the CSV grid (disc 0 first, row by row from the top, as
/// visibility_maps.h) with model->at(a) of its centre a; rot_rms_deg and trans_rms are empty
/// where a is not trackable, and `visible` is the number of visible markers. Throws
/// InvalidArgument naming the field ("model", "report", "samples_per_axis",
/// "csv_samples_per_axis") on bad data, RenderError when drawing or writing fails.
FigureFiles write_crb_map(const CrbMapData& data, const std::filesystem::path& directory,
                          const FigureOptions& options = {});

/// Writes crb_sweep.<ext> and crb_sweep.csv into `directory`. CSV columns distance,status,
/// trackable_fraction,worst_x,worst_y,worst_z,worst_rot_rms_deg,worst_trans_rms,median_x,
/// median_y,median_z,median_rot_rms_deg,median_trans_rms: one row per report.sweep_distance row,
/// the direction and bound columns empty where the status is not "ok". Throws InvalidArgument
/// "sweep_distance" when the report has fewer than 2 sweep rows, RenderError as above.
FigureFiles write_crb_sweep(const std::string& layout_name, const camera::PoseCrbReport& report,
                            const std::filesystem::path& directory,
                            const FigureOptions& options = {});

/// The distance sweep of the figures when none is asked: N = kDefaultSweepCount distances from
/// max(D / 2, 1.1 r) to 2 D, D the camera distance and r the layout's radius about its centroid
/// (D > r, so the range is never empty).
camera::PoseCrbSweep default_crb_sweep(double distance, double radius);
inline constexpr int kDefaultSweepCount = 8;

/// Options of write_crb_figures().
struct CrbFiguresOptions {
  FigureOptions figure;
  int samples_per_axis = 300;      ///< the map's picture, as CrbMapData
  int csv_samples_per_axis = 100;  ///< the map's CSV, as CrbMapData
  /// The distance sweep; default_crb_sweep() of the camera when empty.
  std::optional<camera::PoseCrbSweep> sweep;
  camera::CrbProgress progress;  ///< told each distance of the sweep ("distance k/N"); may be empty
};

/// What the figures draw (the model, the report) and the files written.
struct CrbFigures {
  std::string layout_name;
  std::shared_ptr<const camera::PoseCrbModel> model;
  camera::PoseCrbReport report;
  std::vector<FigureFiles> files;  ///< crb_map, then crb_sweep (after write_crb_figures())
};

/// The front door of `vantage plot --crb`, first half: the model and
/// camera::pose_crb_report(layout, camera, no direction, the sweep, options.progress); nothing is
/// written. Throws
/// what those throw (the camera's and the sweep's InvalidArgument name their field: "distance",
/// ..., "sweep_distance").
CrbFigures crb_figures(const Layout& layout, const camera::PoseCrbOptions& camera,
                       const CrbFiguresOptions& options);

/// Second half: write_crb_map() and write_crb_sweep() of `figures` into `directory`, appending
/// to figures.files.
void write_crb_figures(CrbFigures& figures, const CrbFiguresOptions& options,
                       const std::filesystem::path& directory);

}  // namespace vantage::plot
