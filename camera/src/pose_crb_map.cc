// The pose CRB over the viewpoint sphere (docs/math.md §22, "Sampling"): Fibonacci directions,
// the worst and best refined by compass search, percentiles, the sliver probe, distance sweeps.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

#include "vantage/analysis/common.h"
#include "vantage/analysis/parallel.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/visibility/visibility.h"
#include "vantage/visibility/workspace_lattice.h"

namespace vantage::camera {

namespace crb_sampling {

// Compass search stops when its step (radians) is below this: 1e-5 rad is 0.6 arcsec, far
// below any visibility or noise scale.
constexpr double kRefineMinStep = 1e-5;
// Steps of the sliver probe along each cut: fine up to kSliverWidthDeg, then coarse.
constexpr double kSliverFineStepDeg = 0.02;
constexpr double kSliverCoarseStepDeg = 0.25;

// Two unit vectors spanning the tangent plane at a.
void tangent_basis(const Eigen::Vector3d& a, Eigen::Vector3d* u, Eigen::Vector3d* v) {
  Eigen::Index k = 0;
  a.cwiseAbs().minCoeff(&k);
  *u = a.cross(Eigen::Vector3d::Unit(k)).normalized();
  *v = a.cross(*u);
}

// The point at angle `angle` (radians) from a along tangent direction t.
Eigen::Vector3d along(const Eigen::Vector3d& a, const Eigen::Vector3d& t, double angle) {
  return (std::cos(angle) * a + std::sin(angle) * t).normalized();
}

// Whether the worst may sit at `at`: the first-order bound exists there (trackable, or unbounded
// past the rot_rms limit; not where F is singular).
bool ranked(const PoseCrbAt& at) { return std::isfinite(at.first_order_rot_rms_deg); }

// Compass search on the sphere from `start`, first step `step` radians: for the largest
// first-order rot_rms among ranked directions (sign +1; it stops once past the limit, where the
// worst is unbounded), or the smallest rot_rms among trackable ones (sign -1).
PoseCrbAt refine(const PoseCrbModel& model, double distance, const PoseCrbAt& start, double step,
                 double sign) {
  PoseCrbAt best = start;
  // A workspace narrower than the lattice of the whole sphere has a finer spacing.
  const double min_step = std::min(kRefineMinStep, step / 100.0);
  while (step > min_step && !best.unbounded) {
    Eigen::Vector3d u, v;
    tangent_basis(best.direction, &u, &v);
    bool moved = false;
    for (const Eigen::Vector3d& t : {u, v, Eigen::Vector3d(-u), Eigen::Vector3d(-v)}) {
      PoseCrbAt next = model.at(along(best.direction, t, step), distance);
      const bool admitted = sign > 0 ? ranked(next) : next.trackable;
      if (admitted && sign * next.first_order_rot_rms_deg > sign * best.first_order_rot_rms_deg) {
        best = std::move(next);
        moved = true;
        break;
      }
    }
    if (!moved) step *= 0.5;
  }
  return best;
}

// How far (degrees) from the worst direction along t the first-order bound stays >= half of the
// worst (of the rot_rms limit when the worst is unbounded), and whether the cut left the
// workspace first (then the workspace ends it, not the bound).
struct Reach {
  double deg = 0.0;
  bool workspace_edge = false;
};
Reach half_bound_reach(const PoseCrbModel& model, double distance, const PoseCrbAt& worst,
                       const Eigen::Vector3d& t) {
  const double half = 0.5 * std::min(worst.first_order_rot_rms_deg, PoseCrbAt::kMaxRotRmsDeg);
  Reach reach;
  for (double deg = kSliverFineStepDeg; deg <= PoseCrbMap::kMaxSliverProbeDeg + 1e-12;
       deg += deg < PoseCrbMap::kSliverWidthDeg ? kSliverFineStepDeg : kSliverCoarseStepDeg) {
    const Eigen::Vector3d a = along(worst.direction, t, deg / kDegreesPerRadian);
    if (!model.in_workspace(a)) {
      reach.workspace_edge = true;
      break;
    }
    const PoseCrbAt at = model.at(a, distance);
    if (!ranked(at) || at.first_order_rot_rms_deg < half) break;
    reach.deg = deg;
  }
  return reach;
}

// The narrowest of four cuts (0, 45, 90, 135 degrees in the tangent plane) through the worst.
double worst_region_width_deg(const PoseCrbModel& model, double distance, const PoseCrbAt& worst,
                              bool* fills_workspace) {
  Eigen::Vector3d u, v;
  tangent_basis(worst.direction, &u, &v);
  double narrowest = 2.0 * PoseCrbMap::kMaxSliverProbeDeg;
  *fills_workspace = true;
  for (int k = 0; k < 4; ++k) {
    const double phi = k * kPi / 4.0;
    const Eigen::Vector3d t = std::cos(phi) * u + std::sin(phi) * v;
    const Reach ahead = half_bound_reach(model, distance, worst, t);
    const Reach behind = half_bound_reach(model, distance, worst, -t);
    // A cut the workspace ends on both sides says nothing of the bound's region.
    if (ahead.workspace_edge && behind.workspace_edge) continue;
    *fills_workspace = false;
    narrowest = std::min(narrowest, ahead.deg + behind.deg);
  }
  return narrowest;
}

// Indices of the samples that `admit`, by first-order rot_rms increasing (ties by index).
template <typename Admit>
std::vector<int> by_bound(const std::vector<PoseCrbAt>& samples, Admit admit) {
  std::vector<int> order;
  for (int k = 0; k < static_cast<int>(samples.size()); ++k) {
    if (admit(samples[k])) order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return samples[a].first_order_rot_rms_deg < samples[b].first_order_rot_rms_deg;
  });
  return order;
}

// Indices of the trackable samples, by rot_rms_deg increasing (ties by index).
std::vector<int> trackable_by_bound(const std::vector<PoseCrbAt>& samples) {
  return by_bound(samples, [](const PoseCrbAt& at) { return at.trackable; });
}

std::vector<PoseCrbAt> sample_workspace(const PoseCrbModel& model, double distance,
                                        const Eigen::Matrix3Xd& all) {
  std::vector<PoseCrbAt> samples(static_cast<std::size_t>(all.cols()));
  parallel_blocks(static_cast<long>(all.cols()), model.options().threads,
                  [&](long begin, long end) {
                    for (long k = begin; k < end; ++k) samples[k] = model.at(all.col(k), distance);
                  });
  return samples;
}

// The best of the refinements from the `starts` extreme samples of `order` (sign +1: from the
// largest, -1: from the smallest).
PoseCrbAt refined_extreme(const PoseCrbModel& model, double distance,
                          const std::vector<PoseCrbAt>& samples, const std::vector<int>& order,
                          double sign, double step) {
  const int starts = std::min<int>(model.options().refine_starts, static_cast<int>(order.size()));
  PoseCrbAt best;
  for (int s = 0; s < starts; ++s) {
    const int k = sign > 0 ? order[order.size() - 1 - s] : order[s];
    PoseCrbAt refined = refine(model, distance, samples[k], step, sign);
    if (s == 0 || sign * refined.first_order_rot_rms_deg > sign * best.first_order_rot_rms_deg) {
      best = std::move(refined);
    }
  }
  return best;
}

}  // namespace crb_sampling

