#pragma once

/// Which directions a body shadows, per marker, sampled on the cube-face grid of
/// cube_sphere.h: docs/math.md §20. body::build_occlusion_grid() casts the rays; the
/// visibility search only reads the grid.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace vantage {

/// Per marker, a blocked/clear flag for each of the 6 N^2 cells of the cube faces (cell (i, j)
/// of a face covers u in [-1 + 2i/N, -1 + 2(i+1)/N], v likewise), with summed-area tables so that
/// any rectangle of cells is answered in O(1).
class OcclusionGrid {
 public:
  /// Most cells per cube edge (the sums fit 16 bits): a resolution of about 0.45 degrees.
  static constexpr int kMaxCellsPerEdge = 255;

  OcclusionGrid() = default;
  /// A grid of `markers` markers, every cell clear. 1 <= cells_per_edge <= kMaxCellsPerEdge.
  OcclusionGrid(int markers, int cells_per_edge);

  /// The cells per edge that give cells no wider than `resolution_rad` (radians, > 0), capped
  /// at kMaxCellsPerEdge.
  static int cells_per_edge_for(double resolution_rad);

  bool empty() const { return markers_ == 0; }
  int markers() const { return markers_; }
  int cells_per_edge() const { return n_; }
  /// The largest angular size of a cell (the central cell of a face), radians.
  double resolution() const;

  /// Marks a cell before finish().
  void set_blocked(int marker, int face, int i, int j, bool blocked);
  /// Builds the summed-area tables; call once after the last set_blocked().
  void finish();

  /// The flag of the cell that holds direction a.
  bool blocked(int marker, const Eigen::Vector3d& a) const;

  /// What a rectangle of face coordinates [u0, u1] x [v0, v1] holds for a marker (every cell it
  /// touches counts).
  enum class Span { kClear, kBlocked, kMixed };
  Span span(int marker, int face, double u0, double u1, double v0, double v1) const;

  /// The cells [i0, i1] x [j0, j1] of a face that a rectangle of face coordinates touches, as
  /// span() counts them.
  struct Cells {
    int i0, i1, j0, j1;
  };
  Cells cells(double u0, double u1, double v0, double v1) const;
  /// The flag of cell (i, j) of a face.
  bool blocked_cell(int marker, int face, int i, int j) const {
    return blocked_[flag_at(marker, face, i, j)] != 0;
  }

  /// The grid without marker `k` (the others keep their flags), for dropout analyses.
  OcclusionGrid without(int k) const;

 private:
  int cell_index(double coordinate) const;
  std::size_t flag_at(int marker, int face, int i, int j) const;
  std::size_t sum_at(int marker, int face, int i, int j) const;

  int markers_ = 0;
  int n_ = 0;
  std::vector<std::uint8_t> blocked_;  // [marker][face][i][j]
  std::vector<std::uint16_t> sums_;    // [marker][face][i][j] over (N+1)^2: blocked cells below
};

}  // namespace vantage
