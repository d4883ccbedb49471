#include "vantage/sdp/layout_analysis.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/analysis/scaling.h"

namespace vantage::sdp {

namespace {

// arccos(0) in degrees: the worst-case error of Eq. (30) when p-bar_min = 0.
constexpr double kRightAngleDeg = 90.0;

void append(std::string* message, const std::string& part) {
  if (!message->empty()) *message += "; ";
  *message += part;
}

// Unit columns all within kParallelTolerance of one line.
bool all_parallel(const Eigen::Matrix3Xd& unit) {
  for (Eigen::Index i = 1; i < unit.cols(); ++i) {
    if (unit.col(i).cross(unit.col(0)).norm() > kParallelTolerance) return false;
  }
  return true;
}

}  // namespace

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

LayoutAnalysis analyze_vectors(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& weights,
                               const LayoutAnalysisOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("options." + why);
  if (vectors.cols() < 2) {
    throw InvalidArgument("vectors: need at least 2, got " + std::to_string(vectors.cols()));
  }
  if (!vectors.allFinite()) {
    Eigen::Index bad = 0;
    while (vectors.col(bad).allFinite()) ++bad;
    throw InvalidArgument("vectors[" + std::to_string(bad) + "]: not a finite number");
  }
  // Every part of the analysis depends on directions and relative lengths only: scale by a power
  // of two (exactly) so that no norm over- or underflows, whatever the data's units.
  const Eigen::Matrix3Xd scaled = scaled_by_power_of_two(vectors, binary_exponent(vectors));
  for (Eigen::Index i = 0; i < scaled.cols(); ++i) {
    if (!(scaled.col(i).norm() > 0.0)) {
      throw InvalidArgument("vectors[" + std::to_string(i) +
                            "]: zero (or negligible beside the longest vector)");
    }
  }
  const Eigen::Matrix3Xd n = normalized_columns(scaled, "vectors");

  LayoutAnalysis report;
  WorstViewpointOptions wv = options.worst_viewpoint;
  wv.confirm_with_sdp = true;
  auto stage = [&](const char* name) {
    if (options.progress) options.progress(name);
  };
  stage("global worst viewpoint");
  const WorstViewpoint global = global_worst_viewpoint(scaled, wv);
  report.worst_viewpoint = global.viewpoint;
  report.worst_viewpoints = global.viewpoints;
  report.t = global.t;
  report.pbar_min = global.pbar_min;
  report.worst_case_errors_deg = worst_case_errors_deg(scaled, global.viewpoint);
  // With tied worst viewpoints the bound is the largest over all of them (design reports the same).
  report.max_worst_case_error_deg = report.worst_case_errors_deg.maxCoeff();
  for (const Eigen::Vector3d& a : global.viewpoints) {
    report.max_worst_case_error_deg =
        std::max(report.max_worst_case_error_deg, worst_case_errors_deg(scaled, a).maxCoeff());
  }
  report.certificate = {global.t_upper, global.t_lower, global.certified()};
  report.solver.backend = wv.sdp.backend;
  report.solver.status = global.status;
  report.solver.cells_solved = global.cells_solved;
  report.solver.patches = global.patches;
  report.solver.sdp_status = global.confirmation.sdp.status;
  report.message = global.message;

  stage("paper's single LMI");
  const CellViewpoint paper = paper_worst_viewpoint(scaled, wv.sdp);
  report.paper_lmi = {paper.viewpoint, paper.t, paper.pbar_at, paper.status};

  if (options.run_crosscheck) {
    stage("cross-check");
    const CrossCheck check =
        crosscheck_worst_viewpoint(scaled, global.t, options.crosscheck, global.viewpoints);
    report.crosscheck = {true,
                         check.method,
                         check.t,
                         check.agrees,
                         check.message,
                         check.samples,
                         check.sample_spacing,
                         check.samples_cover_cells};
    if (!check.agrees) append(&report.message, check.message);
  }
  stage("swap sensitivity");
  report.swaps = swap_sensitivity(scaled, weights, options.swap_count);
  if (all_parallel(n)) {
    // Every p_i is 0 at the common line: the whole of each vector is lost (docs/math.md §11 with
    // p-bar_min = 0), and nothing fixes the rotation about that line.
    report.degenerate = true;
    report.worst_case_errors_deg.setConstant(kRightAngleDeg);
    report.max_worst_case_error_deg = kRightAngleDeg;
    append(&report.message,
           "degenerate layout: every data vector is parallel to one line (collinear points, or "
           "duplicated or opposite vectors), so p-bar_min = 0, the LUB scale is undefined and "
           "the rotation about that line cannot be determined");
  }
  return report;
}

bool LayoutAnalysis::trusted() const {
  return solver.status == WorstViewpoint::Status::kCertified &&
         (!crosscheck.ran || crosscheck.agrees);
}

}  // namespace vantage::sdp
