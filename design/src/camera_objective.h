#pragma once

// Private to vantage::design: the `camera` objective of marker placement (docs/math.md §21,
// "Objectives"): the pinhole CRB of §22 at the lattice directions of the workspace, each site
// seen by its own line of sight to the camera centre.

#include <Eigen/Core>
#include <vector>

#include "vantage/camera/pose_crb.h"
#include "vantage/design/placement.h"

namespace vantage::design::internal {

class CameraSiteObjective {
 public:
  /// Builds the model of every site and which site each lattice camera sees (`threads`, 0: all).
  CameraSiteObjective(const CameraObjective& objective, int threads);

  /// The workspace's lattice directions (those of `vantage crb`'s map, in its order).
  int directions() const { return static_cast<int>(directions_.size()); }
  /// Site s is seen by the camera of direction d.
  bool sees(int site, int d) const { return seen_[static_cast<std::size_t>(site) * stride_ + d]; }
  /// Markers a direction must see: max(3, min_visible).
  int min_seen() const { return min_seen_; }

  /// The statistic of rot_rms_deg over the directions where `chosen` (increasing) is trackable,
  /// +inf when it is trackable nowhere. With the worst, the evaluation stops at the first value
  /// at or above `level` (then the result is some value >= level), trying direction `*hint` first
  /// and setting it to the worst direction found.
  double value(const std::vector<int>& chosen, double level, int* hint) const;

  /// The bound of `chosen` at direction d (for the tests).
  camera::PoseCrbAt at(const std::vector<int>& chosen, int d) const;

 private:
  const CameraObjective& objective_;
  camera::PoseCrbModel model_;
  std::vector<Eigen::Vector3d> directions_;
  std::vector<Eigen::Matrix3d> rotations_;
  std::vector<Eigen::Vector3d> translations_;
  std::vector<char> seen_;
  std::size_t stride_ = 0;
  int min_seen_ = 3;
};

}  // namespace vantage::design::internal
