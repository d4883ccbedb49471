#pragma once

// The worst viewpoint of a near-degenerate layout, from the sines rather than the cosines.
// Private to vantage::sdp.

#include <Eigen/Core>

namespace vantage::sdp::internal {

/// For unit vectors n_i all within a small angle of the line of a0 (up to sign: a
/// near-degenerate layout, docs/math.md §12), the viewpoint a that minimises
/// p-bar(a) = max_i |a x n_i|: the axis of the narrowest cone around the +-n_i. Theorem 6's
/// objective t = min_i |a.n_i| = cos(angle) has rounded to 1 for all such a (1 - t ~ angle^2 / 2
/// is below the rounding of t when the angle is below 1e-8), so the branch and bound may return
/// any of them; the sines keep their digits. Solved as the smallest enclosing circle (Welzl's
/// algorithm, in a fixed pseudo-random order) of the projections s_i n_i onto the plane through
/// a0 perpendicular to it (s_i = sign(a0.n_i)), whose centre c gives a = (a0 + c) / |a0 + c|:
/// exact to first order in the cone's angle (the projection shortens an angle phi to sin phi).
Eigen::Vector3d narrowest_cone_axis(const Eigen::Matrix3Xd& unit_vectors,
                                    const Eigen::Vector3d& a0);

}  // namespace vantage::sdp::internal
