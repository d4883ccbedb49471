#include "vantage/sdp/layout_analysis.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "narrowest_cone.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/analysis/scaling.h"
#include "vantage/sdp/certified_worst.h"
#include "vantage/sdp/internal/message_parts.h"

namespace vantage::sdp {

namespace {

// arccos(0) in degrees: the worst-case error of Eq. (30) when p-bar_min = 0.
constexpr double kRightAngleDeg = 90.0;

std::string three_digits(double x) {
  std::ostringstream out;
  out << std::setprecision(3) << x;
  return out.str();
}

// Unit columns all within kParallelTolerance of one line.
bool all_parallel(const Eigen::Matrix3Xd& unit) {
  for (Eigen::Index i = 1; i < unit.cols(); ++i) {
    if (unit.col(i).cross(unit.col(0)).norm() > kParallelTolerance) return false;
  }
  return true;
}

// A near-degenerate layout's t has rounded to 1 near the optimum, so the search's viewpoint is
// any of the near-optimal ones; the sines (p-bar) still tell them apart (narrowest_cone.h).
void sharpen_near_degenerate(const Eigen::Matrix3Xd& n, LayoutAnalysis* report) {
  const Eigen::Vector3d a =
      upper_hemisphere(internal::narrowest_cone_axis(n, report->worst_viewpoint));
  const double pbar = pbar_at(n, a);
  if (pbar >= report->pbar_min) return;
  report->worst_viewpoint = a;
  report->worst_viewpoints = {a};
  report->t = min_abs_projection(n, a);
  report->pbar_min = pbar;
}

}  // namespace

bool is_near_degenerate(double pbar_min, double t, double certificate_tolerance) {
  // 1 - t from p-bar, which keeps its digits where t has rounded to 1.
  return pbar_min * pbar_min / (1.0 + t) <= certificate_tolerance;
}

bool LayoutAnalysisOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!worst_viewpoint.is_valid(&inner) || !crosscheck.is_valid(&inner)) {
    if (why != nullptr) *why = inner;
    return false;
  }
  if (swap_count < 1) {
    if (why != nullptr) *why = "swap_count: must be >= 1";
    return false;
  }
  return true;
}

