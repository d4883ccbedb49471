#include "vantage/design/weights.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "max_min_lp.h"
#include "vantage/analysis/common.h"

namespace vantage::design {

namespace {

// In a boundary solution, a z_i whose dual slack exceeds this multiple of zero_tolerance lies
// strictly beyond the supporting plane through the origin: its weight is forced to 0. (CSDP
// path: a weight below this multiple; the interior-point optimum lies in the relative interior
// of the optimal face, so the free weights stay well away from 0.)
constexpr double kForcedZeroFactor = 1e3;
// Up to this many entries every symmetric partner is tried; beyond it only the partners of the
// kPartnerCandidates entries with the largest dual slack (farthest beyond the plane that
// separates the z_i from the origin), so that the search stays O(n).
constexpr int kPartnerSearchAll = 64;
constexpr int kPartnerCandidates = 32;

using internal::MaxMinSolution;

MaxMinSolution solve_max_min(const Eigen::Matrix3Xd& z, const WeightsOptions& options) {
  if (options.solver == WeightsOptions::Solver::kCsdp) {
    return internal::solve_max_min_csdp(z, options.sdp);
  }
  return internal::solve_max_min_dual(z);
}

std::string format_vector(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

struct Classified {
  Weights::Status status = Weights::Status::kSolverFailed;
  Eigen::VectorXd weights;
  double s = 0.0;
  Eigen::VectorXd slack;  // dual slacks (active-set solver), empty otherwise
  std::vector<int> zero_forced;
  sdp::SdpStatus sdp_status = sdp::SdpStatus::kOptimal;
  int lp_solves = 0;
};

// Solves and classifies; a boundary solution is re-solved on its support so that the free
// weights are max-min and the forced ones exactly 0.
Classified classify(const Eigen::Matrix3Xd& z, const WeightsOptions& options) {
  Classified out;
  const MaxMinSolution m = solve_max_min(z, options);
  out.lp_solves = m.lp_solves;
  out.sdp_status = m.sdp_status;
  out.slack = m.slack;
  if (m.kind == MaxMinSolution::Kind::kSolverFailed) return out;
  if (m.kind == MaxMinSolution::Kind::kAffineInfeasible) {
    out.status = Weights::Status::kInfeasible;
    out.s = -1.0;
    return out;
  }
  out.s = m.s;
  if (m.s > options.zero_tolerance) {
    out.status = Weights::Status::kPositive;
    out.weights = m.w;
    return out;
  }
  if (m.s < -options.zero_tolerance) {
    out.status = Weights::Status::kInfeasible;
    return out;
  }
  out.status = Weights::Status::kBoundary;
  const int n = static_cast<int>(z.cols());
  std::vector<int> support;
  const double forced = kForcedZeroFactor * options.zero_tolerance;
  for (int i = 0; i < n; ++i) {
    if (m.slack.size() > 0 ? m.slack(i) > forced : m.w(i) <= forced) {
      out.zero_forced.push_back(i);
    } else {
      support.push_back(i);
    }
  }
  out.weights = m.w.cwiseMax(0.0);
  if (support.empty() || out.zero_forced.empty()) return out;
  Eigen::Matrix3Xd sub(3, support.size());
  for (size_t k = 0; k < support.size(); ++k) sub.col(k) = z.col(support[k]);
  const Classified inner = classify(sub, options);
  out.lp_solves += inner.lp_solves;
  if (inner.status != Weights::Status::kPositive && inner.status != Weights::Status::kBoundary) {
    return out;
  }
  out.weights.setZero();
  const double rescale = static_cast<double>(n) / static_cast<double>(support.size());
  for (size_t k = 0; k < support.size(); ++k) {
    out.weights(support[k]) = inner.weights(k) * rescale;
  }
  for (int i : inner.zero_forced) out.zero_forced.push_back(support[i]);
  std::sort(out.zero_forced.begin(), out.zero_forced.end());
  return out;
}

// The entries whose symmetric partners are tried: all of them for small layouts (or without
// slacks), else those with the largest dual slack, in index order.
std::vector<int> partner_candidates(const Eigen::VectorXd& slack, int n) {
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  if (n <= kPartnerSearchAll || slack.size() != n) return order;
  std::partial_sort(
      order.begin(), order.begin() + kPartnerCandidates, order.end(),
      [&](int a, int b) { return slack(a) > slack(b) || (slack(a) == slack(b) && a < b); });
  order.resize(kPartnerCandidates);
  std::sort(order.begin(), order.end());
  return order;
}

}  // namespace

const char* to_string(WeightsSuggestion::Kind kind) {
  switch (kind) {
    case WeightsSuggestion::Kind::kShiftOrigin:
      return "shift_origin";
    case WeightsSuggestion::Kind::kBalancingEntry:
      return "balancing_entry";
    case WeightsSuggestion::Kind::kSymmetricPartner:
      break;
  }
  return "symmetric_partner";
}

const char* to_string(Weights::Status status) {
  switch (status) {
    case Weights::Status::kPositive:
      return "positive";
    case Weights::Status::kBoundary:
      return "boundary";
    case Weights::Status::kInfeasible:
      return "infeasible";
    case Weights::Status::kSolverFailed:
      return "solver_failed";
  }
  return "unknown";
}

bool WeightsOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (!(zero_tolerance > 0.0 && zero_tolerance <= 1e-2)) {
    return fail("zero_tolerance: must be in (0, 1e-2]");
  }
  std::string sdp_why;
  if (!sdp.is_valid(&sdp_why)) {
    if (why != nullptr) *why = "sdp." + sdp_why;
    return false;
  }
  return true;
}

namespace {

// Re-solves the LP on a fixed layout (its solves counted in `out`); fills `s` (weights,
// min_weight) when weights exist.
bool verify_fix(const Eigen::Matrix3Xd& fixed, const WeightsOptions& options, Weights* out,
                WeightsSuggestion* s) {
  const Classified f = classify(fixed, options);
  out->lp_solves += f.lp_solves;
  if (f.status != Weights::Status::kPositive && f.status != Weights::Status::kBoundary) {
    return false;
  }
  s->weights = f.weights;
  s->min_weight = f.weights.minCoeff();
  return true;
}

Eigen::Matrix3Xd with_entry(const Eigen::Matrix3Xd& z, const Eigen::Vector3d& added) {
  const Eigen::Index n = z.cols();
  Eigen::Matrix3Xd fixed(3, n + 1);
  fixed.leftCols(n) = z;
  fixed.col(n) = added;
  return fixed;
}

// The symmetric partner -z_i that gives the largest smallest weight, among the candidates of
// the LP's slack.
void suggest_partner(const Eigen::Matrix3Xd& z, const Classified& c, const WeightsOptions& options,
                     Weights* out) {
  WeightsSuggestion best_partner;
  bool have_partner = false;
  for (int i : partner_candidates(c.slack, static_cast<int>(z.cols()))) {
    if (!(z.col(i).norm() > 0.0)) continue;
    WeightsSuggestion partner;
    partner.kind = WeightsSuggestion::Kind::kSymmetricPartner;
    partner.index = i;
    partner.added = -z.col(i);
    if (!verify_fix(with_entry(z, partner.added), options, out, &partner)) continue;
    if (!have_partner || partner.min_weight > best_partner.min_weight) {
      have_partner = true;
      best_partner = partner;
    }
  }
  if (!have_partner) return;
  std::ostringstream t;
  t << "add the symmetric partner -z[" << best_partner.index
    << "] = " << format_vector(best_partner.added) << ": the smallest weight becomes "
    << best_partner.min_weight;
  best_partner.text = t.str();
  out->suggestions.push_back(best_partner);
}

// The fixes of a layout without positive weights, best first: a symmetric partner, a balancing
// entry, and (points) moving the origin to the centroid.
void suggest_fixes(const Eigen::Matrix3Xd& z, const Classified& c, const WeightsOptions& options,
                   bool allow_shift, Weights* out) {
  suggest_partner(z, c, options, out);
  WeightsSuggestion entry;
  entry.kind = WeightsSuggestion::Kind::kBalancingEntry;
  entry.added = -z.rowwise().sum();
  if (entry.added.norm() > 0.0 && verify_fix(with_entry(z, entry.added), options, out, &entry)) {
    std::ostringstream t;
    t << "add one entry at -sum z_i = " << format_vector(entry.added)
      << ": equal weights then balance, the smallest weight becomes " << entry.min_weight;
    entry.text = t.str();
    out->suggestions.push_back(entry);
  }
  if (allow_shift) {
    const Eigen::Vector3d centroid = z.rowwise().mean();
    WeightsSuggestion shift;
    shift.kind = WeightsSuggestion::Kind::kShiftOrigin;
    shift.shift = centroid;
    if (verify_fix(z.colwise() - centroid, options, out, &shift)) {
      std::ostringstream t;
      t << "move the object origin to the centroid " << format_vector(centroid)
        << " of the points: the smallest weight becomes " << shift.min_weight;
      shift.text = t.str();
      out->suggestions.push_back(shift);
    }
  }
  std::stable_sort(out->suggestions.begin(), out->suggestions.end(),
                   [](const WeightsSuggestion& a, const WeightsSuggestion& b) {
                     return a.min_weight > b.min_weight;
                   });
}

}  // namespace

Weights nullspace_weights(const Eigen::Matrix3Xd& z, const WeightsOptions& options,
                          bool allow_shift) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("WeightsOptions: " + why);
  if (z.cols() < 1) throw InvalidArgument("z: need at least 1 column");
  for (Eigen::Index i = 0; i < z.cols(); ++i) {
    if (!z.col(i).allFinite()) {
      throw InvalidArgument("z[" + std::to_string(i) + "]: not a finite number");
    }
  }
  Weights out;
  const Classified c = classify(z, options);
  out.status = c.status;
  out.sdp_status = c.sdp_status;
  out.lp_solves = c.lp_solves;
  out.lp_optimum = c.s;
  out.zero_forced = c.zero_forced;
  if (c.status == Weights::Status::kSolverFailed) {
    out.message =
        std::string("the LP backend returned no solution: ") + sdp::to_string(c.sdp_status);
    return out;
  }
  out.feasible = c.status == Weights::Status::kPositive || c.status == Weights::Status::kBoundary;
  if (out.feasible) {
    out.weights = c.weights;
    out.residual = (z * out.weights).norm();
    out.min_weight = out.weights.minCoeff();
  }
  if (c.status == Weights::Status::kPositive) {
    out.message = "strictly positive weights satisfy Eq. (11)";
  } else if (c.status == Weights::Status::kBoundary) {
    out.message =
        "the origin lies on the boundary of the convex hull of the z_i: weights exist only with " +
        std::to_string(out.zero_forced.size()) + " of them 0";
  } else {
    out.message =
        "no non-negative weights satisfy Eq. (11): the origin is outside the convex hull of the "
        "z_i";
  }
  if (!options.suggest || c.status == Weights::Status::kPositive) return out;

  suggest_fixes(z, c, options, allow_shift, &out);
  return out;
}

Weights layout_weights(const Layout& layout, const WeightsOptions& options) {
  layout.validate();
  return nullspace_weights(layout.entries, options, layout.mode == LayoutMode::kPoints);
}

}  // namespace vantage::design
