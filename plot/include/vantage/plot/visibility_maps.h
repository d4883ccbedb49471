#pragma once

/// The whole-sphere figures of a layout on its body (docs/math.md §20), drawn on the two
/// equal-area discs of sphere_map.h from the visibility at each direction
/// (visibility::VisibilityModel::at) and the certified answer of the report:
///
/// - `viewpoint_map` (for a layout with normals): each trackable direction a shaded by its
///   worst-case error asin t(a) with the markers visible from a, untrackable directions grey,
///   the boundaries where the visible-marker count changes (with the counts), and the certified
///   worst viewpoint(s).
/// - `visibility`: the visible-marker count of each direction, the trackable boundary drawn and
///   the untrackable side washed out.

#include <filesystem>
#include <string>

#include "vantage/plot/colormap.h"
#include "vantage/plot/figure.h"
#include "vantage/plot/sphere_map.h"
#include "vantage/visibility/visibility_model.h"
#include "vantage/visibility/visibility_report.h"

namespace vantage::plot {

/// Colours of the whole-sphere maps.
inline constexpr Rgb kUntrackableColour{150, 150, 150};       ///< mid grey: not trackable
inline constexpr Rgb kOutsideWorkspaceColour{222, 222, 222};  ///< pale grey: not in the workspace

/// Where disc d (0 left, 1 right) of the whole-sphere figures lies on a page of width x height
/// pixels: its centre (pixels from the top left, y down) and radius in pixels.
struct DiscPlacement {
  Eigen::Vector2d centre_px;
  double radius_px = 0.0;
};
DiscPlacement sphere_map_disc_placement(int disc, int width, int height);

/// What the whole-sphere figures draw.
struct VisibilityMapData {
  std::string layout_name;
  const visibility::VisibilityModel* model = nullptr;    ///< the layout's visibility (required)
  const visibility::VisibilityReport* report = nullptr;  ///< its certified answer (required)
  /// The worst-case error of the layout seen whole (every marker from everywhere), degrees,
  /// for comparison in the legend; negative: not shown.
  double seen_whole_max_error_deg = -1.0;
  /// N of the picture's cells per disc axis, in [kMinMapSamples, kMaxMapSamples].
  int samples_per_axis = 400;
  /// N of the CSV's samples, in [kMinMapSamples, kMaxMapSamples]; the CSV uses
  /// min(csv_samples_per_axis, samples_per_axis).
  int csv_samples_per_axis = 100;
  /// The picture's samples when already taken (sample_sphere(*model, samples_per_axis)), or
  /// null: sampled here.
  const SphereSamples* samples = nullptr;
};

/// Writes viewpoint_map.<ext> and viewpoint_map.csv (columns disc,x,y,z,visible,trackable,pbar,
/// max_error_deg: one row per cell inside either disc of the CSV grid, disc 0 first, row by row
/// from the top; pbar = sqrt(1 - t^2) and max_error_deg = asin t in degrees, both empty where
/// the direction is not trackable) into `directory`. Throws InvalidArgument on bad data or
/// options, RenderError when drawing or writing fails.
FigureFiles write_visibility_viewpoint_map(const VisibilityMapData& data,
                                           const std::filesystem::path& directory,
                                           const FigureOptions& options = {});

/// Writes visibility.<ext> and visibility.csv (columns disc,x,y,z,visible,trackable,
/// in_workspace,markers: the CSV grid's cells as above, markers the visible markers' indices
/// separated by spaces) into `directory`. Throws as write_visibility_viewpoint_map().
FigureFiles write_visibility_figure(const VisibilityMapData& data,
                                    const std::filesystem::path& directory,
                                    const FigureOptions& options = {});

}  // namespace vantage::plot
