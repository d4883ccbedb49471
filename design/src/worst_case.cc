#include "designer.h"
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
  return sdp::certified_worst(w, vectors);
}

}  // namespace internal

}  // namespace vantage::design
