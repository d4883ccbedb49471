#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <vector>

#include "vantage/analysis/build_options.h"
#include "vantage/analysis/common.h"
#include "vantage/sdp/worst_viewpoint.h"

#if VANTAGE_WITH_NLOPT
#include <nlopt.hpp>
#endif

namespace vantage::sdp {

#if VANTAGE_WITH_NLOPT
namespace {

// Automatic sample count (see automatic_samples()): bounds, samples per optimal inradius, and
// the smallest inradius considered (t of 1e-6 would ask for 1e13 samples).
constexpr double kMinSamples = 20000;
constexpr double kMaxSamples = 400000;
constexpr double kSpacingsPerRadius = 2.0;
constexpr double kMinRadius = 1e-6;
// Sample scans test their running minimum every this many vectors; samples ranked first, and
// the factor by which the ranking grows when their distinct cells run out.
constexpr int kScanBlock = 64;
constexpr int kFirstRanked = 256;
constexpr int kRankMore = 4;
// Constraints the polish starts with: the ones nearest to active at the start. A cell optimum
// has at most three active constraints; the rest are added when the result violates them.
constexpr int kWorkingSet = 16;
// Most violated constraints added per round, and rounds per polish.
constexpr int kPolishAddPerRound = 8;
constexpr int kPolishMaxRounds = 12;
// A constraint outside the working set counts as violated when it is this far below the
// working set's minimum (rounding of unit dot products).
constexpr double kViolation = 1e-15;
// COBYLA stopping tolerance in the shifted coordinates (absolute; d is O(1) at most), far below
// the 1e-6 agreement threshold, and its budget.
constexpr double kPolishXtol = 1e-15;
constexpr int kPolishMaxEval = 400;

// The cell problem of a working set as the quadratic programme min ||a||^2 s.t. p_i.a >= t0
// (its solution a* gives the cell optimum t0 / ||a*|| at a* / ||a*||: Eq. 31 for one sign cell,
// scaled), in coordinates shifted to the start a0 (unit): a = a0 + d, so the objective is
// 2 a0.d + d.d and constraint i is slack_i + p_i.d >= 0 with slack_i = p_i.a0 - t0 >= 0. Nothing
// close to 1 is subtracted, so a narrow cone (t near 1) keeps its digits.
struct ShiftedCell {
  Eigen::Vector3d a0;
  Eigen::Matrix3Xd p;     // s_i n_i of the working set
  Eigen::VectorXd slack;  // p_i.a0 - t0
};

double objective(unsigned, const double* x, double* grad, void* data) {
  const Eigen::Vector3d& a0 = static_cast<ShiftedCell*>(data)->a0;
  const Eigen::Vector3d d(x[0], x[1], x[2]);
  if (grad != nullptr) {
    for (int k = 0; k < 3; ++k) grad[k] = 2.0 * (a0(k) + d(k));
  }
  return 2.0 * a0.dot(d) + d.squaredNorm();
}

// -(slack_i + p_i.d) <= 0 for every i of the working set.
void cell_constraints(unsigned k, double* result, unsigned, const double* x, double* grad,
                      void* data) {
  const ShiftedCell& cell = *static_cast<ShiftedCell*>(data);
  for (unsigned i = 0; i < k; ++i) {
    result[i] = -cell.slack(i) - (cell.p(0, i) * x[0] + cell.p(1, i) * x[1] + cell.p(2, i) * x[2]);
    if (grad != nullptr) {
      for (int j = 0; j < 3; ++j) grad[3 * i + j] = -cell.p(j, i);
    }
  }
}

// Optimum direction of the working set's cell from a0 (NLopt COBYLA: its linear models are exact
// for these constraints; SLSQP and MMA stalled or crept on them).
Eigen::Vector3d polish_working_set(const Eigen::Matrix3Xd& p, const std::vector<int>& working,
                                   const Eigen::Vector3d& a0) {
  const int k = static_cast<int>(working.size());
  ShiftedCell cell;
  cell.a0 = a0;
  cell.p.resize(3, k);
  for (int j = 0; j < k; ++j) cell.p.col(j) = p.col(working[j]);
  const Eigen::VectorXd values = cell.p.transpose() * a0;
  cell.slack = values.array() - values.minCoeff();
  nlopt::opt opt(nlopt::LN_COBYLA, 3);
  opt.set_lower_bounds({-2.0, -2.0, -2.0});
  opt.set_upper_bounds({2.0, 2.0, 2.0});
  opt.set_min_objective(objective, &cell);
  opt.add_inequality_mconstraint(cell_constraints, &cell, std::vector<double>(k, 0.0));
  opt.set_xtol_abs(kPolishXtol);
  opt.set_maxeval(kPolishMaxEval);
  std::vector<double> x = {0.0, 0.0, 0.0};  // feasible: the start itself
  double value = 0.0;
  try {
    opt.optimize(x, value);
  } catch (const std::exception&) {
    // Round-off or other early stops leave the last iterate in x; it is evaluated by the caller.
  }
  const Eigen::Vector3d a = a0 + Eigen::Vector3d(x[0], x[1], x[2]);
  return a.norm() > 0.0 && a.allFinite() ? Eigen::Vector3d(a.normalized()) : a0;
}

// The optimum of the sign cell of `start` (signs s_i = sign(n_i.start)) by working-set rounds.
Eigen::Vector3d polish(const Eigen::Matrix3Xd& n, const Eigen::Vector3d& start) {
  const int m = static_cast<int>(n.cols());
  Eigen::Matrix3Xd p(3, m);
  for (int i = 0; i < m; ++i) p.col(i) = (n.col(i).dot(start) >= 0.0 ? 1.0 : -1.0) * n.col(i);
  const Eigen::VectorXd at_start = p.transpose() * start;
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  const int first = std::min(m, kWorkingSet);
  std::partial_sort(order.begin(), order.begin() + first, order.end(),
                    [&](int a, int b) { return at_start(a) < at_start(b); });
  std::vector<int> working(order.begin(), order.begin() + first);
  std::vector<char> in_working(m, 0);
  for (int i : working) in_working[i] = 1;

  Eigen::Vector3d a = start;
  for (int round = 0; round < kPolishMaxRounds; ++round) {
    a = polish_working_set(p, working, start);
    const Eigen::VectorXd values = p.transpose() * a;
    double working_min = 1.0;
    for (int i : working) working_min = std::min(working_min, values(i));
    std::vector<int> violated;
    for (int i = 0; i < m; ++i) {
      if (!in_working[i] && values(i) < working_min - kViolation) violated.push_back(i);
    }
    if (violated.empty()) break;
    const int add = std::min<int>(kPolishAddPerRound, static_cast<int>(violated.size()));
    std::partial_sort(violated.begin(), violated.begin() + add, violated.end(),
                      [&](int x, int y) { return values(x) < values(y); });
    for (int j = 0; j < add; ++j) {
      working.push_back(violated[j]);
      in_working[violated[j]] = 1;
    }
  }
  return a;
}

// Enough samples for a spacing of half the reference's optimal inradius asin(t_reference), at
// least kMinSamples, and at most max_sample_products / m (and kMaxSamples).
int automatic_samples(long m, double t_reference, const CrossCheckOptions& options) {
  const double radius = std::asin(std::clamp(t_reference, kMinRadius, 1.0));
  const double wanted = kSpacingsPerRadius * kSpacingsPerRadius * 2.0 * kPi / (radius * radius);
  const double by_work = options.max_sample_products / static_cast<double>(m);
  const double count =
      std::min({std::ceil(std::max(wanted, kMinSamples)), std::floor(by_work), kMaxSamples});
  return static_cast<int>(std::max(1.0, count));
}

// Fibonacci points on the upper hemisphere.
Eigen::Matrix3Xd fibonacci_hemisphere(int samples) {
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  Eigen::Matrix3Xd directions(3, samples);
  for (int k = 0; k < samples; ++k) {
    const double z = 1.0 - (k + 0.5) / samples;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * k;
    directions.col(k) << r * std::cos(phi), r * std::sin(phi), z;
  }
  return directions;
}

struct RankedSample {
  int index;     // column of the directions
  double value;  // min_i |a.n_i|
};

// Ranking of samples: larger value first, ties by lower index (deterministic).
bool ranks_before(const RankedSample& a, const RankedSample& b) {
  return a.value > b.value || (a.value == b.value && a.index < b.index);
}

// The `count` samples (columns of `directions`) with the largest min_i |a.n_i|, best first, with
// exact values: the first `count` of a full evaluation sorted by ranks_before. A sample's scan
// over the n_i stops once its running minimum cannot beat the count-th best so far, so most
// samples cost a block or two of the m dot products instead of all of them.
std::vector<RankedSample> best_samples(const Eigen::Matrix3Xd& n,
                                       const Eigen::Matrix3Xd& directions, int count) {
  const Eigen::ArrayXd x = n.row(0).transpose(), y = n.row(1).transpose(), z = n.row(2).transpose();
  const Eigen::Index m = n.cols();
  std::vector<RankedSample> kept;  // a heap under ranks_before: front() is the worst kept
  kept.reserve(count + 1);
  for (int k = 0; k < static_cast<int>(directions.cols()); ++k) {
    const double floor = static_cast<int>(kept.size()) == count
                             ? kept.front().value
                             : -std::numeric_limits<double>::infinity();
    const Eigen::Vector3d a = directions.col(k);
    double running = std::numeric_limits<double>::infinity();
    // A later sample equal to the worst kept ranks after it: stop at equality too.
    for (Eigen::Index s = 0; s < m && running > floor; s += kScanBlock) {
      const Eigen::Index e = std::min<Eigen::Index>(kScanBlock, m - s);
      running = std::min(
          running, (x.segment(s, e) * a.x() + y.segment(s, e) * a.y() + z.segment(s, e) * a.z())
                       .abs()
                       .minCoeff());
    }
    if (running <= floor) continue;
    kept.push_back({k, running});
    std::push_heap(kept.begin(), kept.end(), ranks_before);
    if (static_cast<int>(kept.size()) > count) {
      std::pop_heap(kept.begin(), kept.end(), ranks_before);
      kept.pop_back();
    }
  }
  std::sort_heap(kept.begin(), kept.end(), ranks_before);
  return kept;
}

}  // namespace
#endif

bool CrossCheckOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (samples < 0) return fail("CrossCheckOptions::samples must be >= 0 (0 = automatic)");
  if (polish_starts < 1) return fail("CrossCheckOptions::polish_starts must be >= 1");
  if (!(agreement > 0.0)) return fail("CrossCheckOptions::agreement must be > 0");
  if (!(max_sample_products >= 1e5)) {
    return fail("CrossCheckOptions::max_sample_products must be >= 1e5");
  }
  return true;
}

