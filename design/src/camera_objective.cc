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
    : objective_(objective),
      model_(objective.sites, objective.model_options()),
      distances_(objective.sample_distances()) {
  for (double distance : distances_) model_.check_distance(distance);
  const Eigen::Matrix3Xd lattice =
      visibility::workspace_lattice(model_.workspace(), objective.crb.samples).directions;
  for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
    // Normalised as `vantage crb` normalises each direction, so that both see the same cameras.
    directions_.push_back(lattice.col(k).normalized());
  }
  const std::size_t n_directions = directions_.size();
  stride_ = n_directions * distances_.size();
  rotations_.resize(stride_);
  translations_.resize(stride_);
  for (std::size_t d = 0; d < stride_; ++d) {
    model_.camera_pose(directions_[d % n_directions], distances_[d / n_directions], &rotations_[d],
                       &translations_[d]);
  }
  min_seen_ = std::max(3, model_.visibility().min_visible());
  const long n = static_cast<long>(objective.sites.entries.cols());
  seen_.assign(static_cast<std::size_t>(n) * stride_, 0);
  const Eigen::Vector3d& aim = model_.centroid();
  parallel_blocks(n, threads, [&](long b, long e) {
    for (long s = b; s < e; ++s) {
      for (std::size_t d = 0; d < stride_; ++d) {
        const Eigen::Vector3d c =
            aim + distances_[d / n_directions] * directions_[d % n_directions];
        seen_[static_cast<std::size_t>(s) * stride_ + d] =
            model_.visibility().visible(static_cast<int>(s), c) ? 1 : 0;
      }
    }
  });
}

camera::PoseCrbAt CameraSiteObjective::at(const std::vector<int>& chosen, int d) const {
  camera::PoseCrbAt out;
  const std::size_t k = static_cast<std::size_t>(d);
  out.direction = directions_[k % directions_.size()];
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
  camera::complete_pose_crb(F, objective_.crb.noise_px, distances_[k / directions_.size()], &out);
  return out;
}

double CameraSiteObjective::value(const std::vector<int>& chosen, double level, int* hint) const {
  if (objective_.statistic == CrbStatistic::kWorst) return worst(chosen, level, hint);
  return percentile(chosen, objective_.statistic == CrbStatistic::kP95 ? 0.95 : 0.50);
}

// The largest first-order value over every sample (the largest over the distances of each
// distance's worst), +inf when some distance has no trackable direction.
double CameraSiteObjective::worst(const std::vector<int>& chosen, double level, int* hint) const {
  const int n = directions();
  const std::size_t lattice = directions_.size();
  std::vector<char> tracked(distances_.size(), 0);
  int worst_at = -1;
  double largest = -1.0;
  const int first = hint != nullptr && *hint >= 0 && *hint < n ? *hint : 0;
  for (int step = 0; step < n; ++step) {
    const int d = (first + step) % n;
    // The first-order value ranks past the reporting limit too (a 200 deg layout is better
    // than a 6 000 deg one, though neither is a figure: docs/math.md §21, "Objectives").
    const double rot_rms_deg = this->at(chosen, d).first_order_rot_rms_deg;
    if (!std::isfinite(rot_rms_deg)) continue;
    tracked[static_cast<std::size_t>(d) / lattice] = 1;
    if (rot_rms_deg > largest) {
      largest = rot_rms_deg;
      worst_at = d;
    }
    if (largest >= level) break;
  }
  if (hint != nullptr && worst_at >= 0) *hint = worst_at;
  if (worst_at < 0) return std::numeric_limits<double>::infinity();
  if (largest >= level) return largest;  // stopped early: some value >= level
  const bool every_distance = std::all_of(tracked.begin(), tracked.end(), [](char t) { return t; });
  return every_distance ? largest : std::numeric_limits<double>::infinity();
}

// The largest over the distances of the nearest-rank q-quantile of the trackable directions.
double CameraSiteObjective::percentile(const std::vector<int>& chosen, double q) const {
  const std::size_t lattice = directions_.size();
  double out = -1.0;
  for (std::size_t k = 0; k < distances_.size(); ++k) {
    std::vector<double> values;
    for (std::size_t d = 0; d < lattice; ++d) {
      const double rot_rms_deg =
          this->at(chosen, static_cast<int>(k * lattice + d)).first_order_rot_rms_deg;
      if (std::isfinite(rot_rms_deg)) values.push_back(rot_rms_deg);
    }
    if (values.empty()) return std::numeric_limits<double>::infinity();
    std::sort(values.begin(), values.end());
    out = std::max(out, camera::nearest_rank(values, q));
  }
  return out;
}

}  // namespace vantage::design::internal
