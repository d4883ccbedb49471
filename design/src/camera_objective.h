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

  /// The samples: the workspace's lattice directions (those of `vantage crb`'s map, in its
  /// order) at each distance of the approach, distance outer: sample d is lattice direction
  /// d % L at distance d / L for a lattice of L directions.
  int directions() const { return static_cast<int>(stride_); }
  /// Site s is seen by the camera of sample d.
  bool sees(int site, int d) const { return seen_[static_cast<std::size_t>(site) * stride_ + d]; }
  /// Markers a direction must see: max(3, min_visible).
  int min_seen() const { return min_seen_; }

  /// The largest over the distances of the statistic of rot_rms_deg over the lattice directions
  /// where `chosen` (increasing) is trackable at that distance, +inf when it is trackable nowhere
  /// at one of them. With the worst, the evaluation stops at the first value at or above `level`
  /// (then the result is some value >= level), trying sample `*hint` first and setting it to the
  /// worst sample found.
  double value(const std::vector<int>& chosen, double level, int* hint) const;

  /// The bound of `chosen` at sample d (for the tests).
  camera::PoseCrbAt at(const std::vector<int>& chosen, int d) const;

 private:
  double worst(const std::vector<int>& chosen, double level, int* hint) const;
  double percentile(const std::vector<int>& chosen, double q) const;

  const CameraObjective& objective_;
  camera::PoseCrbModel model_;
  std::vector<Eigen::Vector3d> directions_;  ///< the lattice
  std::vector<double> distances_;            ///< the approach, or the one distance
  std::vector<Eigen::Matrix3d> rotations_;   ///< per sample
  std::vector<Eigen::Vector3d> translations_;
  std::vector<char> seen_;
  std::size_t stride_ = 0;
  int min_seen_ = 3;
};

}  // namespace vantage::design::internal