namespace {

// Throws InvalidArgument on invalid options, fewer than 2 vectors or a zero or non-finite
// reference viewpoint; returns the vectors normalised.
Eigen::Matrix3Xd checked_unit_vectors(const Eigen::Matrix3Xd& vectors,
                                      const CrossCheckOptions& options,
                                      const std::vector<Eigen::Vector3d>& reference_viewpoints) {
  std::string why;
  if (!options.is_valid(&why)) {
    throw InvalidArgument("crosscheck_worst_viewpoint: options: " + why);
  }
  if (vectors.cols() < 2) {
    throw InvalidArgument("crosscheck_worst_viewpoint: vectors must have at least 2 columns");
  }
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "crosscheck_worst_viewpoint: vectors");
  for (std::size_t k = 0; k < reference_viewpoints.size(); ++k) {
    const Eigen::Vector3d& a = reference_viewpoints[k];
    if (!a.allFinite() || !(a.norm() > 0.0)) {
      throw InvalidArgument("crosscheck_worst_viewpoint: reference_viewpoints[" +
                            std::to_string(k) + "] is zero or not finite");
    }
  }
  return n;
}

}  // namespace

CrossCheck crosscheck_worst_viewpoint(const Eigen::Matrix3Xd& vectors,
                                      [[maybe_unused]] double t_reference,
                                      const CrossCheckOptions& options,
                                      const std::vector<Eigen::Vector3d>& reference_viewpoints) {
  const Eigen::Matrix3Xd n = checked_unit_vectors(vectors, options, reference_viewpoints);
#if !VANTAGE_WITH_NLOPT
  CrossCheck skipped;
  skipped.skipped = kWithoutNlopt;
  skipped.method = "skipped";
  skipped.message = std::string("cross-check skipped: ") + kWithoutNlopt;
  return skipped;
#else
  const long m = n.cols();
  const int samples =
      options.samples > 0 ? options.samples : automatic_samples(m, t_reference, options);

  const Eigen::Matrix3Xd directions = fibonacci_hemisphere(samples);
  const Eigen::MatrixXd nt = n.transpose();
  int ranked = std::min(samples, kFirstRanked);
  std::vector<RankedSample> best = best_samples(n, directions, ranked);

  CrossCheck result;
  result.method = "nlopt_multistart_cobyla";
  result.t = -1.0;
  result.samples = samples;
  result.sample_spacing = std::sqrt(2.0 * kPi / samples);
  result.samples_cover_cells = result.sample_spacing < std::asin(std::clamp(t_reference, 0.0, 1.0));
  auto consider = [&](const Eigen::Vector3d& a, double value) {
    if (value > result.t) {
      result.t = value;
      result.viewpoint = upper_hemisphere(a);
    }
  };
  auto polish_and_consider = [&](const Eigen::Vector3d& start) {
    const Eigen::Vector3d a = polish(n, start);
    consider(a, min_abs_projection(n, a));
    ++result.polished;
  };
  std::vector<Eigen::VectorXd> cells;  // sign patterns already polished
  for (int k = 0; k < samples && static_cast<int>(cells.size()) < options.polish_starts; ++k) {
    if (k == static_cast<int>(best.size())) {
      // The ranked samples ran out before polish_starts distinct cells: rank more (the same
      // ranking, longer).
      ranked = std::min(samples, kRankMore * ranked);
      best = best_samples(n, directions, ranked);
    }
    const Eigen::Vector3d start = directions.col(best[k].index);
    Eigen::VectorXd signs = (nt * start).array().sign().matrix();
    bool seen = false;
    for (const Eigen::VectorXd& s : cells) seen = seen || s == signs;
    if (seen) continue;
    cells.push_back(signs);
    polish_and_consider(start);
    consider(start, best[k].value);
  }
  for (const Eigen::Vector3d& a : reference_viewpoints) polish_and_consider(a.normalized());
  result.difference = result.t - t_reference;
  result.agrees = std::abs(result.difference) <= options.agreement;
  if (!result.agrees) {
    std::ostringstream out;
    out << "CROSS-CHECK DISAGREES: NLopt t = " << result.t << " vs reference t = " << t_reference
        << " (difference " << result.difference << ")";
    result.message = out.str();
  }
  return result;
#endif
}

}  // namespace vantage::sdp
