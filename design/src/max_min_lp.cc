#include "max_min_lp.h"

#include <Eigen/Dense>
#include <algorithm>
#include <string>
#include <vector>

#include "vantage/analysis/common.h"

namespace vantage::design::internal {

namespace {

// The z_i are scaled to max |z_ij| = 1, so g_i = z_i - c has entries in [-2, 2] and the step
// direction d has unit length: a constraint whose slope g_i.d is below this is parallel to the
// step up to rounding and does not block it.
constexpr double kSlopeTolerance = 1e-13;
// The projected descent direction counts as zero below this fraction of |c| (rounding of a
// projection onto at most three planes).
constexpr double kDirectionTolerance = 1e-13;
// A multiplier below -kMultiplierTolerance * |c| leaves the active set.
constexpr double kMultiplierTolerance = 1e-12;
// Active-set steps allowed: a generous multiple of the three dimensions plus a term in n; every
// non-degenerate step strictly lowers c.u and Bland's rule (smallest index) breaks ties.
constexpr int kBaseIterations = 1000;

// CSDP path: singular values of [Z / scale; 1^T] below this fraction of the largest count as
// zero, and Z w = 0, 1^T w = n is inconsistent when its least-squares residual exceeds
// kConsistencyTolerance * n.
constexpr double kRankTolerance = 1e-10;
constexpr double kConsistencyTolerance = 1e-9;

// Orthonormal basis (columns) of span{g_a : a in active}.
Eigen::Matrix3Xd orthonormal_basis(const Eigen::Matrix3Xd& g, const std::vector<int>& active) {
  Eigen::Matrix3Xd q(3, active.size());
  int k = 0;
  for (int a : active) {
    Eigen::Vector3d v = g.col(a);
    for (int j = 0; j < k; ++j) v -= q.col(j).dot(v) * q.col(j);
    for (int j = 0; j < k; ++j) v -= q.col(j).dot(v) * q.col(j);
    const double length = v.norm();
    if (length > 0.0) q.col(k++) = v / length;
  }
  return q.leftCols(k);
}

// Least-squares multipliers lambda of c + sum_a lambda_a g_a = 0.
Eigen::VectorXd multipliers(const Eigen::Matrix3Xd& g, const std::vector<int>& active,
                            const Eigen::Vector3d& c) {
  Eigen::Matrix3Xd ga(3, active.size());
  for (std::size_t k = 0; k < active.size(); ++k) ga.col(k) = g.col(active[k]);
  return ga.colPivHouseholderQr().solve(-c);
}

}  // namespace

MaxMinSolution solve_max_min_dual(const Eigen::Matrix3Xd& z) {
  MaxMinSolution out;
  const Eigen::Index n = z.cols();
  const double scale = z.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) {
    out.kind = MaxMinSolution::Kind::kSolved;
    out.w = Eigen::VectorXd::Ones(n);
    out.s = 1.0;
    out.slack = Eigen::VectorXd::Ones(n);
    return out;
  }
  const Eigen::Vector3d c = (z / scale).rowwise().mean();
  const Eigen::Matrix3Xd g = (z / scale).colwise() - c;
  const double c_norm = c.norm();
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  std::vector<int> active;
  Eigen::VectorXd lambda;
  const long max_iterations = kBaseIterations + 4 * static_cast<long>(n);
  out.lp_solves = 1;
  for (long iteration = 0;; ++iteration) {
    out.iterations = static_cast<int>(iteration);
    if (iteration >= max_iterations) {
      out.sdp_status = sdp::SdpStatus::kMaxIterations;  // reported as the LP's status
      return out;
    }
    const Eigen::Matrix3Xd q = orthonormal_basis(g, active);
    Eigen::Vector3d d = -c - q * (q.transpose() * -c);
    const double d_norm = d.norm();
    if (d_norm <= kDirectionTolerance * c_norm) {
      if (active.empty()) break;
      lambda = multipliers(g, active, c);
      Eigen::Index leaving = -1;
      for (Eigen::Index k = 0; k < lambda.size(); ++k) {
        if (lambda(k) < -kMultiplierTolerance * c_norm &&
            (leaving < 0 || active[k] < active[leaving])) {
          leaving = k;
        }
      }
      if (leaving < 0) break;
      active.erase(active.begin() + leaving);
      continue;
    }
    d /= d_norm;
    Eigen::Index entering = -1;
    double step = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double slope = g.col(i).dot(d);
      if (!(slope > kSlopeTolerance)) continue;
      if (std::find(active.begin(), active.end(), i) != active.end()) continue;
      const double t = std::max(0.0, 1.0 - g.col(i).dot(u)) / slope;
      if (entering < 0 || t < step) {
        entering = i;
        step = t;
      }
    }
    if (entering < 0) {
      out.kind = MaxMinSolution::Kind::kAffineInfeasible;
      return out;
    }
    u += step * d;
    active.push_back(static_cast<int>(entering));
  }
  out.kind = MaxMinSolution::Kind::kSolved;
  if (active.empty()) lambda.resize(0);
  const double alpha_sum = lambda.cwiseMax(0.0).sum();
  out.s = 1.0 - alpha_sum;
  out.w = Eigen::VectorXd::Constant(n, out.s);
  for (std::size_t k = 0; k < active.size(); ++k) {
    out.w(active[k]) += static_cast<double>(n) * std::max(0.0, lambda(k));
  }
  out.slack = (1.0 - (g.transpose() * u).array()).matrix();
  return out;
}

