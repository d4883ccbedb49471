#include "vantage/sdp/internal/min_norm_point.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace vantage::sdp::internal {
namespace {

// Optimality slack of the Wolfe test x.p_j >= ||x||^2 - kOptimality for unit-size points.
constexpr double kOptimality = 1e-14;
// Barycentric weights at or below this are treated as zero (point leaves the corral).
constexpr double kWeightZero = 1e-14;
// ||x||^2 below this means the origin is in the hull.
constexpr double kOriginSquared = 1e-28;
// Gram determinants below this (relative) mean the corral is affinely dependent.
constexpr double kSingular = 1e-22;

// Affine minimum-norm point of the corral q[0..k-1]: y = sum lambda_i q_i, sum lambda_i = 1.
// Returns false when the corral is (numerically) affinely dependent.
bool affine_min_norm(const Eigen::Vector3d* q, int k, double* lambda, Eigen::Vector3d* y) {
  if (k == 1) {
    lambda[0] = 1.0;
    *y = q[0];
    return true;
  }
  const int r = k - 1;
  Eigen::Matrix3d E;
  for (int i = 0; i < r; ++i) E.col(i) = q[i + 1] - q[0];
  Eigen::Vector3d mu = Eigen::Vector3d::Zero();
  if (r == 1) {
    const double ee = E.col(0).squaredNorm();
    if (ee <= kSingular) return false;
    mu(0) = -E.col(0).dot(q[0]) / ee;
  } else if (r == 2) {
    const Eigen::Matrix2d G = E.leftCols<2>().transpose() * E.leftCols<2>();
    const double det = G.determinant();
    if (det <= kSingular * G.trace() * G.trace()) return false;
    const Eigen::Vector2d rhs = -E.leftCols<2>().transpose() * q[0];
    mu.head<2>() = G.inverse() * rhs;
  } else {
    const double det = E.determinant();
    if (std::abs(det) <= 1e-15) return false;
    mu = -E.inverse() * q[0];
  }
  double sum = 0.0;
  for (int i = 0; i < r; ++i) {
    lambda[i + 1] = mu(i);
    sum += mu(i);
  }
  lambda[0] = 1.0 - sum;
  *y = q[0] + E.leftCols(r) * mu.head(r);
  return true;
}

using PointAt = Eigen::Map<const Eigen::Vector3d>;

// The index of the point of least norm (the first of equals).
int nearest_to_origin(const double* points, int count) {
  int best = 0;
  double best_norm = PointAt(points).squaredNorm();
  for (int i = 1; i < count; ++i) {
    const double n = PointAt(points + 3 * i).squaredNorm();
    if (n < best_norm) {
      best_norm = n;
      best = i;
    }
  }
  return best;
}

// The point most violating the Wolfe test x.p_j >= ||x||^2 - kOptimality, or -1 if none does.
int most_violating(const Eigen::Vector3d& x, double xx, const double* points, int count) {
  int j = -1;
  double lowest = xx - kOptimality;
  for (int i = 0; i < count; ++i) {
    const double v = x.dot(PointAt(points + 3 * i));
    if (v < lowest) {
      lowest = v;
      j = i;
    }
  }
  return j;
}

// Wolfe's minor cycles on the corral corral[0..*k-1] with barycentric weights weight[] of x:
// moves x to the affine minimum-norm point of the corral, dropping the points whose weight
// vanishes on the way. Returns false (with the newest point dropped) when the corral is affinely
// dependent, which happens only from rounding.
bool minor_cycles(Eigen::Vector3d* corral, double* weight, int* k, Eigen::Vector3d* x) {
  double lambda[4];
  for (int minor = 0; minor < 8; ++minor) {
    Eigen::Vector3d y;
    if (!affine_min_norm(corral, *k, lambda, &y)) {
      // Affinely dependent corral (only from rounding): keep x, which is in the hull.
      --*k;
      return false;
    }
    bool interior = true;
    for (int i = 0; i < *k; ++i) interior = interior && lambda[i] > kWeightZero;
    if (interior) {
      *x = y;
      std::copy(lambda, lambda + *k, weight);
      return true;
    }
    double theta = 1.0;
    for (int i = 0; i < *k; ++i) {
      if (lambda[i] <= kWeightZero && weight[i] - lambda[i] > 0.0) {
        theta = std::min(theta, weight[i] / (weight[i] - lambda[i]));
      }
    }
    *x = (1.0 - theta) * *x + theta * y;
    int kept = 0;
    int weakest = 0;
    for (int i = 0; i < *k; ++i) {
      weight[i] = (1.0 - theta) * weight[i] + theta * lambda[i];
      if (weight[i] < weight[weakest]) weakest = i;
    }
    for (int i = 0; i < *k; ++i) {
      if (i != weakest && weight[i] > kWeightZero) {
        corral[kept] = corral[i];
        weight[kept] = weight[i];
        ++kept;
      }
    }
    *k = std::max(kept, 1);
    if (kept == 0) {
      corral[0] = *x;
      weight[0] = 1.0;
    }
  }
  return true;
}

}  // namespace

MinNormPoint min_norm_point(const double* points, int count) {
  MinNormPoint result;
  Eigen::Vector3d corral[4];
  double weight[4];
  int k = 1;
  corral[0] = PointAt(points + 3 * nearest_to_origin(points, count));
  weight[0] = 1.0;
  Eigen::Vector3d x = corral[0];
  bool stalled = false;

  for (int major = 0; major < 64 + 4 * count; ++major) {
    const double xx = x.squaredNorm();
    if (xx <= kOriginSquared) {
      result.x.setZero();
      result.contains_origin = true;
      return result;
    }
    const int j = most_violating(x, xx, points, count);
    if (j < 0 || k == 4 || stalled) break;
    corral[k] = PointAt(points + 3 * j);
    weight[k] = 0.0;
    ++k;
    stalled = !minor_cycles(corral, weight, &k, &x);
  }
  result.x = x;
  result.contains_origin = x.squaredNorm() <= kOriginSquared;
  return result;
}

}  // namespace vantage::sdp::internal