double nearest_rank(const std::vector<double>& sorted, double q) {
  const auto n = static_cast<double>(sorted.size());
  const auto rank = static_cast<std::size_t>(std::max(1.0, std::ceil(q * n)));
  return sorted[std::min(sorted.size(), rank) - 1];
}

const char* to_string(PoseCrbMap::Status status) {
  switch (status) {
    case PoseCrbMap::Status::kOk:
      return "ok";
    case PoseCrbMap::Status::kUntrackable:
      return "untrackable";
    case PoseCrbMap::Status::kIllConditioned:
      return "ill_conditioned";
    case PoseCrbMap::Status::kUnbounded:
      return "unbounded";
  }
  return "untrackable";
}

std::string untrackable_reason(const PoseCrbMap& map, double distance) {
  switch (map.status) {
    case PoseCrbMap::Status::kOk:
      return "";
    case PoseCrbMap::Status::kUntrackable:
      return "no sampled direction of the workspace sees enough markers (" +
             std::to_string(map.samples.size()) + " sampled)";
    case PoseCrbMap::Status::kIllConditioned:
      break;
    case PoseCrbMap::Status::kUnbounded: {
      static_assert(PoseCrbAt::kMaxRotRmsDeg == 45.0, "the sentence below quotes it");
      const auto unbounded = std::count_if(map.samples.begin(), map.samples.end(),
                                           [](const PoseCrbAt& at) { return at.unbounded; });
      std::ostringstream out;
      out << unbounded << " of the " << map.samples.size()
          << " sampled directions of the workspace see enough markers, but at each the "
             "first-order bound is unbounded (rot_rms above 45 deg, or the Fisher information "
             "singular) at distance "
          << distance;
      return out.str();
    }
  }
  static_assert(PoseCrbAt::kMaxCondition == 1e12, "the sentence below quotes it");
  const auto ill = std::count_if(map.samples.begin(), map.samples.end(),
                                 [](const PoseCrbAt& at) { return at.ill_conditioned; });
  std::ostringstream out;
  out << ill << " of the " << map.samples.size()
      << " sampled directions of the workspace see enough markers, but at each the Fisher "
         "information's condition number exceeds "
      << "1e12: the pose is not determined to first order at distance " << distance
      << " (the markers subtend too small an angle, or are degenerate)";
  return out.str();
}

