#include "perspective_start.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "vantage/analysis/internal/checks.h"

namespace vantage::internal {
namespace {

/// Reciprocal condition number below which a normal matrix counts as singular.
constexpr double kSingularRcond = 1e-12;

}  // namespace

bool scaled_orthographic_start(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                               const Eigen::VectorXd& weights, double focal_length,
                               const PositSettings& settings, PinholeStart* start) {
  const Eigen::Index n = model.cols();
  if (n < 4) return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    centroid += weight_at(weights, i) * model.col(i);
    weight_sum += weight_at(weights, i);
  }
  centroid /= weight_sum;
  // Normal matrix of the rows [z_i - c, 1], scaled to unit object spread for its conditioning.
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  double spread = 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
    spread += weight_at(weights, i) * (model.col(i) - centroid).squaredNorm();
  const double scale = std::sqrt(spread / weight_sum);
  if (!(scale > 0.0)) return false;
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Vector4d row;
    row << (model.col(i) - centroid) / scale, 1.0;
    normal.noalias() += weight_at(weights, i) * row * row.transpose();
  }
  const Eigen::LDLT<Eigen::Matrix4d> solver(normal);
  if (solver.info() != Eigen::Success || !(solver.rcond() > kSingularRcond)) return false;

  Eigen::VectorXd eps = Eigen::VectorXd::Zero(n);
  double best_sse = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < settings.max_iterations; ++iteration) {
    Eigen::Vector4d bx = Eigen::Vector4d::Zero();
    Eigen::Vector4d by = Eigen::Vector4d::Zero();
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::Vector4d row;
      row << (model.col(i) - centroid) / scale, 1.0;
      const double factor = weight_at(weights, i) * (1.0 + eps(i)) / focal_length;
      bx += (factor * centred(0, i)) * row;
      by += (factor * centred(1, i)) * row;
    }
    const Eigen::Vector4d u = solver.solve(bx);
    const Eigen::Vector4d v = solver.solve(by);
    Eigen::Matrix<double, 2, 3> rows;
    rows.row(0) = u.head<3>().transpose() / scale;
    rows.row(1) = v.head<3>().transpose() / scale;
    const Eigen::JacobiSVD<Eigen::Matrix<double, 2, 3>> svd(
        rows, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const double inverse_depth = 0.5 * (svd.singularValues()(0) + svd.singularValues()(1));
    if (!(inverse_depth > 0.0) || !std::isfinite(inverse_depth)) break;
    const Eigen::Matrix<double, 2, 3> top = svd.matrixU() * svd.matrixV().leftCols<2>().transpose();
    Eigen::Matrix3d R;
    R.topRows<2>() = top;
    R.row(2) = top.row(0).cross(top.row(1));
    const double depth = 1.0 / inverse_depth;
    const Eigen::Vector3d centroid_camera(u(3) * depth, v(3) * depth, depth);
    const Eigen::Vector3d p = centroid_camera - R * centroid;
    const double sse = pinhole_sse(model, centred, weights, focal_length, R, p);
    if (sse < best_sse) {
      best_sse = sse;
      start->R = R;
      start->p = p;
    }
    double change = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double next = R.row(2).dot(model.col(i) - centroid) * inverse_depth;
      change = std::max(change, std::abs(next - eps(i)));
      eps(i) = next;
    }
    if (change <= settings.tolerance) break;
  }
  return std::isfinite(best_sse);
}

