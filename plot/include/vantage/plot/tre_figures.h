#pragma once

/// The figures of the target registration error of a tool on a 3-D tracker (docs/math.md §23,
/// "Sweeps and figures"; `vantage plot LAYOUT --tre`), drawn from the one library call
/// tracker::tre_sweeps() and, for the map, tracker::TreModel::at():
///
/// - `tre_tip_axis`: RMS TRE against the distance s from the markers' centroid along the tip axis
///   (through the first target), at the first target's worst and best line of sight and at
///   TreOptions::direction, with Fitzpatrick's isotropic formula for an isotropic FLE.
/// - `tre_polar`: NDI-style polar plots, RMS TRE of a target on a circle of radius R about each
///   tool axis (three panels on one radial scale) at the worst line of sight.
/// - `tre_map`: every line of sight a of the two equal-area discs of sphere_map.h shaded by the
///   RMS TRE of the first target (linear scale, layout units), untracked directions grey, the
///   visible-marker count boundaries, the worst (red) and best (white) marked.
///
/// Every value is in the layout's units.

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/plot/figure.h"
#include "vantage/tracker/tre_sweeps.h"

namespace vantage::plot {

/// Writes tre_tip_axis.<ext> and tre_tip_axis.csv into `directory`. CSV columns series,
/// direction_x,direction_y,direction_z,visible,distance,target_x,target_y,target_z,rms: one row
/// per distance of each tracked curve (series "worst", "best", "direction"), then of series
/// "isotropic" (Eq. 23.3, every marker; direction empty, visible the marker count) when the FLE
/// is isotropic. Throws RenderError when drawing or writing fails.
FigureFiles write_tre_tip_axis(const std::string& layout_name, const tracker::TreSweeps& sweeps,
                               const std::filesystem::path& directory,
                               const FigureOptions& options = {});

/// Writes tre_polar.<ext> and tre_polar.csv into `directory`. CSV columns series,axis,
/// direction_x,direction_y,direction_z,visible,angle_deg,target_x,target_y,target_z,rms: series
/// "worst" for axis x, y, z (when tracked), then "isotropic" likewise (isotropic FLE only).
FigureFiles write_tre_polar(const std::string& layout_name, const tracker::TreSweeps& sweeps,
                            const std::filesystem::path& directory,
                            const FigureOptions& options = {});

/// What the TRE map draws.
struct TreMapData {
  std::string layout_name;
  const tracker::TreModel* model = nullptr;    ///< the markers, visibility and FLE (required)
  const tracker::TreSweeps* sweeps = nullptr;  ///< tre_sweeps() of the same model (required)
  /// N of the picture's cells per disc axis, in [kMinMapSamples, kMaxMapSamples].
  int samples_per_axis = 300;
  /// N of the CSV's cells, in [kMinMapSamples, kMaxMapSamples]; the CSV uses
  /// min(csv_samples_per_axis, samples_per_axis).
  int csv_samples_per_axis = 100;
};

/// Writes tre_map.<ext> and tre_map.csv into `directory`. CSV columns kind,disc,x,y,z,visible,
/// tracked,rms: the rows of kind "worst" and "best" (the report's, when tracked), then one row of
/// kind "cell" per cell inside either disc of the CSV grid (disc 0 first, row by row from the
/// top, as crb_figures.h) with model->at(first target, a) of its centre a; rms is empty where a
/// is not tracked. Throws InvalidArgument naming the field ("model", "sweeps",
/// "samples_per_axis", "csv_samples_per_axis") on bad data, RenderError as above.
FigureFiles write_tre_map(const TreMapData& data, const std::filesystem::path& directory,
                          const FigureOptions& options = {});

/// Options of tre_figures() and write_tre_figures().
struct TreFiguresOptions {
  FigureOptions figure;
  tracker::TreSweepOptions sweep;
  int samples_per_axis = 300;      ///< the map's picture, as TreMapData
  int csv_samples_per_axis = 100;  ///< the map's CSV, as TreMapData
};

/// What the figures draw and the files written.
struct TreFigures {
  std::string layout_name;
  std::shared_ptr<const tracker::TreModel> model;
  tracker::TreSweeps sweeps;
  std::vector<FigureFiles> files;  ///< tre_tip_axis, tre_polar, tre_map (after writing)
};

/// The front door of `vantage plot --tre`, first half: the model of (layout, tre.fle) and
/// tracker::tre_sweeps(); nothing is written. Throws what those throw (InvalidArgument naming
/// "target", "fle.sigma_perp", "radius", ... or the layout's field).
TreFigures tre_figures(const Layout& layout, const std::vector<Eigen::Vector3d>& targets,
                       const tracker::TreOptions& tre, const TreFiguresOptions& options);

/// Second half: the three figures of `figures` into `directory`, appended to figures.files.
void write_tre_figures(TreFigures& figures, const TreFiguresOptions& options,
                       const std::filesystem::path& directory);

}  // namespace vantage::plot
