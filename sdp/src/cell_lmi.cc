// The cell LMI of Eq. (28) on an SDP backend, solved by constraint generation (docs/math.md §13).

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "vantage/analysis/common.h"
#include "vantage/sdp/internal/min_norm_point.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::sdp {
namespace {

// Data vectors in the first LMI solve: the ones nearest to active at the cell's minimum-norm
// direction (at most three are needed to support a cell optimum). A cell of at most this many is
// solved whole in one LMI.
constexpr int kFirstWorkingSet = 32;
// Most violated data vectors added per round, and rounds before the whole cell is solved.
constexpr int kAddPerRound = 32;
constexpr int kMaxRounds = 8;

// The (at most) `count` indices of `candidates` with the smallest values, smallest first, ties
// by index.
std::vector<int> smallest(std::vector<int> candidates, const Eigen::VectorXd& values, int count) {
  const int kept = std::min<int>(count, static_cast<int>(candidates.size()));
  std::partial_sort(
      candidates.begin(), candidates.begin() + kept, candidates.end(),
      [&](int a, int b) { return values(a) < values(b) || (values(a) == values(b) && a < b); });
  candidates.resize(kept);
  return candidates;
}

// The kFirstWorkingSet vectors with the smallest p_i.a0, a0 the direction of the minimum-norm
// point of conv{p_i} (the cell's optimum, docs/math.md §13), or of the sum of the p_i when the
// origin is in the hull. Only a guess: the rounds below add whatever the LMI's answer violates.
std::vector<int> first_working_set(const Eigen::Matrix3Xd& p) {
  const int m = static_cast<int>(p.cols());
  const internal::MinNormPoint hull = internal::min_norm_point(p.data(), m);
  Eigen::Vector3d a0 = hull.contains_origin ? Eigen::Vector3d(p.rowwise().sum()) : hull.x;
  if (!(a0.norm() > 0.0)) a0 = Eigen::Vector3d::UnitZ();
  std::vector<int> all(m);
  std::iota(all.begin(), all.end(), 0);
  std::vector<int> working = smallest(std::move(all), p.transpose() * a0, kFirstWorkingSet);
  std::sort(working.begin(), working.end());
  return working;
}

// The vectors outside `working` that the LMI answer y = [a; t] violates by more than the SDP's
// own tolerance, most violated first, at most kAddPerRound.
std::vector<int> violated(const Eigen::Matrix3Xd& p, const std::vector<char>& in_working,
                          const Eigen::VectorXd& y, double tolerance) {
  const Eigen::VectorXd values = p.transpose() * y.head<3>();
  const double below = y(3) - tolerance;
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(p.cols()); ++i) {
    if (!in_working[i] && values(i) < below) out.push_back(i);
  }
  return smallest(std::move(out), values, kAddPerRound);
}

// Solves the LMI on growing subsets of the cell's vectors until its answer satisfies all of them
// (then it is the whole cell's optimum: a subset's optimum is >= the cell's, and it is feasible
// for the cell), or solves the whole cell after kMaxRounds or when the backend fails on a subset.
SdpResult solve_by_constraint_generation(const Eigen::Matrix3Xd& p, const SdpOptions& options,
                                         CellViewpoint* cell) {
  const int m = static_cast<int>(p.cols());
  std::vector<int> working(m);
  std::iota(working.begin(), working.end(), 0);
  if (m > kFirstWorkingSet) working = first_working_set(p);
  std::vector<char> in_working(m, 0);
  for (int i : working) in_working[i] = 1;
  for (int round = 1;; ++round) {
    Eigen::Matrix3Xd subset(3, working.size());
    for (std::size_t k = 0; k < working.size(); ++k) subset.col(k) = p.col(working[k]);
    SdpResult sdp = solve_lmi(cell_lmi_problem(subset), options);
    ++cell->lmi_solves;
    cell->lmi_vectors = static_cast<int>(working.size());
    if (static_cast<int>(working.size()) == m) return sdp;
    std::vector<int> add;
    if (has_solution(sdp.status)) {
      add = violated(p, in_working, sdp.y, options.tolerance);
      if (add.empty()) return sdp;
    }
    if (add.empty() || round == kMaxRounds) {
      // The backend failed on a subset, or the rounds ran out: the whole cell, once.
      working.resize(m);
      std::iota(working.begin(), working.end(), 0);
      continue;
    }
    for (int i : add) in_working[i] = 1;
    working.insert(working.end(), add.begin(), add.end());
    std::sort(working.begin(), working.end());
  }
}

}  // namespace

