#pragma once

// One scalar over the two discs of a whole-sphere map (sphere_map.h), sampled at every cell
// centre with the visible-marker count and flags the shared drawing needs: the CRB map's bound
// and the TRE map's RMS. Private to vantage::plot.

#include <Eigen/Core>
#include <array>
#include <functional>
#include <limits>

#include "vantage/plot/sphere_map.h"

namespace vantage::plot::internal {

/// What a map shows at one direction.
struct CellValue {
  int visible = 0;  ///< markers seen
  bool trackable = false;
  bool in_workspace = false;
  double value = std::numeric_limits<double>::quiet_NaN();  ///< NaN when not trackable
};

/// The cells of both discs (visible counts and flags, for the boundaries and count labels) and
/// the value at each cell centre (NaN where not trackable).
struct ValueCells {
  SphereSamples samples;
  std::array<Eigen::MatrixXd, 2> value;
};

/// `at` of every cell centre of both n x n discs, on `threads` threads (0: all cores); `at`
/// must be safe to call concurrently.
ValueCells sample_value_cells(int n, int threads,
                              const std::function<CellValue(const Eigen::Vector3d& a)>& at);

/// Widens [*lo, *hi] to every value of the cells inside the discs.
void widen_to_cells(const ValueCells& cells, double* lo, double* hi);

}  // namespace vantage::plot::internal
