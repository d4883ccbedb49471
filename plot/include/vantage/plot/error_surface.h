#pragma once

/// Figure `error_surface`: the paper's Fig. 1. Eq. (26) gives the angular error of data vector i
/// when the scale is the least upper bound (Eq. 23):
///   theta(p_i, p_bar) = arccos[p_i^2 / p_bar + sqrt((1 - p_i^2)(1 - p_i^2 / p_bar^2))]
/// over 0 <= p_i <= p_bar <= 1, where p_i is the fraction of vector i's norm in the image and
/// p_bar = max_j p_j. Shaded map in degrees, with the layout's own (p_i, p_bar_min) at its worst
/// viewpoint overlaid.

#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "vantage/plot/figure.h"

namespace vantage::plot {

/// What the error surface draws.
struct ErrorSurfaceData {
  std::string layout_name;
  /// p_i of every data vector at the worst viewpoint (vantage::projected_fractions); the largest
  /// is p_bar_min.
  Eigen::VectorXd p_at_worst;
  int samples_per_axis = 200;  ///< grid of the map (cell centres), in [16, 2000]
  /// The layout is on a body but p_at_worst is of its worst viewpoint seen whole (every marker):
  /// the figure says so.
  bool seen_whole_of_a_body = false;
};

/// Writes error_surface.<ext> and error_surface.csv (columns series,index,p,pbar,theta_deg:
/// series "grid" for every grid cell centre with p <= pbar, index -1; series "layout" for the
/// layout's vectors, index i, at (p_i, p_bar_min)) into `directory`.
/// Throws InvalidArgument on bad data or options, RenderError when drawing or writing fails.
FigureFiles write_error_surface(const ErrorSurfaceData& data,
                                const std::filesystem::path& directory,
                                const FigureOptions& options = {});

}  // namespace vantage::plot
