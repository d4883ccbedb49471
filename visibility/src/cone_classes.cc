// The cone classes of docs/math.md §20 ("Units"): markers of one normal and one cone, and the
// pairs of classes whose hidden sides do not meet.

#include "vantage/visibility/internal/cone_classes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "vantage/analysis/common.h"

namespace vantage::visibility::internal {
namespace {

// Two cones' hidden sides count as apart only this far (radians) beyond touching.
constexpr double kApartMargin = 1e-12;

// Open caps about -n of radius pi - theta, apart when their centres are at least the sum of the
// radii apart. Opposite normals are decided exactly (n.a < c1 and n.a > -c2 never both hold
// when c1 <= -c2). A normal is unit only to the problem's tolerance (1e-9), and the visibility
// test is n.a >= c with n as given, so the cap's true half-angle is acos(c / |n|): far more than
// the margin when |n| is 1 - 1e-9.
bool hidden_sides_apart(const Eigen::Vector3d& n1, double c1, const Eigen::Vector3d& n2,
                        double c2) {
  if (n1 == -n2) return c1 + c2 <= 0.0;
  const double between = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
  const double t1 = std::acos(std::clamp(c1 / n1.norm(), -1.0, 1.0));
  const double t2 = std::acos(std::clamp(c2 / n2.norm(), -1.0, 1.0));
  return between >= 2.0 * kPi - t1 - t2 + kApartMargin;
}

}  // namespace

ConeClasses::ConeClasses(const Eigen::Matrix3Xd& normals, const Eigen::VectorXd& cos_cone) {
  const auto n = static_cast<int>(normals.cols());
  class_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    class_[i] = i;
    for (int j = 0; j < i; ++j) {
      if (normals.col(j) == normals.col(i) && cos_cone(j) == cos_cone(i)) {
        class_[i] = class_[j];
        break;
      }
    }
  }
  apart_.assign(static_cast<std::size_t>(n) * n, 0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      apart_[static_cast<std::size_t>(class_[i]) * n + class_[j]] =
          hidden_sides_apart(normals.col(i), cos_cone(i), normals.col(j), cos_cone(j));
    }
  }
}

}  // namespace vantage::visibility::internal
