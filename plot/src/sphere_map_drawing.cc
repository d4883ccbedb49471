#include "sphere_map_drawing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "style.h"
#include "vantage/plot/visibility_maps.h"

namespace vantage::plot::internal {
namespace {

// The discs' boxes in page fractions (x0, x1, y0, y1): side by side under the title, the legend
// and the colour bar's room to the right and below.
constexpr double kDiscBox[2][4] = {{0.005, 0.445, 0.215, 0.875}, {0.445, 0.885, 0.215, 0.875}};
// World window around the unit disc: room for the axis names.
constexpr double kWindow = 1.13;

// The square viewport (page fractions x0, x1, y0, y1, y up) centred in disc d's box.
Eigen::Vector4d disc_viewport(int d, int width, int height) {
  const double* box = kDiscBox[d];
  const double side_px = std::min((box[1] - box[0]) * width, (box[3] - box[2]) * height);
  const double cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
  const double hx = 0.5 * side_px / width, hy = 0.5 * side_px / height;
  return {cx - hx, cx + hx, cy - hy, cy + hy};
}

}  // namespace

void select_disc(Canvas& canvas, int d) {
  const Eigen::Vector4d v = disc_viewport(d, canvas.width(), canvas.height());
  canvas.pls().vpor(v[0], v[1], v[2], v[3]);
  canvas.pls().wind(-kWindow, kWindow, -kWindow, kWindow);
}

Raster trackable_raster(const SphereSamples& samples, int d,
                        const std::function<Rgb(int r, int c)>& trackable_colour) {
  const int n = samples.samples_per_axis;
  Raster raster;
  raster.width = raster.height = n;
  raster.argb.resize(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      Rgb colour = kOutsideWorkspaceColour;
      if (samples.trackable[d](r, c)) {
        colour = trackable_colour(r, c);
      } else if (samples.in_workspace[d](r, c)) {
        colour = kUntrackableColour;
      }
      raster.argb[static_cast<std::size_t>(r) * n + c] = opaque_argb(colour);
    }
  }
  return raster;
}

void paint_disc(Canvas& canvas, int d, const Raster& raster) {
  select_disc(canvas, d);
  canvas.clip_to_unit_disc();
  canvas.paint_raster(raster, -1.0, 1.0, -1.0, 1.0);
  canvas.unclip();
}

void draw_disc_frame(Canvas& canvas, int d) {
  const double s = page_scale(canvas);
  select_disc(canvas, d);
  canvas.pls().col0(kPenInk);
  canvas.pls().width(1.6 * s);
  canvas.pls().arc(0.0, 0.0, 1.0, 1.0, 0.0, 360.0, 0.0, false);
  const Rgb ink{25, 25, 25};
  const double small = kSmallSize * s;
  // Disc 1 is the sphere turned half a turn about +y: -x on the right.
  const char* right = d == 0 ? "+x" : "−x";
  const char* left = d == 0 ? "−x" : "+x";
  canvas.label(1.0, 0.0, right, 6 * s, 0.0, 0.0, small, ink);
  canvas.label(-1.0, 0.0, left, -6 * s, 0.0, 1.0, small, ink);
  canvas.label(0.0, 1.0, "+y", 0.0, -10 * s, 0.5, small, ink);
  canvas.label(0.0, -1.0, "−y", 0.0, 11 * s, 0.5, small, ink);
  canvas.label(0.0, -1.0,
               d == 0 ? "a_z ≥ 0: +z at the centre" : "a_z < 0: −z at the centre, seen from below",
               0.0, 30 * s, 0.5, kLabelSize * s, ink);
}

void draw_disc_contours(Canvas& canvas, int d, const Eigen::MatrixXd& field,
                        const std::vector<double>& levels) {
  if (levels.empty()) return;
  const int n = static_cast<int>(field.rows());
  std::vector<double> values(static_cast<std::size_t>(n) * n);
  std::vector<const double*> columns(n);
  std::vector<double> grid(n);
  for (int i = 0; i < n; ++i) {
    grid[i] = SphereSamples::cell_centre(i, n);
    for (int j = 0; j < n; ++j) {
      // f[i][j] at x = grid[i], y = grid[j]; row r of the field is at y = grid[n - 1 - r].
      values[static_cast<std::size_t>(i) * n + j] = field(n - 1 - j, i);
    }
    columns[i] = values.data() + static_cast<std::size_t>(i) * n;
  }
  PLcGrid coordinates{grid.data(), grid.data(), nullptr, n, n, 0};
  select_disc(canvas, d);
  canvas.clip_to_unit_disc();
  canvas.pls().cont(columns.data(), n, n, 1, n, 1, n, levels.data(),
                    static_cast<int>(levels.size()), plcallback::tr1, &coordinates);
  canvas.unclip();
}

void draw_count_boundaries(Canvas& canvas, const SphereSamples& samples, double width_px, int pen) {
  for (int d = 0; d < 2; ++d) {
    const Eigen::MatrixXd field = samples.visible[d].cast<double>();
    std::vector<double> levels;
    for (int k = field.minCoeff(); k < field.maxCoeff(); ++k) levels.push_back(k + 0.5);
    canvas.pls().col0(pen);
    canvas.pls().width(width_px * page_scale(canvas));
    draw_disc_contours(canvas, d, field, levels);
  }
}

