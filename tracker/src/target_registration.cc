#include "vantage/tracker/target_registration.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/analysis/internal/number_text.h"

namespace vantage::tracker {
namespace {

// Lambda is singular (collinear markers) below this fraction of its trace: its condition then
// exceeds 1e12 and the first-order maps lose every digit.
constexpr double kCollinearFraction = 1e-12;

// A length in a message: three significant digits.
std::string length_text(double x) {
  if (!std::isfinite(x)) return "beyond the range of doubles";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// "target 2: " for the third of several targets (index 2), "" for index -1.
std::string target_text(long index) {
  return index < 0 ? std::string() : "target " + std::to_string(index) + ": ";
}

// A target is on a 5-DoF tool's line within this fraction of the set's size (rounding).
constexpr double kOnAxisFraction = 1e-9;

// Lambda (Eq. 23.2) of the markers `visible` about their centroid.
Eigen::Matrix3d lambda_of(const Eigen::Matrix3Xd& points, const std::vector<int>& visible,
                          Eigen::Vector3d* centroid) {
  *centroid = Eigen::Vector3d::Zero();
  for (int i : visible) *centroid += points.col(i);
  *centroid /= static_cast<double>(visible.size());
  Eigen::Matrix3d lambda = Eigen::Matrix3d::Zero();
  for (int i : visible) {
    const Eigen::Vector3d q = points.col(i) - *centroid;
    lambda += q.squaredNorm() * Eigen::Matrix3d::Identity() - q * q.transpose();
  }
  return lambda;
}

bool collinear(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& eigen, double trace) {
  return !(eigen.eigenvalues()(0) > kCollinearFraction * trace);
}

// 0, 1, ..., n - 1: every marker of a tool.
std::vector<int> all_markers(Eigen::Index n) {
  std::vector<int> all(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return all;
}

// Every marker of the tool on one line: its centroid and (unsigned) direction; false otherwise.
bool tool_line(const Eigen::Matrix3Xd& points, Eigen::Vector3d* centroid,
               Eigen::Vector3d* direction) {
  const Eigen::Matrix3d lambda = lambda_of(points, all_markers(points.cols()), centroid);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(lambda);
  if (!collinear(eigen, lambda.trace())) return false;
  *direction = eigen.eigenvectors().col(0);
  return true;
}

// How far a target may be from the line of collinear markers (about their centroid, along
// `axis`) and still be on it: the rounding of the lengths, plus twice what the markers'
// deviation from the line, epsilon, leaves undetermined there (the line is known to within
// epsilon across it and epsilon / radius in direction, so to within epsilon (1 + |d| / radius)
// at the target). Epsilon is the larger of the markers' own largest distance from the line and
// the largest the collinearity test accepts, sqrt(1e-12 trace Lambda) (about 1e-6 of the tool's
// size; float32 coordinates, a .rom's, deviate by about 1e-7).
double on_axis_tolerance(const Eigen::Matrix3Xd& points, const std::vector<int>& visible,
                         const Eigen::Vector3d& centroid, const Eigen::Vector3d& axis,
                         double radius, double distance, double trace) {
  double epsilon = std::sqrt(kCollinearFraction * trace);
  for (int i : visible) {
    epsilon = std::max(epsilon, (points.col(i) - centroid).cross(axis).norm());
  }
  return kOnAxisFraction * (radius + distance) + 2.0 * epsilon * (1.0 + distance / radius);
}

// The registration of the set `visible` (about `centroid`, `eigen` of its Lambda) for a target
// at `d` from the centroid.
Registration classify(const Eigen::Matrix3Xd& points, const std::vector<int>& visible,
                      const Eigen::Vector3d& centroid, const Eigen::Vector3d& d,
                      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& eigen, double trace) {
  if (visible.size() < 3) return Registration::kTooFew;
  if (!collinear(eigen, trace)) return Registration::kFull;
  // Lambda = s (I - u u^T) for markers on the line u: trace 2 s, RMS radius sqrt(s / n).
  const double radius = std::sqrt(0.5 * trace / static_cast<double>(visible.size()));
  const Eigen::Vector3d axis = eigen.eigenvectors().col(0);
  const bool on_axis = d.cross(axis).norm() <=
                       on_axis_tolerance(points, visible, centroid, axis, radius, d.norm(), trace);
  Eigen::Vector3d tool_centroid;
  Eigen::Vector3d tool_direction;
  return on_axis && tool_line(points, &tool_centroid, &tool_direction) ? Registration::kOnAxis
                                                                       : Registration::kOffAxis;
}

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

FleModel FleModel::isotropic(double rms) {
  FleModel fle;
  fle.sigma_perp = fle.sigma_axial = rms / std::sqrt(3.0);
  fle.from_rms = true;
  return fle;
}

double FleModel::rms() const {
  return std::sqrt(2.0 * sigma_perp * sigma_perp + sigma_axial * sigma_axial);
}

bool FleModel::is_valid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why != nullptr) *why = message;
    return false;
  };
  if (!(std::isfinite(sigma_perp) && sigma_perp >= 0.0)) {
    return fail("sigma_perp: must be finite and >= 0");
  }
  if (!(std::isfinite(sigma_axial) && sigma_axial >= 0.0)) {
    return fail("sigma_axial: must be finite and >= 0");
  }
  if (sigma_perp == 0.0 && sigma_axial == 0.0) {
    return fail("sigma_perp: sigma_perp and sigma_axial must not both be 0");
  }
  return true;
}

const char* to_string(Registration registration) {
  switch (registration) {
    case Registration::kFull:
      return "full";
    case Registration::kOnAxis:
      return "on_axis";
    case Registration::kTooFew:
      return "too_few";
    case Registration::kOffAxis:
      break;
  }
  return "off_axis";
}

Registration registration_of(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                             const Eigen::Vector3d& target_tool) {
  if (visible.size() < 3) return Registration::kTooFew;
  Eigen::Vector3d centroid;
  const Eigen::Matrix3d lambda = lambda_of(points_tool, visible, &centroid);
  return classify(points_tool, visible, centroid, target_tool - centroid,
                  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(lambda), lambda.trace());
}

bool tool_axis(const Eigen::Matrix3Xd& points_tool, Eigen::Vector3d* point,
               Eigen::Vector3d* direction) {
  if (points_tool.cols() < 2 || !tool_line(points_tool, point, direction)) return false;
  // One sign for the line: the first non-zero of its z, y, x components positive.
  for (int j = 2; j >= 0; --j) {
    if (std::abs((*direction)(j)) > 1e-12) {
      if ((*direction)(j) < 0.0) *direction = -*direction;
      break;
    }
  }
  return true;
}

bool tre_linear_maps(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                     const Eigen::Vector3d& target_tool, std::vector<Eigen::Matrix3d>* A,
                     Registration* how) {
  A->clear();
  const int n = static_cast<int>(visible.size());
  if (how != nullptr) *how = Registration::kTooFew;
  if (n < 3) return false;
  Eigen::Vector3d centroid;
  const Eigen::Matrix3d lambda = lambda_of(points_tool, visible, &centroid);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(lambda);
  const Registration registration =
      classify(points_tool, visible, centroid, target_tool - centroid, eigen, lambda.trace());
  if (how != nullptr) *how = registration;
  if (registration != Registration::kFull && registration != Registration::kOnAxis) return false;
  // Lambda^-1 from the eigenpairs already at hand, not from cofactors: its determinant (the cube
  // of the markers' squared spread) leaves the range of doubles long before Lambda does. On a
  // 5-DoF tool's line the unmeasured rotation about the line (eigenvalue 0) is left out: the
  // pseudo-inverse, exact there since the target's lever arm is along the line.
  Eigen::Vector3d inverse = eigen.eigenvalues().cwiseInverse();
  if (registration == Registration::kOnAxis) inverse(0) = 0.0;
  const Eigen::Matrix3d lambda_inv =
      eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
  const Eigen::Matrix3d d_lambda_inv = cross_matrix(target_tool - centroid) * lambda_inv;
  A->reserve(visible.size());
  for (int i : visible) {
    A->push_back(Eigen::Matrix3d::Identity() / n -
                 d_lambda_inv * cross_matrix(points_tool.col(i) - centroid));
  }
  return true;
}

TreQuadratic tre_quadratic(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                           const Eigen::Vector3d& target_tool, const FleModel& fle) {
  TreQuadratic out;
  std::vector<Eigen::Matrix3d> A;
  if (!tre_linear_maps(points_tool, visible, target_tool, &A, &out.registration)) return out;
  const double perp2 = fle.sigma_perp * fle.sigma_perp;
  const double extra = fle.sigma_axial * fle.sigma_axial - perp2;
  for (const Eigen::Matrix3d& a : A) {
    out.c += perp2 * a.squaredNorm();
    out.M += extra * a.transpose() * a;
  }
  out.M = 0.5 * (out.M + out.M.transpose());
  out.registrable = true;
  return out;
}

Eigen::Matrix3d tre_covariance(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                               const Eigen::Vector3d& target_tool, const FleModel& fle,
                               const Eigen::Vector3d& a) {
  std::vector<Eigen::Matrix3d> A;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  if (!tre_linear_maps(points_tool, visible, target_tool, &A)) return cov;
  const double perp2 = fle.sigma_perp * fle.sigma_perp;
  const Eigen::Matrix3d sigma = perp2 * Eigen::Matrix3d::Identity() +
                                (fle.sigma_axial * fle.sigma_axial - perp2) * a * a.transpose();
  for (const Eigen::Matrix3d& m : A) cov += m * sigma * m.transpose();
  return 0.5 * (cov + cov.transpose());
}

void check_on_axis(const Eigen::Matrix3Xd& points_tool, const Eigen::Vector3d& target_tool,
                   long index) {
  // Off a line of every marker only: a 6-DoF tool's targets are kFull, too few markers kTooFew.
  if (registration_of(points_tool, all_markers(points_tool.cols()), target_tool) !=
      Registration::kOffAxis) {
    return;
  }
  Eigen::Vector3d point;
  Eigen::Vector3d axis;
  tool_axis(points_tool, &point, &axis);
  const Eigen::Vector3d nearest = point + axis * axis.dot(target_tool - point);
  throw InvalidArgument(
      "target", target_text(index) + length_text((target_tool - nearest).norm()) +
                    " from the line of the tool's collinear markers: a 5-DoF tool (the rotation "
                    "about its line is not measured, so a target off the line has no bounded "
                    "error); the nearest target on the line is " +
                    internal::round_trip_number(nearest.x()) + "," +
                    internal::round_trip_number(nearest.y()) + "," +
                    internal::round_trip_number(nearest.z()));
}

void check_tre_range(const Eigen::Matrix3Xd& points_tool, const Eigen::Vector3d& target_tool,
                     const FleModel& fle, long index) {
  const auto outside = [](double length) {
    return !(length >= kTreMinLength && length <= kTreMaxLength);
  };
  const std::string range =
      " vantage computes the TRE in double precision for lengths in "
      "[1e-50, 1e50] (docs/math.md §23); give the lengths in other units";
  for (const auto& [field, sigma] :
       {std::pair<const char*, double>{"fle.sigma_perp", fle.sigma_perp},
        {"fle.sigma_axial", fle.sigma_axial}}) {
    if (sigma > kTreMaxLength) throw InvalidArgument(field, "exceeds 1e50:" + range);
  }
  if (outside(std::max(fle.sigma_perp, fle.sigma_axial))) {
    throw InvalidArgument("fle.sigma_perp", "the larger FLE deviation is below 1e-50:" + range);
  }
  if (points_tool.cols() == 0) return;
  const Eigen::Vector3d centroid = points_tool.rowwise().mean();
  const double radius =
      std::sqrt((points_tool.colwise() - centroid).colwise().squaredNorm().mean());
  if (outside(radius)) {
    throw InvalidArgument("points", "the markers' RMS radius about their centroid, " +
                                        length_text(radius) +
                                        ", is outside [1e-50, 1e50]:" + range);
  }
  if (!((target_tool - centroid).norm() <= kTreMaxLength)) {
    throw InvalidArgument(
        "target", target_text(index) + "is more than 1e50 from the markers' centroid:" + range);
  }
  check_on_axis(points_tool, target_tool, index);
  const TreQuadratic q =
      tre_quadratic(points_tool, all_markers(points_tool.cols()), target_tool, fle);
  if (!q.registrable) return;
  const double mean_rms = std::sqrt(q.c + q.M.trace() / 3.0);
  if (outside(mean_rms)) {
    throw InvalidArgument("target", target_text(index) + "the RMS TRE there, " +
                                        length_text(mean_rms) +
                                        " averaged over the lines of sight, is outside [1e-50, "
                                        "1e50]:" +
                                        range);
  }
}

double tre_rms_isotropic(const Eigen::Matrix3Xd& points_tool, const Eigen::Vector3d& target_tool,
                         double fle_rms) {
  const TreQuadratic quadratic = tre_quadratic(points_tool, all_markers(points_tool.cols()),
                                               target_tool, FleModel::isotropic(fle_rms));
  if (quadratic.registration == Registration::kOffAxis) check_on_axis(points_tool, target_tool, -1);
  if (!quadratic.registrable) {
    throw InvalidArgument("points",
                          "fewer than 3 markers or collinear: the tool cannot be registered");
  }
  return std::sqrt(quadratic.c);
}

}  // namespace vantage::tracker
