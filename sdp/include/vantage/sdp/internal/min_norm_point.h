#pragma once

// Private: the point of minimum norm in the convex hull of points in R^3 (Wolfe's algorithm).

#include <Eigen/Core>

namespace vantage::sdp::internal {

struct MinNormPoint {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< a point of conv{p_i}, of minimum norm
  bool contains_origin = false;                 ///< ||x|| ~ 0: the origin is in the hull
};

/// Minimum-norm point of conv{p_0..p_{count-1}}, points stored as consecutive xyz triples
/// (the layout of Eigen::Matrix3Xd::data()), count >= 1, each of norm ~1. Terminates when
/// x.p_j >= ||x||^2 - 1e-14 for every j, so ||x|| is the distance from the origin to the hull
/// to about 1e-14 and x is always inside the hull. Allocates nothing.
MinNormPoint min_norm_point(const double* points, int count);

}  // namespace vantage::sdp::internal
