#include "vantage/analysis/pose_estimate.h"

#include <algorithm>

namespace vantage {

const char* to_string(PoseStatus status) {
  switch (status) {
    case PoseStatus::kOk:
      return "ok";
    case PoseStatus::kMaxIterations:
      return "max_iterations";
    case PoseStatus::kDegenerate:
      return "degenerate";
    case PoseStatus::kNoPointsInFront:
      return "no_points_in_front";
  }
  return "unknown";
}

bool BranchOptions::ambiguous(const PoseEstimate& estimate) const {
  if (!estimate.alternative) return false;
  const double floor = std::max(estimate.reprojection_rms_px, ambiguity_floor_px);
  return estimate.alternative->reprojection_rms_px <= ambiguity_ratio * floor;
}

bool BranchOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(necker_planarity >= 0.0 && necker_planarity <= 1.0))
    return fail("necker_planarity must be in [0, 1]");
  if (!(ambiguity_ratio >= 1.0)) return fail("ambiguity_ratio must be >= 1");
  if (!(ambiguity_floor_px >= 0.0)) return fail("ambiguity_floor_px must be >= 0");
  if (!(same_pose_angle >= 0.0)) return fail("same_pose_angle must be >= 0");
  return true;
}

}  // namespace vantage
