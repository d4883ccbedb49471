#include "vantage/tracker/target_registration.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "vantage/analysis/common.h"

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

bool tre_linear_maps(const Eigen::Matrix3Xd& points_tool, const std::vector<int>& visible,
                     const Eigen::Vector3d& target_tool, std::vector<Eigen::Matrix3d>* A) {
  A->clear();
  const int n = static_cast<int>(visible.size());
  if (n < 3) return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int i : visible) centroid += points_tool.col(i);
  centroid /= n;
  Eigen::Matrix3d lambda = Eigen::Matrix3d::Zero();
  for (int i : visible) {
    const Eigen::Vector3d q = points_tool.col(i) - centroid;
    lambda += q.squaredNorm() * Eigen::Matrix3d::Identity() - q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(lambda);
  if (!(eigen.eigenvalues()(0) > kCollinearFraction * lambda.trace())) return false;
  // Lambda^-1 from the eigenpairs already at hand, not from cofactors: its determinant (the cube
  // of the markers' squared spread) leaves the range of doubles long before Lambda does.
  const Eigen::Matrix3d lambda_inv = eigen.eigenvectors() *
                                     eigen.eigenvalues().cwiseInverse().asDiagonal() *
                                     eigen.eigenvectors().transpose();
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
  if (!tre_linear_maps(points_tool, visible, target_tool, &A)) return out;
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
  std::vector<int> all(static_cast<std::size_t>(points_tool.cols()));
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const TreQuadratic q = tre_quadratic(points_tool, all, target_tool, fle);
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
  std::vector<int> all(static_cast<std::size_t>(points_tool.cols()));
  for (int i = 0; i < static_cast<int>(all.size()); ++i) all[static_cast<std::size_t>(i)] = i;
  const TreQuadratic quadratic =
      tre_quadratic(points_tool, all, target_tool, FleModel::isotropic(fle_rms));
  if (!quadratic.registrable) {
    throw InvalidArgument("points",
                          "fewer than 3 markers or collinear: the tool cannot be registered");
  }
  return std::sqrt(quadratic.c);
}

}  // namespace vantage::tracker
