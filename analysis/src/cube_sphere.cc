#include "vantage/analysis/cube_sphere.h"

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

double cube_patch_cos_radius(double u, double v, double h) {
  // On every face the point is a signed permutation of (1, u, v), which leaves dot products
  // alone, and 1 + u cu + v cv >= 1 inside a face, so cos^2 decides.
  double worst = std::numeric_limits<double>::infinity();  // min over corners of dot^2 / |q|^2
  for (int corner = 0; corner < 4; ++corner) {
    const double cu = u + ((corner & 1) ? h : -h);
    const double cv = v + ((corner & 2) ? h : -h);
    const double dot = 1.0 + u * cu + v * cv;
    worst = std::min(worst, dot * dot / (1.0 + cu * cu + cv * cv));
  }
  return std::clamp(std::sqrt(worst / (1.0 + u * u + v * v)), 0.0, 1.0);
}

}  // namespace vantage
