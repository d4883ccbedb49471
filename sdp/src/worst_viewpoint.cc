#include "vantage/sdp/worst_viewpoint.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "global_search.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/scaling.h"
#include "vantage/sdp/internal/message_parts.h"
#include "vantage/sdp/internal/min_norm_point.h"

namespace vantage::sdp {
namespace {

// Attained values this close to the best are equal up to rounding (each is min_i |a.n_i|, dot
// products of unit vectors accurate to a few ulps): among them the reported viewpoint is the
// lexicographically first, so exactly symmetric layouts give a canonical answer. Far below any
// certificate_tolerance, and the only slack allowed between t_lower and the best attained value.
constexpr double kSameValue = 1e-14;
// A whole-cell optimum replaces the search's point when its value is at least the search's
// within this (both are computed to ~1e-14; the search's point is the same cell's optimum).
constexpr double kCellExact = 1e-12;

bool lexicographically_before(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  for (int k = 2; k >= 0; --k) {
    if (a(k) != b(k)) return a(k) > b(k);
  }
  return false;
}

}  // namespace

Eigen::Matrix3Xd normalized_columns(const Eigen::Matrix3Xd& vectors, const char* argument) {
  Eigen::Matrix3Xd n(3, vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    // Each column on its own scale: a direction is never lost beside a longer vector.
    n.col(i) = unit_direction(vectors.col(i));
    if (n.col(i).isZero(0.0)) {
      std::ostringstream out;
      out << argument << ": column " << i << " is zero or not finite";
      throw InvalidArgument(out.str());
    }
  }
  return n;
}

double min_abs_projection(const Eigen::Matrix3Xd& unit_vectors, const Eigen::Vector3d& a) {
  return (unit_vectors.transpose() * a).cwiseAbs().minCoeff();
}

double pbar_at(const Eigen::Matrix3Xd& unit_vectors, const Eigen::Vector3d& a) {
  double largest = 0.0;
  for (Eigen::Index i = 0; i < unit_vectors.cols(); ++i) {
    largest = std::max(largest, a.cross(unit_vectors.col(i)).norm());
  }
  return std::min(1.0, largest);
}

double pbar_from_t(double t) {
  const double c = std::clamp(t, 0.0, 1.0);
  return std::sqrt((1.0 - c) * (1.0 + c));
}

Eigen::Vector3d upper_hemisphere(const Eigen::Vector3d& a) {
  if (a.z() > 0.0) return a;
  if (a.z() < 0.0) return -a;
  if (a.y() > 0.0) return a;
  if (a.y() < 0.0) return -a;
  return a.x() >= 0.0 ? a : Eigen::Vector3d(-a);
}

Eigen::VectorXd upper_hemisphere_signs(const Eigen::Matrix3Xd& vectors) {
  Eigen::VectorXd signs(vectors.cols());
  for (Eigen::Index i = 0; i < vectors.cols(); ++i) {
    const Eigen::Vector3d z = vectors.col(i);
    signs(i) = upper_hemisphere(z) == z ? 1.0 : -1.0;
  }
  return signs;
}

const char* to_string(CellViewpoint::Status status) {
  switch (status) {
    case CellViewpoint::Status::kOk:
      return "ok";
    case CellViewpoint::Status::kEmptyCell:
      return "empty_cell";
    case CellViewpoint::Status::kSolverFailed:
      return "solver_failed";
  }
  return "unknown";
}

const char* to_string(WorstViewpoint::Status status) {
  switch (status) {
    case WorstViewpoint::Status::kCertified:
      return "certified";
    case WorstViewpoint::Status::kNotCertified:
      return "not_certified";
    case WorstViewpoint::Status::kSdpDisagrees:
      return "sdp_disagrees";
    case WorstViewpoint::Status::kStoppedAbove:
      return "stopped_above";
  }
  return "unknown";
}

bool WorstViewpointOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (!(certificate_tolerance >= 1e-15 && certificate_tolerance <= 1e-3)) {
    return fail("WorstViewpointOptions::certificate_tolerance must be in [1e-15, 1e-3]");
  }
  if (!(tie_tolerance >= 0.0 && tie_tolerance <= 1e-3)) {
    return fail("WorstViewpointOptions::tie_tolerance must be in [0, 1e-3]");
  }
  if (max_patches < 1) return fail("WorstViewpointOptions::max_patches must be >= 1");
  if (threads != 1 && threads != 2) return fail("WorstViewpointOptions::threads must be 1 or 2");
  if (std::isnan(stop_above)) return fail("WorstViewpointOptions::stop_above must not be NaN");
  for (const Eigen::Vector3d& h : hints) {
    if (!h.allFinite() || h.norm() == 0.0) {
      return fail("WorstViewpointOptions::hints must be finite and non-zero");
    }
  }
  std::string sdp_why;
  if (!sdp.is_valid(&sdp_why)) {
    if (why != nullptr) *why = "WorstViewpointOptions::sdp: " + sdp_why;
    return false;
  }
  return true;
}