void draw_trackable_boundary(Canvas& canvas, const SphereSamples& samples) {
  const double s = page_scale(canvas);
  for (int d = 0; d < 2; ++d) {
    const Eigen::MatrixXd field = samples.trackable[d].cast<double>();
    if (field.minCoeff() == field.maxCoeff()) continue;
    canvas.pls().col0(kPenInk);
    canvas.pls().width(4.2 * s);
    draw_disc_contours(canvas, d, field, {0.5});
    canvas.pls().col0(kPenBackground);
    canvas.pls().width(2.0 * s);
    draw_disc_contours(canvas, d, field, {0.5});
  }
}

std::vector<CountRegion> count_regions(const SphereSamples& samples) {
  const int n = samples.samples_per_axis;
  std::vector<CountRegion> regions;
  for (int d = 0; d < 2; ++d) {
    const Eigen::MatrixXi& count = samples.visible[d];
    Eigen::MatrixXi region = Eigen::MatrixXi::Constant(n, n, -1);
    std::vector<std::pair<int, int>> stack, cells;
    for (int r0 = 0; r0 < n; ++r0) {
      for (int c0 = 0; c0 < n; ++c0) {
        if (!samples.inside[d](r0, c0) || region(r0, c0) >= 0) continue;
        const int id = static_cast<int>(regions.size());
        cells.clear();
        stack.assign(1, {r0, c0});
        region(r0, c0) = id;
        while (!stack.empty()) {
          const auto [r, c] = stack.back();
          stack.pop_back();
          cells.emplace_back(r, c);
          const int next[4][2] = {{r - 1, c}, {r + 1, c}, {r, c - 1}, {r, c + 1}};
          for (const auto& q : next) {
            if (q[0] < 0 || q[0] >= n || q[1] < 0 || q[1] >= n) continue;
            if (!samples.inside[d](q[0], q[1]) || region(q[0], q[1]) >= 0) continue;
            if (count(q[0], q[1]) != count(r0, c0)) continue;
            region(q[0], q[1]) = id;
            stack.push_back({q[0], q[1]});
          }
        }
        double mr = 0.0, mc = 0.0;
        for (const auto& [r, c] : cells) {
          mr += r;
          mc += c;
        }
        mr /= cells.size();
        mc /= cells.size();
        // The label goes in the region: its cell nearest the centroid, preferring cells away
        // from the region's edge (a cell whose 4-neighbours at distance 2 are in the region).
        CountRegion best{d, count(r0, c0), static_cast<long>(cells.size()), r0, c0};
        double nearest = std::numeric_limits<double>::infinity();
        for (int pass = 0; pass < 2 && !std::isfinite(nearest); ++pass) {
          for (const auto& [r, c] : cells) {
            if (pass == 0) {
              bool interior = true;
              for (const auto& q : {std::pair{r - 2, c}, {r + 2, c}, {r, c - 2}, {r, c + 2}}) {
                interior = interior && q.first >= 0 && q.first < n && q.second >= 0 &&
                           q.second < n && region(q.first, q.second) == id;
              }
              if (!interior) continue;
            }
            const double dist = (r - mr) * (r - mr) + (c - mc) * (c - mc);
            if (dist < nearest) {
              nearest = dist;
              best.row = r;
              best.column = c;
            }
          }
        }
        regions.push_back(best);
      }
    }
  }
  return regions;
}

void label_count_regions(Canvas& canvas, const SphereSamples& samples, double min_fraction) {
  const double s = page_scale(canvas);
  const int n = samples.samples_per_axis;
  const double disc_cells = 0.25 * kPi * n * n;
  for (const CountRegion& region : count_regions(samples)) {
    if (region.cells < min_fraction * disc_cells) continue;
    select_disc(canvas, region.disc);
    canvas.label(SphereSamples::cell_centre(region.column, n),
                 SphereSamples::cell_centre(n - 1 - region.row, n), std::to_string(region.count),
                 0.0, 0.0, 0.5, kSmallSize * s, {25, 25, 25}, {255, 255, 255}, 0.75);
  }
}

void mark_direction(Canvas& canvas, const Eigen::Vector3d& a, double radius_px, Rgb fill,
                    Canvas::Shape shape) {
  const SphereMapPoint p = sphere_map_from_direction(a);
  select_disc(canvas, p.disc);
  canvas.marker(p.xy.x(), p.xy.y(), radius_px, fill, shape);
}

}  // namespace vantage::plot::internal

namespace vantage::plot {

DiscPlacement sphere_map_disc_placement(int disc, int width, int height) {
  const Eigen::Vector4d v = internal::disc_viewport(disc == 0 ? 0 : 1, width, height);
  DiscPlacement p;
  p.centre_px = {0.5 * (v[0] + v[1]) * width, (1.0 - 0.5 * (v[2] + v[3])) * height};
  p.radius_px = 0.5 * (v[1] - v[0]) * width / internal::kWindow;
  return p;
}

}  // namespace vantage::plot
