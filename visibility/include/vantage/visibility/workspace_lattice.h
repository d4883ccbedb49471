#pragma once

/// The directions at which a workspace is sampled (docs/math.md §20, "Coverage"): a Fibonacci
/// lattice on the workspace's own cap, at the density of `count` points on the whole sphere.

#include <Eigen/Core>
#include <optional>

#include "vantage/visibility/visibility.h"

namespace vantage::visibility {

/// Equal-area directions of a workspace, every one inside it.
struct WorkspaceLattice {
  Eigen::Matrix3Xd directions;  ///< 3 x M, unit
  double spacing = 0.0;         ///< sqrt(cap area / M), radians: the mean distance between them
};

/// A cap smaller than this share of the sphere's lattice still gets this many directions.
inline constexpr int kMinWorkspaceDirections = 100;

/// The lattice of `count` (>= 1) directions' density on the sphere, restricted to `workspace`:
/// without one (or with the whole sphere) exactly fibonacci_directions(count); for a cap of
/// half-angle θ about w, M = max(ceil(count (1 - cos θ) / 2), min(count, 100)) points of the
/// Fibonacci spiral of the cap, z_k = 1 - (1 - cos θ)(2k + 1) / (2M) along w.
WorkspaceLattice workspace_lattice(const std::optional<Workspace>& workspace, int count);

}  // namespace vantage::visibility