WorstViewpoint global_worst_viewpoint(const Eigen::Matrix3Xd& vectors,
                                      const WorstViewpointOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("global_worst_viewpoint: options: " + why);
  if (vectors.cols() < 2) {
    throw InvalidArgument("global_worst_viewpoint: vectors must have at least 2 columns, got " +
                          std::to_string(vectors.cols()));
  }
  const Eigen::Matrix3Xd n = normalized_columns(vectors, "global_worst_viewpoint: vectors");
  return internal::worst_viewpoint_result(
      n, internal::search_worst_viewpoint(internal::distinct_directions(n), options), options);
}

namespace internal {

// The optimum of the cell containing c.a, solved on every column of n: the search reaches a
// cell's optimum along different paths (from a sub-list of the circles, or with hints, or from a
// prepared frontier), which agree only to rounding; solved again on the whole cell, the reported
// point and value depend on the cell alone, to the last bit.
void canonical_cell_optimum(const Eigen::Matrix3Xd& n, AttainedViewpoint* c) {
  Eigen::Matrix3Xd points(3, n.cols());
  for (Eigen::Index i = 0; i < n.cols(); ++i) {
    points.col(i) = n.col(i).dot(c->a) >= 0.0 ? n.col(i) : Eigen::Vector3d(-n.col(i));
  }
  const MinNormPoint p = min_norm_point(points.data(), static_cast<int>(n.cols()));
  if (p.contains_origin) return;
  const Eigen::Vector3d a = p.x / p.x.norm();
  const double value = min_abs_projection(n, a);
  if (value >= c->value - kCellExact) *c = {a, value};
}

WorstViewpoint worst_viewpoint_result(const Eigen::Matrix3Xd& n, const SearchOutcome& search,
                                      const WorstViewpointOptions& options) {
  WorstViewpoint result;
  if (search.stopped) {
    result.status = WorstViewpoint::Status::kStoppedAbove;
    result.viewpoint = upper_hemisphere(search.stop_point);
    result.viewpoints = {result.viewpoint};
    result.t = min_abs_projection(n, result.viewpoint);
    result.t_lower = result.t;
    result.t_upper = 1.0;
    result.pbar_min = pbar_at(n, result.viewpoint);
    result.cells_solved = search.cells_solved;
    result.patches = search.patches;
    result.message = "stopped: an attained value exceeds stop_above";
    return result;
  }
  std::vector<AttainedViewpoint> optima = search.optima;
  VANTAGE_CHECK(!optima.empty(), "the branch and bound found no attained viewpoint");
  // The reported viewpoint must attain the best value found: t_upper is certified against that
  // value, so reporting another tie (up to tie_tolerance below it) would widen the certificate by
  // up to tie_tolerance. Only values equal to the best up to rounding are ordered
  // lexicographically; the other ties follow by decreasing value. The group is fixed before
  // sorting, so the comparison is a strict weak ordering.
  double best = 0.0;
  for (AttainedViewpoint& c : optima) {
    canonical_cell_optimum(n, &c);
    c.a = upper_hemisphere(c.a);
    best = std::max(best, c.value);
  }
  std::sort(optima.begin(), optima.end(),
            [&](const AttainedViewpoint& a, const AttainedViewpoint& b) {
              const bool a_best = a.value >= best - kSameValue;
              const bool b_best = b.value >= best - kSameValue;
              if (a_best != b_best) return a_best;
              if (!a_best && a.value != b.value) return a.value > b.value;
              return lexicographically_before(a.a, b.a);
            });
  result.viewpoint = optima.front().a;
  for (const AttainedViewpoint& c : optima) result.viewpoints.push_back(c.a);
  result.t = min_abs_projection(n, result.viewpoint);
  result.t_lower = result.t;
  result.t_upper = std::max(search.upper, result.t);
  result.pbar_min = pbar_at(n, result.viewpoint);
  result.cells_solved = search.cells_solved;
  result.patches = search.patches;
  const bool certified =
      !search.exhausted && result.t_upper - result.t_lower <= options.certificate_tolerance;
  result.status =
      certified ? WorstViewpoint::Status::kCertified : WorstViewpoint::Status::kNotCertified;
  if (!certified) {
    std::ostringstream out;
    out << "not certified: t_upper - t_lower = " << result.t_upper - result.t_lower << " after "
        << result.patches << " patches";
    result.message = out.str();
  }
  if (options.confirm_with_sdp) {
    Eigen::VectorXd signs(n.cols());
    for (Eigen::Index i = 0; i < n.cols(); ++i) {
      signs(i) = n.col(i).dot(result.viewpoint) >= 0.0 ? 1.0 : -1.0;
    }
    result.confirmation = solve_cell_lmi(n, signs, options.sdp);
    result.sdp_confirmed = true;
    const bool agrees = result.confirmation.status == CellViewpoint::Status::kOk &&
                        std::abs(result.confirmation.t - result.t) <= WorstViewpoint::kSdpAgreement;
    if (!agrees) {
      std::ostringstream out;
      out << "SDP confirmation disagrees: cell LMI " << to_string(result.confirmation.status)
          << " t = " << result.confirmation.t << " vs t = " << result.t;
      append_message(&result.message, out.str());
      if (certified) result.status = WorstViewpoint::Status::kSdpDisagrees;
    }
  }
  return result;
}

}  // namespace internal

}  // namespace vantage::sdp
