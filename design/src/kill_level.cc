#include "kill_level.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vantage::design::internal {

void perpendicular_basis(const Eigen::Vector3d& a, Eigen::Vector3d* u, Eigen::Vector3d* v) {
  Eigen::Index i;
  a.cwiseAbs().minCoeff(&i);
  *u = a.cross(Eigen::Vector3d::Unit(i)).normalized();
  *v = a.cross(*u).normalized();
}

double best_kill_level(const std::vector<Eigen::Vector3d>& a, Eigen::Vector3d* argmin,
                       std::vector<Eigen::Vector3d>* points) {
  const int k = static_cast<int>(a.size());
  auto level = [&a](const Eigen::Vector3d& c) {
    double m = 0.0;
    for (const Eigen::Vector3d& ak : a) m = std::max(m, std::abs(ak.dot(c)));
    return m;
  };
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](const Eigen::Vector3d& d) {
    if (d.norm() < kMinCross) return;
    const Eigen::Vector3d c = d.normalized();
    points->push_back(c);
    const double l = level(c);
    if (l < best) {
      best = l;
      *argmin = c;
    }
  };
  if (k == 1) {
    Eigen::Vector3d u, v;
    perpendicular_basis(a[0], &u, &v);
    consider(u);
  }
  for (int i = 0; i < k; ++i) {
    for (int j = i + 1; j < k; ++j) {
      consider(a[i].cross(a[j]));
      for (int l = j + 1; l < k; ++l) {
        for (double s1 : {1.0, -1.0}) {
          for (double s2 : {1.0, -1.0}) consider((a[i] - s1 * a[j]).cross(a[i] - s2 * a[l]));
        }
      }
    }
  }
  return best;
}

}  // namespace vantage::design::internal