namespace {

/// The homography H from plane coordinates (a, b, 1), a = u . (z - c), b = v . (z - c) (basis
/// columns u, v, n), to normalised image points (x, y, 1) ~ H (a, b, 1): linear least squares
/// on Hartley-normalised coordinates, scaled so that H(2, 2) = 1.
bool plane_homography(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                      const Eigen::VectorXd& weights, double focal_length, const PlaneFit& plane,
                      const Eigen::Matrix3d& basis, Eigen::Matrix3d* H) {
  const Eigen::Index n = model.cols();
  double weight_sum = 0.0;
  double plane_spread = 0.0;
  Eigen::Vector2d image_mean = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = weight_at(weights, i);
    weight_sum += w;
    plane_spread +=
        w * (basis.leftCols<2>().transpose() * (model.col(i) - plane.centroid)).squaredNorm();
    image_mean += w * centred.col(i);
  }
  image_mean /= weight_sum;
  double image_spread = 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
    image_spread += weight_at(weights, i) * (centred.col(i) - image_mean).squaredNorm();
  const double plane_scale = std::sqrt(plane_spread / weight_sum);
  const double image_scale = std::sqrt(image_spread / weight_sum);
  if (!(plane_scale > 0.0) || !(image_scale > 0.0)) return false;

  // H'(2, 2) = 1: the centroid (the origin of both normalised frames) does not map to infinity
  // for an object in front of the camera. Linear least squares in the other eight entries.
  using Matrix8d = Eigen::Matrix<double, 8, 8>;
  using Vector8d = Eigen::Matrix<double, 8, 1>;
  Matrix8d ata = Matrix8d::Zero();
  Vector8d atb = Vector8d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d local =
        basis.leftCols<2>().transpose() * (model.col(i) - plane.centroid) / plane_scale;
    const Eigen::Vector2d q = (centred.col(i) - image_mean) / image_scale;
    const Eigen::Vector3d m(local.x(), local.y(), 1.0);
    Vector8d rx, ry;
    rx << m, Eigen::Vector3d::Zero(), -q.x() * m.head<2>();
    ry << Eigen::Vector3d::Zero(), m, -q.y() * m.head<2>();
    const double w = weight_at(weights, i);
    ata.noalias() += w * (rx * rx.transpose() + ry * ry.transpose());
    atb.noalias() += w * (q.x() * rx + q.y() * ry);
  }
  const Eigen::LDLT<Matrix8d> solver(ata);
  if (solver.info() != Eigen::Success || !(solver.rcond() > kSingularRcond)) return false;
  const Vector8d h = solver.solve(atb);
  Eigen::Matrix3d normalised_h;
  normalised_h << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), 1.0;
  // Undo the normalisations: centred pixels = T^-1 H' S (a, b, 1); then divide by f.
  Eigen::Matrix3d to_image;
  to_image << image_scale, 0.0, image_mean.x(), 0.0, image_scale, image_mean.y(), 0.0, 0.0, 1.0;
  const Eigen::Matrix3d from_plane =
      Eigen::Vector3d(1.0 / plane_scale, 1.0 / plane_scale, 1.0).asDiagonal();
  *H = Eigen::Vector3d(1.0 / focal_length, 1.0 / focal_length, 1.0).asDiagonal() * to_image *
       normalised_h * from_plane;
  if (!H->allFinite() || !(std::abs((*H)(2, 2)) > 0.0)) return false;
  *H /= (*H)(2, 2);
  return true;
}

/// The rotation taking the unit vector along (v, 1) to the z axis (IPPE's R_v^T).
Eigen::Matrix3d rotation_to_z_axis(const Eigen::Vector2d& v) {
  const Eigen::Vector3d a = Eigen::Vector3d(v.x(), v.y(), 1.0).normalized();
  const double d = 1.0 / (1.0 + a.z());
  Eigen::Matrix3d R;
  R << 1.0 - a.x() * a.x() * d, -a.x() * a.y() * d, -a.x(),  //
      -a.x() * a.y() * d, 1.0 - a.y() * a.y() * d, -a.y(),   //
      a.x(), a.y(), 1.0 - (a.x() * a.x() + a.y() * a.y()) * d;
  return R;
}

