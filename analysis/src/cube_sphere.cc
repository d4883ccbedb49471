#include "vantage/analysis/cube_sphere.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vantage {

Eigen::Vector3d cube_face_direction(int face, double u, double v) {
  const int k = face % 3;
  const double s = face < 3 ? 1.0 : -1.0;
  Eigen::Vector3d a;
  a(k) = s;
  a((k + 1) % 3) = u;
  a((k + 2) % 3) = v;
  return a / std::sqrt(1.0 + u * u + v * v);
}

CubeFacePoint cube_face_point(const Eigen::Vector3d& a) {
  int k = 0;
  a.cwiseAbs().maxCoeff(&k);
  CubeFacePoint p;
  p.face = a(k) >= 0.0 ? k : k + 3;
  // a / |a_k| = s e_k + u e_{k+1} + v e_{k+2}, s the sign of a_k.
  const double major = std::abs(a(k));
  p.u = std::clamp(a((k + 1) % 3) / major, -1.0, 1.0);
  p.v = std::clamp(a((k + 2) % 3) / major, -1.0, 1.0);
  return p;
}

double cube_patch_radius(double u, double v, double h) {
  // On every face the points are signed permutations of (1, u, v), which leave angles alone.
  // atan2(|p x q|, p.q) keeps full precision for small patches, where acos of a dot would not.
  const Eigen::Vector3d p(1.0, u, v);
  double widest = 0.0;
  for (int corner = 0; corner < 4; ++corner) {
    const Eigen::Vector3d q(1.0, u + ((corner & 1) ? h : -h), v + ((corner & 2) ? h : -h));
    widest = std::max(widest, std::atan2(p.cross(q).norm(), p.dot(q)));
  }
  // A few ulps up: the radius bounds the patch from outside.
  return widest * (1.0 + 8.0 * std::numeric_limits<double>::epsilon());
}

}  // namespace vantage
