#include "vantage/analysis/occlusion_grid.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/cube_sphere.h"

namespace vantage {

OcclusionGrid::OcclusionGrid(int markers, int cells_per_edge)
    : markers_(markers), n_(cells_per_edge) {
  VANTAGE_CHECK(markers >= 0 && cells_per_edge >= 1 && cells_per_edge <= kMaxCellsPerEdge,
                "occlusion grid size");
  blocked_.assign(static_cast<std::size_t>(markers) * 6 * n_ * n_, 0);
}

int OcclusionGrid::cells_per_edge_for(double resolution_rad) {
  // The central cell spans 2 atan(1 / N); the others are narrower.
  const double n = std::ceil(1.0 / std::tan(0.5 * resolution_rad));
  return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(kMaxCellsPerEdge)));
}

double OcclusionGrid::resolution() const { return 2.0 * std::atan(1.0 / std::max(n_, 1)); }

std::size_t OcclusionGrid::flag_at(int marker, int face, int i, int j) const {
  return ((static_cast<std::size_t>(marker) * 6 + face) * n_ + i) * n_ + j;
}

std::size_t OcclusionGrid::sum_at(int marker, int face, int i, int j) const {
  const std::size_t side = static_cast<std::size_t>(n_) + 1;
  return ((static_cast<std::size_t>(marker) * 6 + face) * side + i) * side + j;
}

void OcclusionGrid::set_blocked(int marker, int face, int i, int j, bool blocked) {
  blocked_[flag_at(marker, face, i, j)] = blocked ? 1 : 0;
}

void OcclusionGrid::finish() {
  const std::size_t side = static_cast<std::size_t>(n_) + 1;
  sums_.assign(static_cast<std::size_t>(markers_) * 6 * side * side, 0);
  for (int m = 0; m < markers_; ++m) {
    for (int f = 0; f < 6; ++f) {
      for (int i = 0; i < n_; ++i) {
        for (int j = 0; j < n_; ++j) {
          sums_[sum_at(m, f, i + 1, j + 1)] = static_cast<std::uint16_t>(
              blocked_[flag_at(m, f, i, j)] + sums_[sum_at(m, f, i, j + 1)] +
              sums_[sum_at(m, f, i + 1, j)] - sums_[sum_at(m, f, i, j)]);
        }
      }
    }
  }
}

int OcclusionGrid::cell_index(double coordinate) const {
  const int i = static_cast<int>(std::floor((coordinate + 1.0) * 0.5 * n_));
  return std::clamp(i, 0, n_ - 1);
}

bool OcclusionGrid::blocked(int marker, const Eigen::Vector3d& a) const {
  const CubeFacePoint p = cube_face_point(a);
  return blocked_[flag_at(marker, p.face, cell_index(p.u), cell_index(p.v))] != 0;
}

OcclusionGrid::Cells OcclusionGrid::cells(double u0, double u1, double v0, double v1) const {
  return {cell_index(u0), cell_index(u1), cell_index(v0), cell_index(v1)};
}

OcclusionGrid::Span OcclusionGrid::span(int marker, int face, double u0, double u1, double v0,
                                        double v1) const {
  const auto [i0, i1, j0, j1] = cells(u0, u1, v0, v1);
  const int count = sums_[sum_at(marker, face, i1 + 1, j1 + 1)] -
                    sums_[sum_at(marker, face, i0, j1 + 1)] -
                    sums_[sum_at(marker, face, i1 + 1, j0)] + sums_[sum_at(marker, face, i0, j0)];
  if (count == 0) return Span::kClear;
  if (count == (i1 - i0 + 1) * (j1 - j0 + 1)) return Span::kBlocked;
  return Span::kMixed;
}

OcclusionGrid OcclusionGrid::without(int k) const {
  VANTAGE_CHECK(k >= 0 && k < markers_, "occlusion grid: no such marker");
  OcclusionGrid out(markers_ - 1, n_);
  const std::size_t per_marker = static_cast<std::size_t>(6) * n_ * n_;
  std::copy_n(blocked_.begin(), per_marker * k, out.blocked_.begin());
  std::copy(blocked_.begin() + per_marker * (k + 1), blocked_.end(),
            out.blocked_.begin() + per_marker * k);
  out.finish();
  return out;
}

}  // namespace vantage
