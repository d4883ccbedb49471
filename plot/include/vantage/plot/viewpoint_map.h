#pragma once

/// Figure `viewpoint_map`: the whole sphere of viewing directions, shaded by the worst-case
/// angular error arccos p_bar(a) at each viewpoint a, with p_bar(a) = max_i sqrt(1 - (a.n_i)^2)
/// (docs/math.md §11). a and -a are the same viewpoint, so the upper hemisphere (a_z >= 0)
/// shows everything; it is drawn in the Lambert azimuthal equal-area projection, so equal areas
/// of the disc are equal solid angles of viewing directions.
///
/// The error at a is also the angle from a to the nearest plane n_i^perp: it is 0 on the great
/// circles n_i^perp (the sign-cell arrangement of Theorem 6) and largest, arccos p_bar_min, at
/// the global worst viewpoints.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include "vantage/plot/figure.h"

namespace vantage::plot {

/// Lambert azimuthal equal-area projection of the upper hemisphere onto the unit disc:
/// (X, Y) = (a_x, a_y) / sqrt(1 + a_z), so +z maps to the centre and the equator to the unit
/// circle; the disc radius is sqrt(1 - a_z). a is unit; a with a_z < 0 is replaced by -a.
Eigen::Vector2d lambert_from_viewpoint(const Eigen::Vector3d& a);

/// The inverse for |(X, Y)| <= 1: a = (X s, Y s, 1 - r^2) with r^2 = X^2 + Y^2, s = sqrt(2 - r^2).
/// Points outside the disc are first moved radially onto the unit circle.
Eigen::Vector3d viewpoint_from_lambert(const Eigen::Vector2d& xy);

/// p_bar(a) sampled at the centres of an N x N grid of cells over [-1, 1]^2 in the Lambert disc.
struct ViewpointSamples {
  int samples_per_axis = 0;  ///< N
  /// Unit viewpoints of the cells whose centre lies in the disc, row by row from the top
  /// (Y = +1) and left to right.
  Eigen::Matrix3Xd viewpoints;
  Eigen::VectorXd pbar;  ///< p_bar at each of them
  /// arccos p_bar in degrees at every cell (row 0 at Y = +1), cells outside the disc evaluated
  /// at their radial projection onto the unit circle (continuous across the rim, for contours).
  Eigen::MatrixXd error_deg;
  /// 1 for cells whose centre is inside the disc, else 0.
  Eigen::Matrix<unsigned char, Eigen::Dynamic, Eigen::Dynamic> inside;
};

/// Smallest and largest accepted samples_per_axis.
inline constexpr int kMinMapSamples = 16;
inline constexpr int kMaxMapSamples = 4000;

/// Samples p_bar(a) (vantage::pbar_at_viewpoints) on the grid, rows split over `threads`
/// threads (0 = all cores); the result does not depend on the thread count. vectors: 3 x m,
/// m >= 1, non-zero finite columns. Throws InvalidArgument on bad vectors or samples_per_axis
/// outside [kMinMapSamples, kMaxMapSamples].
ViewpointSamples sample_viewpoints(const Eigen::Matrix3Xd& vectors, int samples_per_axis,
                                   int threads = 0);

/// What the viewpoint map draws.
struct ViewpointMapData {
  std::string layout_name;
  Eigen::Matrix3Xd vectors;                       ///< data vectors, 3 x m
  std::vector<Eigen::Vector3d> worst_viewpoints;  ///< every global worst viewpoint (>= 1)
  double pbar_min = 1.0;                          ///< at the worst viewpoints
  Eigen::Vector3d paper_lmi_viewpoint = Eigen::Vector3d::UnitZ();  ///< the paper's single LMI
  double paper_lmi_pbar = 1.0;
  double threshold_deg = 5.0;  ///< contour of arccos p_bar = threshold, in (0, 90) degrees
  int samples_per_axis = 400;  ///< N of sample_viewpoints, >= 400 keeps the minimum visible
  /// N of the CSV's samples, in [kMinMapSamples, kMaxMapSamples]; the CSV uses
  /// min(csv_samples_per_axis, samples_per_axis). 100 gives 7 860 rows (0.72 MB for the
  /// satellite) where the picture's 400 has 125 676 (11.7 MB): the same map on cells of side
  /// 2/N, for the reader's own analysis; the picture's raster is not repeated.
  int csv_samples_per_axis = 100;
};

/// Writes viewpoint_map.<ext> and viewpoint_map.csv (columns x,y,z,pbar,max_error_deg: one row
/// per sample inside the disc of the csv_samples_per_axis grid, max_error_deg = arccos(pbar) in
/// degrees) into `directory`.
/// Throws InvalidArgument on bad data or options, RenderError when drawing or writing fails.
FigureFiles write_viewpoint_map(const ViewpointMapData& data,
                                const std::filesystem::path& directory,
                                const FigureOptions& options = {});

}  // namespace vantage::plot
