#pragma once

// Drawing the two discs of the whole-sphere maps (sphere_map.h): where they sit on the page,
// their rims and axis labels, rasters of per-cell values, contours of a cell field, and the
// regions of constant visible-marker count with their numbers. Private to vantage::plot.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "canvas.h"
#include "vantage/plot/sphere_map.h"

namespace vantage::plot::internal {

/// Sets PLplot's viewport and window to disc d (0 left: a_z >= 0, 1 right: a_z < 0); the unit
/// disc spans most of the viewport, below the title and above the legends.
void select_disc(Canvas& canvas, int d);

/// Paints raster (N x N, row 0 at Y = +1) over [-1, 1]^2 of disc d, clipped to the disc.
void paint_disc(Canvas& canvas, int d, const Raster& raster);

/// The rim of disc d, its axis names and its caption below.
void draw_disc_frame(Canvas& canvas, int d);

/// Contours of field (N x N cells of disc d, as SphereSamples) at `levels`, clipped to the disc,
/// in the current pen and width.
void draw_disc_contours(Canvas& canvas, int d, const Eigen::MatrixXd& field,
                        const std::vector<double>& levels);

/// The boundaries where the visible-marker count changes: contours at every half-integer.
void draw_count_boundaries(Canvas& canvas, const SphereSamples& samples, double width_px, int pen);

/// The boundary of the trackable directions, white over a dark underlay (readable on any value
/// colour).
void draw_trackable_boundary(Canvas& canvas, const SphereSamples& samples);

/// A connected region of one visible-marker count on one disc.
struct CountRegion {
  int disc = 0;
  int count = 0;
  long cells = 0;
  int row = 0, column = 0;  ///< the region's cell nearest its centroid
};

/// The regions of constant count of both discs (cells inside the discs; 4-neighbours).
std::vector<CountRegion> count_regions(const SphereSamples& samples);

/// The count of every region of at least `min_fraction` of a disc's cells, at its label cell.
void label_count_regions(Canvas& canvas, const SphereSamples& samples, double min_fraction);

/// A filled marker at unit direction a on its disc.
void mark_direction(Canvas& canvas, const Eigen::Vector3d& a, double radius_px, Rgb fill,
                    Canvas::Shape shape = Canvas::Shape::kCircle);

/// The opaque ARGB32 pixel of colour c (a raster cell).
inline std::uint32_t opaque_argb(Rgb c) {
  return 0xff000000u | (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
}

/// The raster of disc d of `samples`: a trackable cell (row r, column c) in `trackable_colour(r,
/// c)`, any other cell of the workspace untrackable grey, the rest the outside-workspace colour.
Raster trackable_raster(const SphereSamples& samples, int d,
                        const std::function<Rgb(int r, int c)>& trackable_colour);

}  // namespace vantage::plot::internal
