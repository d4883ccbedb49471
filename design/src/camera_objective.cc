// The `camera` objective of marker placement (docs/math.md §21, "Objectives"): the pinhole CRB
// (§22) of a choice of sites at the workspace's lattice directions.

#include "camera_objective.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vantage/analysis/parallel.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/workspace_lattice.h"

namespace vantage::design::internal {

CameraSiteObjective::CameraSiteObjective(const CameraObjective& objective, int threads)
    : objective_(objective), model_(objective.sites, objective.crb) {
  const Eigen::Matrix3Xd lattice =
      visibility::workspace_lattice(model_.workspace(), objective.crb.samples).directions;
  for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
    // Normalised as `vantage crb` normalises each direction, so that both see the same cameras.
    directions_.push_back(lattice.col(k).normalized());
  }
  const double distance = objective.crb.distance;
  rotations_.resize(directions_.size());
  translations_.resize(directions_.size());
  for (std::size_t d = 0; d < directions_.size(); ++d) {
    model_.camera_pose(directions_[d], distance, &rotations_[d], &translations_[d]);
  }
  min_seen_ = std::max(3, model_.visibility().min_visible());
  stride_ = directions_.size();
  const long n = static_cast<long>(objective.sites.entries.cols());
  seen_.assign(static_cast<std::size_t>(n) * stride_, 0);
  const Eigen::Vector3d& aim = model_.centroid();
  parallel_blocks(n, threads, [&](long b, long e) {
    for (long s = b; s < e; ++s) {
      for (std::size_t d = 0; d < stride_; ++d) {
        const Eigen::Vector3d c = aim + distance * directions_[d];
        seen_[static_cast<std::size_t>(s) * stride_ + d] =
            model_.visibility().visible(static_cast<int>(s), c) ? 1 : 0;
      }
    }
  });
}

camera::PoseCrbAt CameraSiteObjective::at(const std::vector<int>& chosen, int d) const {
  camera::PoseCrbAt out;
  const std::size_t k = static_cast<std::size_t>(d);
  out.direction = directions_[k];
  out.rot_rms_deg = std::numeric_limits<double>::infinity();
  out.trans_rms = std::numeric_limits<double>::infinity();
  out.first_order_rot_rms_deg = std::numeric_limits<double>::infinity();
  Eigen::Matrix<double, 6, 6> F = Eigen::Matrix<double, 6, 6>::Zero();
  const Eigen::Matrix3Xd& points = objective_.sites.entries;
  for (std::size_t m = 0; m < chosen.size(); ++m) {
    if (!sees(chosen[m], d)) continue;
    out.visible_markers.push_back(static_cast<int>(m));
    F.noalias() += camera::marker_information(points.col(chosen[m]), rotations_[k],
                                              translations_[k], objective_.crb.focal_length);
  }
  if (static_cast<int>(out.visible_markers.size()) < min_seen_) return out;
  camera::complete_pose_crb(F, objective_.crb.noise_px, objective_.crb.distance, &out);
  return out;
}

double CameraSiteObjective::value(const std::vector<int>& chosen, double level, int* hint) const {
  const bool worst = objective_.statistic == CrbStatistic::kWorst;
  const int n = directions();
  std::vector<double> values;  // every trackable value, for a percentile only
  int worst_at = -1;
  double largest = -1.0;
  const int first = hint != nullptr && *hint >= 0 && *hint < n ? *hint : 0;
  for (int step = 0; step < n; ++step) {
    const int d = (first + step) % n;
    // The first-order value ranks past the reporting limit too (a 200 deg layout is better
    // than a 6 000 deg one, though neither is a figure: docs/math.md §21, "Objectives").
    const double rot_rms_deg = this->at(chosen, d).first_order_rot_rms_deg;
    if (!std::isfinite(rot_rms_deg)) continue;
    if (!worst) values.push_back(rot_rms_deg);
    if (rot_rms_deg > largest) {
      largest = rot_rms_deg;
      worst_at = d;
    }
    if (worst && largest >= level) break;
  }
  if (hint != nullptr && worst_at >= 0) *hint = worst_at;
  if (worst_at < 0) return std::numeric_limits<double>::infinity();
  if (worst) return largest;
  std::sort(values.begin(), values.end());
  return camera::nearest_rank(values, objective_.statistic == CrbStatistic::kP95 ? 0.95 : 0.50);
}

}  // namespace vantage::design::internal