PoseCrbMap pose_crb_map(const PoseCrbModel& model) {
  return pose_crb_map(model, model.options().distance);
}

PoseCrbMap pose_crb_map(const PoseCrbModel& model, double distance) {
  using namespace crb_sampling;
  PoseCrbMap map;
  const visibility::WorkspaceLattice lattice =
      visibility::workspace_lattice(model.workspace(), model.options().samples);
  map.samples = sample_workspace(model, distance, lattice.directions);
  const std::vector<int> order = trackable_by_bound(map.samples);
  const auto unbounded = std::count_if(map.samples.begin(), map.samples.end(),
                                       [](const PoseCrbAt& at) { return at.unbounded; });
  map.unbounded_fraction = static_cast<double>(unbounded) / static_cast<double>(map.samples.size());
  if (order.empty()) {
    const bool ill = std::any_of(map.samples.begin(), map.samples.end(),
                                 [](const PoseCrbAt& at) { return at.ill_conditioned; });
    const bool past_limit =
        std::any_of(map.samples.begin(), map.samples.end(),
                    [](const PoseCrbAt& at) { return at.unbounded && !at.ill_conditioned; });
    if (past_limit) {
      map.status = PoseCrbMap::Status::kUnbounded;
    } else if (ill) {
      map.status = PoseCrbMap::Status::kIllConditioned;
    }
    return map;
  }
  map.status = PoseCrbMap::Status::kOk;
  map.trackable_fraction =
      static_cast<double>(order.size()) / static_cast<double>(map.samples.size());
  std::vector<double> sorted(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = map.samples[order[k]].rot_rms_deg;
  map.percentiles = {nearest_rank(sorted, 0.50), nearest_rank(sorted, 0.95),
                     nearest_rank(sorted, 0.99)};
  // The worst starts from every direction where the first-order bound exists, unbounded ones
  // included: the worst is unbounded when the bound passes its limit anywhere it is reached.
  const std::vector<int> ranked_order = by_bound(map.samples, ranked);
  map.worst = refined_extreme(model, distance, map.samples, ranked_order, +1.0, lattice.spacing);
  // A sampled direction of the workspace that sees enough markers but whose F is singular has
  // no finite bound: the worst is unbounded there.
  if (!map.worst.unbounded) {
    const auto singular = std::find_if(map.samples.begin(), map.samples.end(),
                                       [](const PoseCrbAt& at) { return at.ill_conditioned; });
    if (singular != map.samples.end()) map.worst = *singular;
  }
  map.best = refined_extreme(model, distance, map.samples, order, -1.0, lattice.spacing);
  map.worst_region_width_deg =
      worst_region_width_deg(model, distance, map.worst, &map.worst_region_fills_workspace);
  map.sliver = map.worst_region_width_deg < PoseCrbMap::kSliverWidthDeg;
  return map;
}

std::vector<PoseCrbSweepRow> pose_crb_distance_sweep(const PoseCrbModel& model, double d1,
                                                     double d2, int count,
                                                     const CrbProgress& progress) {
  if (count < 2 || !(d1 < d2) || !(d2 <= PoseCrbOptions::kMaxLength) || !(d1 > model.radius()) ||
      !(d1 >= PoseCrbOptions::kMinLength)) {
    throw InvalidArgument("sweep_distance", "needs D1 < D2, both above the layout's radius " +
                                                std::to_string(model.radius()) +
                                                " and in [1e-50, 1e50], and N >= 2");
  }
  std::vector<PoseCrbSweepRow> rows;
  for (int k = 0; k < count; ++k) {
    if (progress) progress("distance " + std::to_string(k + 1) + "/" + std::to_string(count));
    PoseCrbSweepRow row;
    row.distance = d1 + k * (d2 - d1) / (count - 1);
    PoseCrbMap map = pose_crb_map(model, row.distance);
    row.status = map.status;
    row.trackable_fraction = map.trackable_fraction;
    row.unbounded_fraction = map.unbounded_fraction;
    if (map.status == PoseCrbMap::Status::kOk) {
      row.worst = map.worst;
      const std::vector<int> order = crb_sampling::trackable_by_bound(map.samples);
      row.median = map.samples[order[(order.size() - 1) / 2]];
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace vantage::camera
