#pragma once

/// Figure `vectors`: the data vectors (direction mode) or the markers and their free vectors
/// (point mode) in 3-D, with the worst viewpoint(s) as axes and the plane a^perp of the first as
/// a translucent disc, in the style of the paper's Figs. 2-3. A vector lying in a^perp keeps its
/// whole length in the image when the camera looks along a.
///
/// Camera: orthographic, fixed, looking at the object frame's origin from azimuth
/// kVectorsAzimuthDeg (from +x towards +y) and elevation kVectorsElevationDeg (above the x-y
/// plane), +z up on the page.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/plot/figure.h"

namespace vantage::plot {

inline constexpr double kVectorsAzimuthDeg = 10.0;
inline constexpr double kVectorsElevationDeg = 15.0;

/// What the vectors figure draws.
struct VectorsFigureData {
  std::string layout_name;
  LayoutMode mode = LayoutMode::kVectors;
  Eigen::Matrix3Xd entries;  ///< data vectors (direction mode) or marker positions (point mode)
  std::vector<Eigen::Vector3d> worst_viewpoints;  ///< every global worst viewpoint (>= 1)
  double pbar_min = 1.0;
  Eigen::Vector3d paper_lmi_viewpoint = Eigen::Vector3d::UnitZ();
  double paper_lmi_pbar = 1.0;
};

/// Page coordinates of object-frame point p under the fixed camera: (p.right, p.up), where
/// right = (-sin az, cos az, 0) and up = (-sin el cos az, -sin el sin az, cos el).
Eigen::Vector2d vectors_camera_projection(const Eigen::Vector3d& p);

/// Writes vectors.<ext> and vectors.csv (columns series,index,x,y,z in the object frame: series
/// "vector" or "point" for the entries, "worst_viewpoint" and "paper_lmi" for the unit axes)
/// into `directory`. Throws InvalidArgument on bad data or options, RenderError when drawing or
/// writing fails.
FigureFiles write_vectors_figure(const VectorsFigureData& data,
                                 const std::filesystem::path& directory,
                                 const FigureOptions& options = {});

}  // namespace vantage::plot