LmiProblem cell_lmi_problem(const Eigen::Matrix3Xd& signed_unit_vectors) {
  const Eigen::Matrix3Xd& p = signed_unit_vectors;
  LmiProblem problem(4);
  problem.set_objective(3, -1.0);
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    const int b = problem.add_dense_block(2);
    for (int k = 0; k < 3; ++k) {
      if (p(k, i) == 0.0) continue;
      problem.add_variable_entry(k, b, 0, 0, p(k, i));
      problem.add_variable_entry(k, b, 1, 1, p(k, i));
    }
    problem.add_variable_entry(3, b, 0, 1, 1.0);
  }
  const int ball = problem.add_dense_block(4);
  for (int k = 0; k < 3; ++k) problem.add_variable_entry(k, ball, k, 3, 1.0);
  for (int k = 0; k < 4; ++k) problem.add_constant_entry(ball, k, k, -1.0);
  return problem;
}

CellViewpoint solve_cell_lmi(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& signs,
                             const SdpOptions& options) {
  if (vectors.cols() < 1) throw InvalidArgument("solve_cell_lmi: vectors has no column");
  if (signs.size() != vectors.cols()) {
    throw InvalidArgument("solve_cell_lmi: signs must have one entry per column of vectors");
  }
  for (Eigen::Index i = 0; i < signs.size(); ++i) {
    if (signs(i) != 1.0 && signs(i) != -1.0) {
      throw InvalidArgument("solve_cell_lmi: signs(" + std::to_string(i) + ") is not +1 or -1");
    }
  }
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "solve_cell_lmi: vectors");
  const Eigen::Matrix3Xd p = n * signs.asDiagonal();

  CellViewpoint result;
  result.sdp = solve_by_constraint_generation(p, options, &result);
  if (!has_solution(result.sdp.status)) {
    result.status = CellViewpoint::Status::kSolverFailed;
    result.message =
        std::string("cell LMI: ") + to_string(result.sdp.status) + ": " + result.sdp.message;
    return result;
  }
  // The SDP's t is accurate to its tolerance only; report what the normalised viewpoint attains
  // in the cell, min_i s_i a.n_i over every vector, so that t never exceeds a value some
  // viewpoint achieves.
  const Eigen::Vector3d a = result.sdp.y.head<3>();
  const double t_sdp = result.sdp.y(3);
  if (t_sdp <= CellViewpoint::kEmptyCellT || !(a.norm() > 0.0)) {
    result.t = t_sdp;
    result.pbar_at = pbar_from_t(std::max(0.0, t_sdp));
    result.status = CellViewpoint::Status::kEmptyCell;
    result.message = "the sign cell is empty: 0 is in conv{s_i n_i}";
    return result;
  }
  const Eigen::Vector3d unit_a = a.normalized();
  result.t = (p.transpose() * unit_a).minCoeff();
  // Inside the cell p-bar(a) = sqrt(1 - t^2) = max_i |a x n_i|; the cross products keep their
  // digits where t is within rounding of 1 (sqrt(1 - t^2) gave 0 for a near-degenerate layout
  // whose p-bar is 5e-10), as the global pbar_min is computed.
  result.pbar_at = result.t > 0.0 ? pbar_at(n, unit_a) : 1.0;
  result.viewpoint = upper_hemisphere(unit_a);
  result.status = CellViewpoint::Status::kOk;
  return result;
}

Eigen::VectorXd paper_signs(const Eigen::Matrix3Xd& vectors) {
  const Eigen::Matrix3Xd unit = normalized_columns(vectors, "vectors");
  const internal::MinNormPoint hull =
      internal::min_norm_point(unit.data(), static_cast<int>(unit.cols()));
  if (!hull.contains_origin) return Eigen::VectorXd::Ones(unit.cols());
  return upper_hemisphere_signs(unit);
}

CellViewpoint paper_worst_viewpoint(const Eigen::Matrix3Xd& vectors, const SdpOptions& options) {
  return solve_cell_lmi(vectors, paper_signs(vectors), options);
}

}  // namespace vantage::sdp
