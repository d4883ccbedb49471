#pragma once

/// How many AprilTags, and how big (`vantage crb --sweep-tags`, docs/math.md §22): the faces of
/// a tag layout, the same faces tiled with k x k tags of a given fill, and the pose CRB map of
/// each tiling at the camera of PoseCrbOptions.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "vantage/analysis/layout.h"
#include "vantage/camera/pose_crb.h"

namespace vantage::camera {

/// One planar face of a tag layout: tags sharing a plane and a normal.
struct TagFace {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< of the bounding square
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();  ///< the first tag's edge c0 -> c1, unit
  Eigen::Vector3d y_axis = Eigen::Vector3d::UnitY();  ///< the first tag's edge c0 -> c3, unit
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< x_axis x y_axis
  double extent = 0.0;   ///< side of the smallest axis-aligned square holding its corners
  int first_marker = 0;  ///< the first corner of its first tag (its cone is the face's)
  int tags = 0;          ///< tags of the layout on this face
};

/// The faces of a layout whose markers are AprilTag corners (names "tag<id>_c0".."tag<id>_c3",
/// four consecutive markers per tag). Throws InvalidArgument "names" when they are not, and
/// "points" when a tag's corners are not a square.
std::vector<TagFace> tag_faces(const Layout& layout);

/// The layout with the tags of every face replaced by k x k tags of side fill * extent / k
/// (names "tag<j>_c<c>", j counting over the faces), each marker with its face's normal and the
/// cone of the face's first marker; min_visible, workspace and body are the layout's.
Layout tag_grid_layout(const Layout& layout, const std::vector<TagFace>& faces, int per_side,
                       double fill);

/// The tilings of the sweep.
struct TagSweepOptions {
  /// The largest k: the cube's 3 faces at 12 x 12 tags (1728 corners) cost 0.6 s of CPU and
  /// 58 MB per map (README "Limits"; the map's memory grows with the corners).
  static constexpr int kMaxPerSide = 12;

  std::vector<int> per_side = {1, 2, 3, 4};  ///< k, each in [1, kMaxPerSide]
  /// Each in (0, 1]; 1 only when every per_side is 1 (neighbours would share corners).
  std::vector<double> fill = {0.5, 0.8};
  /// Gets "tiling k/N" before each tiling's map, or empty.
  CrbProgress progress;

  /// True when every field is in range; otherwise *why names the field and the constraint.
  bool is_valid(std::string* why = nullptr) const;
};

/// One tiling.
struct TagSweepRow {
  int per_side = 0;
  int tags = 0;  ///< per_side^2 times the faces
  double fill = 0.0;
  double tag_size = 0.0;  ///< on the largest face, layout units
  /// tag_size * focal / distance: the tag's width in pixels seen head-on at the distance.
  double tag_pixels = 0.0;
  PoseCrbMap::Status status = PoseCrbMap::Status::kUntrackable;
  PoseCrbAt worst;
  PoseCrbAt median;  ///< the trackable sample whose rot_rms_deg is p50
  PoseCrbPercentiles percentiles;
  double trackable_fraction = 0.0;
  double unbounded_fraction = 0.0;  ///< as PoseCrbMap::unbounded_fraction

  /// Below this many pixels across, a tag is unlikely to be decoded (docs/math.md §22).
  static constexpr double kMinDetectablePixels = 20.0;
};

/// The sweep: one row per (per_side, fill), per_side outer. Throws InvalidArgument as
/// tag_faces() does, "sweep_tags.<field>" for bad options, and as PoseCrbModel for the camera
/// (a tiling's radius above the distance: "distance").
std::vector<TagSweepRow> pose_crb_tag_sweep(const Layout& layout, const PoseCrbOptions& camera,
                                            const TagSweepOptions& options = {});

}  // namespace vantage::camera
