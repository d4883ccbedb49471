#include <algorithm>
#include <cmath>

#include "designer.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/error_bounds.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/design/augment.h"
#include "vantage/sdp/worst_viewpoint.h"

namespace vantage::design {

WorstCase evaluate_worst_case(const Eigen::Matrix3Xd& vectors) {
  return internal::evaluate_worst_case(vectors, {}, nullptr);
}

namespace internal {

WorstCase evaluate_worst_case(const Eigen::Matrix3Xd& vectors,
                              const sdp::WorstViewpointOptions& options, bool* stopped) {
  return worst_case_of(sdp::global_worst_viewpoint(vectors, options), vectors, stopped);
}

WorstCase worst_case_of(const sdp::WorstViewpoint& w, const Eigen::Matrix3Xd& vectors,
                        bool* stopped) {
  if (stopped != nullptr) *stopped = w.status == sdp::WorstViewpoint::Status::kStoppedAbove;
  WorstCase out;
  out.t = w.t;
  out.pbar_min = w.pbar_min;
  out.worst_viewpoints = w.viewpoints;
  if (out.worst_viewpoints.empty()) out.worst_viewpoints.push_back(w.viewpoint);
  out.certified = w.status == sdp::WorstViewpoint::Status::kCertified;
  for (const Eigen::Vector3d& a : out.worst_viewpoints) {
    out.max_worst_case_error_deg =
        std::max(out.max_worst_case_error_deg, worst_case_errors_deg(vectors, a).maxCoeff());
  }
  return out;
}

}  // namespace internal

}  // namespace vantage::design
