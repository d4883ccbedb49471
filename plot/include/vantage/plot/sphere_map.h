#pragma once

/// The whole sphere of signed viewing directions (docs/math.md §20: with visibility a and -a see
/// different markers) on two Lambert azimuthal equal-area discs side by side, and what the
/// markers' visibility (visibility::VisibilityModel::at) gives at the centre of every cell of them.
///
/// Disc 0 holds a_z >= 0 seen from outside above (+z): (X, Y) = (a_x, a_y) / sqrt(1 + a_z), +x
/// right, +y up, as the viewpoint map of a layout seen whole. Disc 1 holds a_z < 0 seen from
/// outside below (-z), the sphere turned half a turn about +y: (X, Y) = (-a_x, a_y) /
/// sqrt(1 - a_z), so -x is right and +y up, and drawn to the right of disc 0 the two discs touch
/// at +x. Both are equal-area: equal areas of the two discs are equal solid angles.

#include <Eigen/Core>
#include <array>

#include "vantage/visibility/visibility_model.h"

namespace vantage::plot {

/// A direction's place on the two discs.
struct SphereMapPoint {
  int disc = 0;        ///< 0: a_z >= 0, 1: a_z < 0
  Eigen::Vector2d xy;  ///< in the unit disc
};

/// The disc and point of unit direction a.
SphereMapPoint sphere_map_from_direction(const Eigen::Vector3d& a);

/// The unit direction of point xy of disc `disc` (0 or 1); points outside the unit disc are
/// first moved radially onto its rim (the equator).
Eigen::Vector3d direction_from_sphere_map(int disc, const Eigen::Vector2d& xy);

/// Visibility sampled at the centres of an N x N grid of cells over [-1, 1]^2 on each disc.
/// Matrices are indexed (row, column), row 0 at Y = +1; cells whose centre lies outside the
/// unit disc are evaluated at their radial projection onto the rim (continuous across it, for
/// contours) and flagged in `inside`.
struct SphereSamples {
  using Flags = Eigen::Matrix<unsigned char, Eigen::Dynamic, Eigen::Dynamic>;
  int samples_per_axis = 0;                ///< N
  std::array<Eigen::MatrixXi, 2> visible;  ///< markers visible from the cell's direction
  std::array<Eigen::MatrixXd, 2> t;        ///< min |a.u_ij| over the visible pairs
  std::array<Flags, 2> trackable;          ///< DirectionVisibility::trackable
  std::array<Flags, 2> in_workspace;       ///< inside the layout's workspace (all without one)
  std::array<Flags, 2> inside;             ///< the cell's centre lies in the unit disc

  /// The cell's centre coordinate (X for a column, Y for a row) of index k of N over [-1, 1].
  static double cell_centre(int k, int n) { return -1.0 + (2.0 * k + 1.0) / n; }
  /// The unit direction of cell (row, column) of disc d.
  Eigen::Vector3d direction(int d, int row, int column) const;
  /// Cells inside the discs.
  long inside_count() const;
  /// The fraction of the inside cells that are trackable, among those in the workspace.
  double trackable_fraction() const;
};

/// Samples model.at() on both discs, rows split over `threads` threads (0 = all cores); the
/// result does not depend on the thread count. Throws InvalidArgument for samples_per_axis
/// outside [kMinMapSamples, kMaxMapSamples] (viewpoint_map.h).
SphereSamples sample_sphere(const visibility::VisibilityModel& model, int samples_per_axis,
                            int threads = 0);

}  // namespace vantage::plot
