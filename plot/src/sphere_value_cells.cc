#include "sphere_value_cells.h"

#include <algorithm>
#include <cmath>

#include "vantage/analysis/parallel.h"

namespace vantage::plot::internal {

ValueCells sample_value_cells(int n, int threads,
                              const std::function<CellValue(const Eigen::Vector3d& a)>& at) {
  ValueCells cells;
  SphereSamples& s = cells.samples;
  s.samples_per_axis = n;
  for (int d = 0; d < 2; ++d) {
    s.visible[d].resize(n, n);
    s.t[d] = Eigen::MatrixXd::Zero(n, n);
    s.trackable[d].resize(n, n);
    s.in_workspace[d].resize(n, n);
    s.inside[d].resize(n, n);
    cells.value[d].resize(n, n);
  }
  parallel_blocks(2L * n, threads, [&](long begin, long end) {
    for (long k = begin; k < end; ++k) {
      const int d = static_cast<int>(k / n), r = static_cast<int>(k % n);
      for (int c = 0; c < n; ++c) {
        const CellValue v = at(s.direction(d, r, c));
        s.visible[d](r, c) = v.visible;
        s.trackable[d](r, c) = v.trackable;
        s.in_workspace[d](r, c) = v.in_workspace;
        const Eigen::Vector2d xy(SphereSamples::cell_centre(c, n),
                                 SphereSamples::cell_centre(n - 1 - r, n));
        s.inside[d](r, c) = xy.squaredNorm() <= 1.0;
        cells.value[d](r, c) = v.trackable ? v.value : std::numeric_limits<double>::quiet_NaN();
      }
    }
  });
  return cells;
}

void widen_to_cells(const ValueCells& cells, double* lo, double* hi) {
  for (int d = 0; d < 2; ++d) {
    for (Eigen::Index k = 0; k < cells.value[d].size(); ++k) {
      const double v = cells.value[d](k);
      if (std::isnan(v) || !cells.samples.inside[d](k)) continue;
      *lo = std::min(*lo, v);
      *hi = std::max(*hi, v);
    }
  }
}

}  // namespace vantage::plot::internal
