// The front door of the pose CRB (docs/math.md §22): the map, the bound at a direction, the
// affine bound of the same layout beside it, and the distance sweep.

#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/report/layout_report.h"

namespace vantage::camera {

PoseCrbReport pose_crb_report(const Layout& layout, const PoseCrbOptions& options,
                              const std::optional<Eigen::Vector3d>& direction,
                              const std::optional<PoseCrbSweep>& sweep,
                              const CrbProgress& progress) {
  const PoseCrbModel model(layout, options);
  PoseCrbReport report;
  report.camera = options;
  report.with_body = model.with_body();
  report.markers = static_cast<int>(model.points().cols());
  if (direction) report.at_direction = model.at(*direction);
  report.map = pose_crb_map(model);
  if (sweep) {
    report.sweep_distance =
        pose_crb_distance_sweep(model, sweep->from, sweep->to, sweep->count, progress);
  }
  report::LayoutReportOptions affine;
  affine.analysis.run_crosscheck = false;
  affine.analysis.swap_count = 1;
  affine.visibility.threads = options.threads;
  const report::LayoutReport analysis = report::analyze_layout(layout, affine);
  report.affine_bound_deg = analysis.visibility ? analysis.visibility->max_worst_case_error_deg
                                                : analysis.analysis.max_worst_case_error_deg;
  return report;
}

}  // namespace vantage::camera
