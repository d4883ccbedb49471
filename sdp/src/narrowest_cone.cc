#include "narrowest_cone.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace vantage::sdp::internal {
namespace {

// Seed of the fixed order in which Welzl's algorithm takes the points (expected linear time;
// the same order every run, so the answer is deterministic).
constexpr unsigned kOrderSeed = 22;
// A point counts as inside a circle up to this relative slack (rounding of the squared radii).
constexpr double kInside = 1e-12;

struct Circle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius2 = -1.0;  // squared radius; < 0: empty
  bool contains(const Eigen::Vector2d& p) const {
    return radius2 >= 0.0 && (p - centre).squaredNorm() <= radius2 * (1.0 + kInside);
  }
};

Circle diameter(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return {0.5 * (a + b), 0.25 * (a - b).squaredNorm()};
}

// The circle through a, b, c; when they are (nearly) collinear, the circle on the two farthest.
Circle through(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d ab = b - a, ac = c - a;
  const double det = 2.0 * (ab.x() * ac.y() - ab.y() * ac.x());
  const double scale = ab.squaredNorm() * ac.squaredNorm();
  if (!(det * det > 1e-24 * scale) || scale == 0.0) {
    Circle best = diameter(a, b);
    for (const Circle& other : {diameter(a, c), diameter(b, c)}) {
      if (other.radius2 > best.radius2) best = other;
    }
    return best;
  }
  const Eigen::Vector2d offset((ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm()) / det,
                               (ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) / det);
  return {a + offset, offset.squaredNorm()};
}

Circle smallest_enclosing_circle(std::vector<Eigen::Vector2d> p) {
  std::mt19937 order(kOrderSeed);
  std::shuffle(p.begin(), p.end(), order);
  Circle c;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (c.contains(p[i])) continue;
    c = {p[i], 0.0};
    for (std::size_t j = 0; j < i; ++j) {
      if (c.contains(p[j])) continue;
      c = diameter(p[i], p[j]);
      for (std::size_t k = 0; k < j; ++k) {
        if (!c.contains(p[k])) c = through(p[i], p[j], p[k]);
      }
    }
  }
  return c;
}

}  // namespace

Eigen::Vector3d narrowest_cone_axis(const Eigen::Matrix3Xd& unit_vectors,
                                    const Eigen::Vector3d& a0) {
  const Eigen::Vector3d e1 = a0.unitOrthogonal();
  const Eigen::Vector3d e2 = a0.cross(e1);
  std::vector<Eigen::Vector2d> projected;
  projected.reserve(static_cast<std::size_t>(unit_vectors.cols()));
  for (Eigen::Index i = 0; i < unit_vectors.cols(); ++i) {
    const Eigen::Vector3d n = unit_vectors.col(i);
    const double s = n.dot(a0) >= 0.0 ? 1.0 : -1.0;
    projected.emplace_back(s * e1.dot(n), s * e2.dot(n));
  }
  const Circle c = smallest_enclosing_circle(std::move(projected));
  return (a0 + c.centre.x() * e1 + c.centre.y() * e2).normalized();
}

}  // namespace vantage::sdp::internal