/// IPPE (Collins and Bartoli 2014): the two rotations (plane frame -> camera) whose first two
/// columns agree with the homography's Jacobian J at the image v of the plane origin. False
/// when J is singular.
bool ippe_rotations(const Eigen::Matrix3d& H, Eigen::Matrix3d rotations[2]) {
  const Eigen::Vector2d v(H(0, 2), H(1, 2));
  Eigen::Matrix2d J;
  J << H(0, 0) - H(2, 0) * v.x(), H(0, 1) - H(2, 1) * v.x(), H(1, 0) - H(2, 0) * v.y(),
      H(1, 1) - H(2, 1) * v.y();
  const Eigen::Matrix3d Rv = rotation_to_z_axis(v).transpose();
  Eigen::Matrix2d B;
  B << Rv(0, 0) - v.x() * Rv(2, 0), Rv(0, 1) - v.x() * Rv(2, 1), Rv(1, 0) - v.y() * Rv(2, 0),
      Rv(1, 1) - v.y() * Rv(2, 1);
  if (!(std::abs(B.determinant()) > 0.0)) return false;
  const Eigen::Matrix2d A = B.inverse() * J;
  const Eigen::Matrix2d ata = A * A.transpose();
  const double gamma2 =
      0.5 * (ata.trace() + std::sqrt((ata(0, 0) - ata(1, 1)) * (ata(0, 0) - ata(1, 1)) +
                                     4.0 * ata(0, 1) * ata(0, 1)));
  if (!(gamma2 > 0.0) || !std::isfinite(gamma2)) return false;
  const Eigen::Matrix2d r = A / std::sqrt(gamma2);
  const double b0 = std::sqrt(std::max(0.0, 1.0 - r.col(0).squaredNorm()));
  double b1 = std::sqrt(std::max(0.0, 1.0 - r.col(1).squaredNorm()));
  if (-r.col(0).dot(r.col(1)) < 0.0) b1 = -b1;
  for (int k = 0; k < 2; ++k) {
    const double sign = k == 0 ? 1.0 : -1.0;
    Eigen::Vector3d c0(r(0, 0), r(1, 0), sign * b0);
    Eigen::Vector3d c1(r(0, 1), r(1, 1), sign * b1);
    Eigen::Matrix3d local;
    local << c0, c1, c0.cross(c1);
    rotations[k] = Rv * local;
  }
  return true;
}

/// Least-squares translation for rotation R: X_i = R z_i + p with (x_i, y_i) X_i.z = X_i.xy,
/// linear in p (algebraic error, weighted).
Eigen::Vector3d linear_translation(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                                   const Eigen::VectorXd& weights, double focal_length,
                                   const Eigen::Matrix3d& R) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < model.cols(); ++i) {
    const Eigen::Vector2d x = centred.col(i) / focal_length;
    Eigen::Matrix<double, 2, 3> a;
    a << 1.0, 0.0, -x.x(), 0.0, 1.0, -x.y();
    const double w = weight_at(weights, i);
    normal.noalias() += w * a.transpose() * a;
    rhs.noalias() -= w * a.transpose() * (a * (R * model.col(i)));
  }
  return normal.ldlt().solve(rhs);
}

}  // namespace

int planar_starts(const Eigen::Matrix3Xd& model, const Eigen::Matrix2Xd& centred,
                  const Eigen::VectorXd& weights, double focal_length, const PlaneFit& plane,
                  PinholeStart starts[2]) {
  if (model.cols() < 4) return 0;
  Eigen::Matrix3d basis;  // columns u, v, n
  basis.col(2) = plane.normal;
  basis.col(0) = plane.normal.unitOrthogonal();
  basis.col(1) = plane.normal.cross(basis.col(0));
  Eigen::Matrix3d H;
  Eigen::Matrix3d rotations[2];
  if (!plane_homography(model, centred, weights, focal_length, plane, basis, &H) ||
      !ippe_rotations(H, rotations)) {
    return 0;
  }
  int count = 0;
  for (const Eigen::Matrix3d& local : rotations) {
    const Eigen::Matrix3d R = local * basis.transpose();
    const Eigen::Vector3d p = linear_translation(model, centred, weights, focal_length, R);
    if (!R.allFinite() || !p.allFinite()) continue;
    starts[count].R = R;
    starts[count].p = p;
    ++count;
  }
  return count;
}

}  // namespace vantage::internal
