#pragma once

/// Figure `vectors`: the data vectors (direction mode) or the markers and their free vectors
/// (point mode) in 3-D, with the worst viewpoint(s) as axes and the plane a^perp of the first as
/// a translucent disc, in the style of the paper's Figs. 2-3. A vector lying in a^perp keeps its
/// whole length in the image when the camera looks along a.
///
/// Camera: orthographic, fixed, looking at the object frame's origin from azimuth
/// kVectorsAzimuthDeg (from +x towards +y) and elevation kVectorsElevationDeg (above the x-y
/// plane), +z up on the page.
///
/// A layout on its body (point mode with normals, docs/math.md §20) adds each marker's outward
/// normal as a short arrow, the body mesh (translucent faces and the edges where it folds), and
/// the worst viewpoint on the body as an arrow towards the camera, with the markers it does not
/// see drawn hollow.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/analysis/mesh.h"
#include "vantage/plot/figure.h"

namespace vantage::plot {

inline constexpr double kVectorsAzimuthDeg = 10.0;
inline constexpr double kVectorsElevationDeg = 15.0;

/// What the vectors figure draws.
struct VectorsFigureData {
  std::string layout_name;
  LayoutMode mode = LayoutMode::kVectors;
  Eigen::Matrix3Xd entries;  ///< data vectors (direction mode) or marker positions (point mode)
  /// One name per entry (Layout::entry_name), shown beside it and written in the CSV.
  std::vector<std::string> names;
  std::vector<Eigen::Vector3d> worst_viewpoints;  ///< every global worst viewpoint (>= 1)
  double pbar_min = 1.0;
  Eigen::Vector3d paper_lmi_viewpoint = Eigen::Vector3d::UnitZ();
  double paper_lmi_pbar = 1.0;
  /// Point mode on a body: the markers' outward unit normals (3 x n), or empty.
  Eigen::Matrix3Xd normals;
  /// The body mesh in the markers' frame, or null.
  const Mesh* body = nullptr;
  /// The worst viewpoint on the body (signed, unit) and the markers it sees, when drawn.
  std::optional<Eigen::Vector3d> body_worst_viewpoint;
  std::vector<int> body_visible_markers;
  double body_max_error_deg = 0.0;  ///< asin t of the worst viewpoint on the body, degrees
};

/// Page coordinates of object-frame point p under the fixed camera: (p.right, p.up), where
/// right = (-sin az, cos az, 0) and up = (-sin el cos az, -sin el sin az, cos el).
Eigen::Vector2d vectors_camera_projection(const Eigen::Vector3d& p);

/// Writes vectors.<ext> and vectors.csv (columns series,index,x,y,z,name in the object frame:
/// series "vector" or "point" for the entries, "worst_viewpoint" and "paper_lmi" for the unit
/// axes, then on a body "normal" (one per marker) and "body_worst_viewpoint"; name is the
/// entry's (p<k> or v<k> when unnamed), empty for the axes)
/// into `directory`. Throws InvalidArgument on bad data or options, RenderError when drawing or
/// writing fails.
FigureFiles write_vectors_figure(const VectorsFigureData& data,
                                 const std::filesystem::path& directory,
                                 const FigureOptions& options = {});

}  // namespace vantage::plot