MaxMinSolution solve_max_min_csdp(const Eigen::Matrix3Xd& z, const sdp::SdpOptions& options) {
  const Eigen::Index n = z.cols();
  if (n > kMaxCsdpEntries) {
    throw InvalidArgument("z: the CSDP weights LP takes at most " +
                          std::to_string(kMaxCsdpEntries) + " columns, got " + std::to_string(n));
  }
  MaxMinSolution out;
  const double scale = z.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) {
    out.kind = MaxMinSolution::Kind::kSolved;
    out.w = Eigen::VectorXd::Ones(n);
    out.s = 1.0;
    return out;
  }
  // Eliminate the equalities: w = w0 + B y with B a basis of the null space of [Z / scale; 1^T].
  Eigen::MatrixXd a(4, n);
  a.topRows<3>() = z / scale;
  a.row(3).setOnes();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(4);
  b(3) = static_cast<double>(n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  int rank = 0;
  for (Eigen::Index k = 0; k < sigma.size(); ++k) {
    if (sigma(k) > kRankTolerance * sigma(0)) ++rank;
  }
  Eigen::VectorXd w0 = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < rank; ++k) {
    w0 += svd.matrixV().col(k) * (svd.matrixU().col(k).dot(b) / sigma(k));
  }
  if ((a * w0 - b).norm() > kConsistencyTolerance * static_cast<double>(n)) {
    out.kind = MaxMinSolution::Kind::kAffineInfeasible;
    return out;
  }
  const Eigen::Index d = n - rank;
  if (d == 0) {
    out.kind = MaxMinSolution::Kind::kSolved;
    out.w = w0;
    out.s = w0.minCoeff();
    return out;
  }
  const Eigen::MatrixXd basis = svd.matrixV().rightCols(d);
  // y = [u; s]; block: w0_i + sum_j B_ij u_j - s >= 0; minimise -s.
  sdp::LmiProblem lp(static_cast<int>(d) + 1);
  const int block = lp.add_diagonal_block(static_cast<int>(n));
  lp.set_objective(static_cast<int>(d), -1.0);
  for (int i = 0; i < static_cast<int>(n); ++i) {
    for (int j = 0; j < static_cast<int>(d); ++j) {
      if (basis(i, j) != 0.0) lp.add_variable_entry(j, block, i, i, basis(i, j));
    }
    lp.add_variable_entry(static_cast<int>(d), block, i, i, -1.0);
    if (w0(i) != 0.0) lp.add_constant_entry(block, i, i, -w0(i));
  }
  const sdp::SdpResult r = sdp::solve_lmi(lp, options);
  out.lp_solves = 1;
  out.sdp_status = r.status;
  if (!sdp::has_solution(r.status)) return out;
  out.kind = MaxMinSolution::Kind::kSolved;
  out.w = w0 + basis * r.y.head(d);
  out.s = out.w.minCoeff();
  return out;
}

}  // namespace vantage::design::internal
