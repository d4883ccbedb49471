#pragma once

/// Figure `placement` (a layout written by `vantage place`, docs/math.md §21): the body from the
/// front and from the back with every candidate site faint and the chosen sites with their
/// outward normals, and p-bar_min against the number of markers K: each greedy step (hollow
/// where the workspace is not yet covered), the answer, and the random baseline of the same K.
///
/// Views: orthographic, from azimuth kPlacementAzimuthDeg and that + 180 degrees, elevation
/// kPlacementElevationDeg, +z up; a site is drawn on the view its normal faces.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"
#include "vantage/plot/figure.h"

namespace vantage::plot {

inline constexpr double kPlacementAzimuthDeg = 35.0;
inline constexpr double kPlacementElevationDeg = 20.0;

/// What the placement figure draws.
struct PlacementFigureData {
  std::string layout_name;
  const Mesh* body = nullptr;  ///< the body, or null (sites from a file without a mesh)
  LayoutPlacement placement;   ///< sites, chosen, steps, random baseline
  Eigen::Matrix3Xd markers;    ///< the placed markers (kept ones included), 3 x K
  Eigen::Matrix3Xd normals;    ///< their outward unit normals
  double pbar_min = 0.0;       ///< the answer's certified p-bar_min under visibility
  double coverage = 0.0;       ///< its trackable fraction of the workspace
  /// The sensor of a camera or tracker placement (the layout's "sensor" block): with the
  /// objective's values recorded in `placement`, the chart shows the objective, not p-bar_min.
  std::optional<LayoutSensor> sensor;
};

/// Writes placement.<ext> and placement.csv (columns series,k,pbar_min,coverage, and objective
/// for a camera or tracker placement: series "step" for each greedy step, "answer",
/// "random_best" and "random_median" at K) into `directory`.
/// Throws InvalidArgument on bad data (markers and normals of different sizes, a chosen index
/// outside the sites, p-bar_min outside [0, 1]) or options, RenderError when drawing or writing
/// fails.
FigureFiles write_placement_figure(const PlacementFigureData& data,
                                   const std::filesystem::path& directory,
                                   const FigureOptions& options = {});

}  // namespace vantage::plot