namespace {

// Throws InvalidArgument unless there are at least 2 finite vectors; returns their unit
// directions, each normalised on its own scale (none of zero length).
Eigen::Matrix3Xd checked_unit_directions(const Eigen::Matrix3Xd& vectors) {
  if (vectors.cols() < 2) {
    throw InvalidArgument("vectors: need at least 2, got " + std::to_string(vectors.cols()));
  }
  if (!vectors.allFinite()) {
    Eigen::Index bad = 0;
    while (vectors.col(bad).allFinite()) ++bad;
    throw InvalidArgument("vectors[" + std::to_string(bad) + "]: not a finite number");
  }
  Eigen::Matrix3Xd n = unit_directions(vectors);
  for (Eigen::Index i = 0; i < n.cols(); ++i) {
    if (n.col(i).isZero(0.0)) {
      throw InvalidArgument("vectors[" + std::to_string(i) + "]: zero length");
    }
  }
  return n;
}

// The global worst viewpoint, its Eq. (30) errors, certificate and solver record.
void record_global_worst(const Eigen::Matrix3Xd& n, const WorstViewpointOptions& wv,
                         const WorstViewpoint& global, LayoutAnalysis* report) {
  report->worst_viewpoint = global.viewpoint;
  report->worst_viewpoints = global.viewpoints;
  report->t = global.t;
  report->pbar_min = global.pbar_min;
  if (is_near_degenerate(global.pbar_min, global.t, wv.certificate_tolerance)) {
    sharpen_near_degenerate(n, report);
  }
  report->worst_case_errors_deg = worst_case_errors_deg(n, report->worst_viewpoint);
  // With tied worst viewpoints the bound is the largest over all of them (design reports the same).
  report->max_worst_case_error_deg =
      std::max(report->worst_case_errors_deg.maxCoeff(),
               max_worst_case_error_deg(n, report->worst_viewpoints));
  report->certificate = {global.t_upper, global.t_lower, global.certified()};
  report->solver.backend = wv.sdp.backend;
  report->solver.status = global.status;
  report->solver.cells_solved = global.cells_solved;
  report->solver.patches = global.patches;
  report->solver.sdp_status = global.confirmation.sdp.status;
  report->message = global.message;
}

// The NLopt cross-check of the global worst viewpoint; a disagreement joins the message.
void record_crosscheck(const Eigen::Matrix3Xd& n, const WorstViewpoint& global,
                       const CrossCheckOptions& options, LayoutAnalysis* report) {
  const CrossCheck check = crosscheck_worst_viewpoint(n, global.t, options, global.viewpoints);
  if (!check.skipped.empty()) {
    report->crosscheck.skipped = check.skipped;
    return;
  }
  report->crosscheck = {true,
                        "",
                        check.method,
                        check.t,
                        check.agrees,
                        check.message,
                        check.samples,
                        check.sample_spacing,
                        check.samples_cover_cells};
  if (!check.agrees) internal::append_message(&report->message, check.message);
}

// Marks a degenerate (all parallel) or near-degenerate layout and says so in the message.
void flag_degeneracy(const Eigen::Matrix3Xd& n, double certificate_tolerance,
                     LayoutAnalysis* report) {
  if (all_parallel(n)) {
    // Every p_i is 0 at the common line: the whole of each vector is lost (docs/math.md §11 with
    // p-bar_min = 0), and nothing fixes the rotation about that line.
    report->degenerate = true;
    report->worst_case_errors_deg.setConstant(kRightAngleDeg);
    report->max_worst_case_error_deg = kRightAngleDeg;
    internal::append_message(
        &report->message,
        "degenerate layout: every data vector is parallel to one line (collinear points, or "
        "duplicated or opposite vectors), so p-bar_min = 0, the LUB scale is undefined and "
        "the rotation about that line cannot be determined");
  } else if (is_near_degenerate(report->pbar_min, report->t, certificate_tolerance)) {
    // The errors stay those of Eq. (30) at the accurate p_i (close to 90 degrees, not 0).
    report->near_degenerate = true;
    internal::append_message(
        &report->message,
        "near-degenerate layout: every data vector is within " +
            three_digits(std::asin(report->pbar_min)) +
            " rad of one line (p-bar_min = " + three_digits(report->pbar_min) +
            "), too close for the certificate on t to tell it from a degenerate layout; the "
            "rotation about that line is barely determined");
  }
}

}  // namespace

LayoutAnalysis analyze_vectors(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& weights,
                               const LayoutAnalysisOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options." + why);
  // The worst viewpoint and Eq. (30) depend on the directions only: each is normalised on its
  // own scale, so no length in [smallest, largest double] is lost beside another. The swap
  // analysis also needs the relative lengths: it gets the data scaled by one power of two
  // (exact), so that no norm over- or underflows whatever the units.
  const Eigen::Matrix3Xd n = checked_unit_directions(vectors);
  const Eigen::Matrix3Xd scaled = scaled_by_power_of_two(vectors, binary_exponent(vectors));

  LayoutAnalysis report;
  WorstViewpointOptions wv = options.worst_viewpoint;
  wv.confirm_with_sdp = true;
  auto stage = [&](const char* name) {
    if (options.progress) options.progress(name);
  };
  stage("global worst viewpoint");
  const WorstViewpoint global = global_worst_viewpoint(n, wv);
  record_global_worst(n, wv, global, &report);

  stage("paper's single LMI");
  const CellViewpoint paper = paper_worst_viewpoint(n, wv.sdp);
  report.paper_lmi = {paper.viewpoint, paper.t, paper.pbar_at, paper.status};

  if (options.run_crosscheck) {
    stage("cross-check");
    record_crosscheck(n, global, options.crosscheck, &report);
  } else {
    report.crosscheck.skipped = "not requested";
  }
  stage("swap sensitivity");
  report.swaps = swap_sensitivity(scaled, weights, options.swap_count);
  flag_degeneracy(n, wv.certificate_tolerance, &report);
  return report;
}

bool LayoutAnalysis::trusted() const {
  return solver.status == WorstViewpoint::Status::kCertified &&
         (!crosscheck.ran || crosscheck.agrees);
}

}  // namespace vantage::sdp
