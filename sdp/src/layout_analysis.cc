#include "vantage/sdp/layout_analysis.h"

#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"

namespace vantage::sdp {

bool LayoutAnalysisOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!worst_viewpoint.is_valid(&inner) || !crosscheck.is_valid(&inner)) {
    if (why != nullptr) *why = "LayoutAnalysisOptions: " + inner;
    return false;
  }
  if (swap_count < 1) {
    if (why != nullptr) *why = "LayoutAnalysisOptions::swap_count must be >= 1";
    return false;
  }
  return true;
}

LayoutAnalysis analyze_vectors(const Eigen::Matrix3Xd& vectors, const Eigen::VectorXd& weights,
                               const LayoutAnalysisOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("analyze_vectors: options: " + why);
  if (vectors.cols() < 2) {
    throw InvalidArgument("analyze_vectors: vectors must have at least 2 columns");
  }
  normalized_columns(vectors, "analyze_vectors: vectors");

  LayoutAnalysis report;
  WorstViewpointOptions wv = options.worst_viewpoint;
  wv.confirm_with_sdp = true;
  const WorstViewpoint global = global_worst_viewpoint(vectors, wv);
  report.worst_viewpoint = global.viewpoint;
  report.worst_viewpoints = global.viewpoints;
  report.t = global.t;
  report.pbar_min = global.pbar;
  report.worst_case_errors_deg = worst_case_errors_deg(vectors, global.viewpoint);
  // With tied worst viewpoints the bound is the largest over all of them (design reports the same).
  report.max_worst_case_error_deg = report.worst_case_errors_deg.maxCoeff();
  for (const Eigen::Vector3d& a : global.viewpoints) {
    report.max_worst_case_error_deg =
        std::max(report.max_worst_case_error_deg, worst_case_errors_deg(vectors, a).maxCoeff());
  }
  report.certificate = {global.t_upper, global.t_lower,
                        global.status != WorstViewpoint::Status::kNotCertified};
  report.solver.backend = to_string(wv.sdp.backend);
  report.solver.status = to_string(global.status);
  report.solver.cells_solved = global.cells_solved;
  report.solver.patches = global.patches;
  report.solver.sdp_status = to_string(global.confirmation.sdp.status);
  report.message = global.message;

  const CellViewpoint paper = paper_worst_viewpoint(vectors, wv.sdp);
  report.paper_lmi = {paper.viewpoint, paper.t, paper.pbar, to_string(paper.status)};

  if (options.run_crosscheck) {
    const CrossCheck check =
        crosscheck_worst_viewpoint(vectors, global.t, options.crosscheck, global.viewpoints);
    report.crosscheck = {check.method, check.t, check.agrees, check.message};
    if (!check.agrees) {
      if (!report.message.empty()) report.message += "; ";
      report.message += check.message;
    }
  } else {
    report.crosscheck = {"skipped", 0.0, false, "cross-check not run"};
  }
  report.swaps = swap_sensitivity(vectors, weights, options.swap_count);
  return report;
}

}  // namespace vantage::sdp
