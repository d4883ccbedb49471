#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <numeric>
#include <sstream>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {
namespace {

// Sample evaluations are done in blocks of this many directions (bounded temporary memory).
constexpr int kSampleBlock = 512;
// MMA stopping tolerance and budget: far below the 1e-6 agreement threshold.
constexpr double kPolishXtol = 1e-13;
constexpr int kPolishMaxEval = 400;
// Starting point scale: start strictly feasible (inside the ball, below every constraint).
constexpr double kPolishShrink = 0.99;

struct CellData {
  Eigen::Matrix3Xd p;  // s_i n_i
};

double objective(unsigned, const double* x, double* grad, void*) {
  if (grad != nullptr) {
    grad[0] = grad[1] = grad[2] = 0.0;
    grad[3] = 1.0;
  }
  return x[3];
}

// t - s_i n_i.a <= 0 for every i.
void cell_constraints(unsigned m, double* result, unsigned, const double* x, double* grad,
                      void* data) {
  const Eigen::Matrix3Xd& p = static_cast<CellData*>(data)->p;
  for (unsigned i = 0; i < m; ++i) {
    result[i] = x[3] - (p(0, i) * x[0] + p(1, i) * x[1] + p(2, i) * x[2]);
    if (grad != nullptr) {
      grad[4 * i + 0] = -p(0, i);
      grad[4 * i + 1] = -p(1, i);
      grad[4 * i + 2] = -p(2, i);
      grad[4 * i + 3] = 1.0;
    }
  }
}

// ||a||^2 - 1 <= 0.
double ball_constraint(unsigned, const double* x, double* grad, void*) {
  if (grad != nullptr) {
    grad[0] = 2.0 * x[0];
    grad[1] = 2.0 * x[1];
    grad[2] = 2.0 * x[2];
    grad[3] = 0.0;
  }
  return x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 1.0;
}

Eigen::Vector3d polish(const Eigen::Matrix3Xd& n, const Eigen::Vector3d& start) {
  const int m = static_cast<int>(n.cols());
  CellData cell;
  cell.p.resize(3, m);
  for (int i = 0; i < m; ++i) cell.p.col(i) = (n.col(i).dot(start) >= 0.0 ? 1.0 : -1.0) * n.col(i);
  nlopt::opt opt(nlopt::LD_MMA, 4);
  opt.set_lower_bounds({-1.0, -1.0, -1.0, -1.0});
  opt.set_upper_bounds({1.0, 1.0, 1.0, 1.0});
  opt.set_max_objective(objective, nullptr);
  opt.add_inequality_mconstraint(cell_constraints, &cell, std::vector<double>(m, 0.0));
  opt.add_inequality_constraint(ball_constraint, nullptr, 0.0);
  opt.set_xtol_rel(kPolishXtol);
  opt.set_maxeval(kPolishMaxEval);
  // Start strictly inside the ball with t below every constraint (strictly feasible).
  const Eigen::Vector3d a0 = kPolishShrink * start;
  std::vector<double> x = {a0.x(), a0.y(), a0.z(), (cell.p.transpose() * a0).minCoeff() - 1e-3};
  double value = 0.0;
  try {
    opt.optimize(x, value);
  } catch (const std::exception&) {
    // Round-off or other early stops leave the last iterate in x; it is evaluated below.
  }
  const Eigen::Vector3d a(x[0], x[1], x[2]);
  return a.norm() > 0.0 ? Eigen::Vector3d(a.normalized()) : start;
}

}  // namespace

bool CrossCheckOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (samples < 0) return fail("CrossCheckOptions::samples must be >= 0 (0 = automatic)");
  if (polish_starts < 1) return fail("CrossCheckOptions::polish_starts must be >= 1");
  if (!(agreement > 0.0)) return fail("CrossCheckOptions::agreement must be > 0");
  return true;
}

CrossCheck crosscheck_worst_viewpoint(const Eigen::Matrix3Xd& vectors, double t_reference,
                                      const CrossCheckOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) {
    throw InvalidArgument("crosscheck_worst_viewpoint: options: " + why);
  }
  if (vectors.cols() < 2) {
    throw InvalidArgument("crosscheck_worst_viewpoint: vectors must have at least 2 columns");
  }
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "crosscheck_worst_viewpoint: vectors");
  const long m = n.cols();
  const int samples = options.samples > 0
                          ? options.samples
                          : static_cast<int>(std::clamp<long>(50 * m * m, 20000, 400000));

  // Fibonacci points on the upper hemisphere.
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  Eigen::Matrix3Xd directions(3, samples);
  for (int k = 0; k < samples; ++k) {
    const double z = 1.0 - (k + 0.5) / samples;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * k;
    directions.col(k) << r * std::cos(phi), r * std::sin(phi), z;
  }
  Eigen::VectorXd values(samples);
  const Eigen::MatrixXd nt = n.transpose();
  for (int start = 0; start < samples; start += kSampleBlock) {
    const int count = std::min(kSampleBlock, samples - start);
    const Eigen::MatrixXd dots = nt * directions.middleCols(start, count);
    values.segment(start, count) = dots.cwiseAbs().colwise().minCoeff().transpose();
  }
  std::vector<int> order(samples);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) > values(b); });

  CrossCheck result;
  result.method = "nlopt_multistart_mma";
  result.t = -1.0;
  std::vector<Eigen::VectorXd> cells;  // sign patterns already polished
  for (int k = 0; k < samples && static_cast<int>(cells.size()) < options.polish_starts; ++k) {
    const Eigen::Vector3d start = directions.col(order[k]);
    Eigen::VectorXd signs = (nt * start).array().sign().matrix();
    bool seen = false;
    for (const Eigen::VectorXd& s : cells) seen = seen || s == signs;
    if (seen) continue;
    cells.push_back(signs);
    const Eigen::Vector3d a = polish(n, start);
    const double value = min_abs_projection(n, a);
    if (value > result.t) {
      result.t = value;
      result.viewpoint = upper_hemisphere(a);
    }
    const double sample_value = values(order[k]);
    if (sample_value > result.t) {
      result.t = sample_value;
      result.viewpoint = start;
    }
  }
  result.difference = result.t - t_reference;
  result.agrees = std::abs(result.difference) <= options.agreement;
  if (!result.agrees) {
    std::ostringstream out;
    out << "CROSS-CHECK DISAGREES: NLopt t = " << result.t << " vs reference t = " << t_reference
        << " (difference " << result.difference << ")";
    result.message = out.str();
  }
  return result;
}

}  // namespace vantage::sdp
