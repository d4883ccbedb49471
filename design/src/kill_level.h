#pragma once

// Private to vantage::design: geometry on the unit sphere behind "can one more vector kill every
// worst viewpoint?" (docs/math.md §18).

#include <Eigen/Core>
#include <vector>

namespace vantage::design::internal {

/// Cross products shorter than this do not define a direction.
inline constexpr double kMinCross = 1e-12;

/// Two unit vectors spanning the plane perpendicular to the unit vector a.
void perpendicular_basis(const Eigen::Vector3d& a, Eigen::Vector3d* u, Eigen::Vector3d* v);

/// min over unit c of max_k |a_k.c| for the worst viewpoints a (non-empty), and a minimiser.
/// The minimum is attained at c = a_i x a_j or c ~ (a_i - s a_j) x (a_i - s' a_k), s, s' = +-1
/// (any c perpendicular to a single a_0): every such point is appended to *points, in the order
/// tried, so that callers can use them as candidates.
double best_kill_level(const std::vector<Eigen::Vector3d>& a, Eigen::Vector3d* argmin,
                       std::vector<Eigen::Vector3d>* points);

}  // namespace vantage::design::internal
