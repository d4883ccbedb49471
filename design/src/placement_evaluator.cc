// The certified worst case of a choice of sites against a level (docs/math.md §21).

#include "placement_evaluator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vantage/tracker/identification.h"
#include "vantage/tracker/target_registration.h"
#include "vantage/tracker/tre_search.h"

namespace vantage::design::internal {

PlacementEvaluator::PlacementEvaluator(const PlacementProblem& problem, const PlaceOptions& options,
                                       const CameraSiteObjective* camera)
    : problem_(problem), options_(options), camera_(camera) {}

visibility::VisibilityProblem PlacementEvaluator::subproblem(const std::vector<int>& chosen) const {
  const visibility::VisibilityProblem& all = problem_.sites;
  visibility::VisibilityProblem out;
  const Eigen::Index n = static_cast<Eigen::Index>(chosen.size());
  out.points.resize(3, n);
  out.normals.resize(3, n);
  out.cos_cone.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int s = chosen[static_cast<std::size_t>(k)];
    out.points.col(k) = all.points.col(s);
    out.normals.col(k) = all.normals.col(s);
    out.cos_cone(k) = all.cos_cone(s);
  }
  out.min_visible = all.min_visible;
  out.workspace = all.workspace;
  out.occlusion = all.occlusion;
  if (all.occlusion != nullptr) {
    for (int s : chosen) out.occlusion_markers.push_back(all.occlusion_marker(s));
  }
  return out;
}

bool PlacementEvaluator::feasible(const std::vector<int>& chosen) const {
  for (std::size_t k = 1; k < chosen.size(); ++k) {
    const std::vector<int> before(chosen.begin(), chosen.begin() + static_cast<long>(k));
    if (!feasible_with(before, chosen[k])) return false;
  }
  return true;
}

bool PlacementEvaluator::feasible_with(const std::vector<int>& chosen, int c) const {
  const Eigen::Matrix3Xd& p = problem_.sites.points;
  for (int s : chosen) {
    if ((p.col(s) - p.col(c)).norm() < problem_.min_separation) return false;
  }
  const double gap = problem_.min_distance_difference;
  if (!(gap > 0.0)) return true;
  Eigen::Matrix3Xd markers(3, static_cast<Eigen::Index>(chosen.size()) + 1);
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    markers.col(static_cast<Eigen::Index>(k)) = p.col(chosen[k]);
  }
  markers.col(markers.cols() - 1) = p.col(c);
  return tracker::min_distance_difference(markers).value >= gap;
}

FamilyValue PlacementEvaluator::family_t(const std::vector<std::vector<int>>& family, double level,
                                         const std::vector<Eigen::Vector3d>& witnesses,
                                         double tolerance) const {
  if (camera_ != nullptr) return camera_family(family, level);
  if (options_.tracker) return tracker_family(family, level, witnesses);
  FamilyValue out;
  std::vector<visibility::VisibilityProblem> problems;
  problems.reserve(family.size());
  for (const std::vector<int>& member : family) problems.push_back(subproblem(member));
  // A trackable witness at or above the level is an attained value: the family cannot beat it.
  for (const Eigen::Vector3d& w : witnesses) {
    for (const visibility::VisibilityProblem& p : problems) {
      const visibility::DirectionVisibility seen = visibility::direction_visibility(p, w);
      if (seen.trackable && seen.t >= level) return out;
    }
  }
  visibility::VisibilitySearchOptions search = options_.search;
  search.stop_above = level;
  if (tolerance > 0.0) search.certificate_tolerance = tolerance;
  out.t_upper = -1.0;
  for (std::size_t m = 0; m < problems.size(); ++m) {
    // A member with fewer markers than a direction must see tracks nothing (robust_dropout's
    // losses early in the greedy): no search, t = 1.
    const bool too_few = problems[m].points.cols() < problems[m].min_visible;
    visibility::VisibilityWorstViewpoint r;
    r.status = visibility::VisibilityWorstViewpoint::Status::kUntrackable;
    if (!too_few) {
      r = visibility::visibility_worst_viewpoint(problems[m], search);
      ++out.searches;
    }
    const bool untrackable = r.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable;
    if (!untrackable) out.witnesses.push_back(r.viewpoint);
    const double t = untrackable ? 1.0 : r.t_upper;
    if (t >= level || (!untrackable && r.t_lower >= level)) {
      out.t_upper = 1.0;
      return out;
    }
    if (t > out.t_upper) {
      out.t_upper = t;
      out.worst_member = static_cast<int>(m);
      out.status = r.status;
    }
  }
  out.below = true;
  return out;
}

FamilyValue PlacementEvaluator::camera_family(const std::vector<std::vector<int>>& family,
                                              double level) const {
  FamilyValue out;
  out.t_upper = -1.0;
  for (std::size_t m = 0; m < family.size(); ++m) {
    int hint = camera_hint_.load(std::memory_order_relaxed);
    const double value = camera_->value(family[m], level, &hint);
    camera_hint_.store(hint, std::memory_order_relaxed);
    ++out.searches;
    if (!(value < level)) {
      out.t_upper = value;
      out.worst_member = static_cast<int>(m);
      return out;
    }
    if (value > out.t_upper) {
      out.t_upper = value;
      out.worst_member = static_cast<int>(m);
      out.status = visibility::VisibilityWorstViewpoint::Status::kCertified;
    }
  }
  out.below = true;
  return out;
}

namespace {

// The largest RMS TRE over the targets attained at the tracked direction a of `p` (what tre's
// search attains there), or -1 when a is not tracked.
double tracker_attained(const visibility::VisibilityProblem& p, const TrackerObjective& tracker,
                        const Eigen::Vector3d& a) {
  const visibility::DirectionVisibility seen = visibility::direction_visibility(p, a);
  if (!seen.trackable) return -1.0;
  double out = -1.0;
  for (const Eigen::Vector3d& target : tracker.targets) {
    const tracker::TreQuadratic q =
        tracker::tre_quadratic(p.points, seen.visible, target, tracker.fle);
    if (!q.registrable) return -1.0;
    out = std::max(out, std::sqrt(std::max(0.0, q.rms_squared(a))));
  }
  return out;
}

}  // namespace

FamilyValue PlacementEvaluator::tracker_family(
    const std::vector<std::vector<int>>& family, double level,
    const std::vector<Eigen::Vector3d>& witnesses) const {
  const TrackerObjective& tracker = *options_.tracker;
  FamilyValue out;
  std::vector<visibility::VisibilityProblem> problems;
  problems.reserve(family.size());
  for (const std::vector<int>& member : family) problems.push_back(subproblem(member));
  // An attained value at or above the level: the family cannot beat it.
  for (const Eigen::Vector3d& w : witnesses) {
    for (const visibility::VisibilityProblem& p : problems) {
      if (p.points.cols() >= p.min_visible && tracker_attained(p, tracker, w) >= level) {
        out.t_upper = std::numeric_limits<double>::infinity();
        return out;
      }
    }
  }
  tracker::TreSearchOptions search = tracker.search;
  search.stop_above = level;
  out.t_upper = -1.0;
  for (std::size_t m = 0; m < problems.size(); ++m) {
    // Fewer markers than a direction must see: tracked nowhere (robust_dropout early on).
    double value = std::numeric_limits<double>::infinity();
    auto status = visibility::VisibilityWorstViewpoint::Status::kUntrackable;
    if (problems[m].points.cols() >= problems[m].min_visible) {
      status = visibility::VisibilityWorstViewpoint::Status::kCertified;
      value = -1.0;
      for (const Eigen::Vector3d& target : tracker.targets) {
        const tracker::TreExtreme worst =
            tracker::tre_worst(problems[m], target, tracker.fle, search);
        ++out.searches;
        if (worst.status == tracker::TreExtreme::Status::kUntracked) {
          value = std::numeric_limits<double>::infinity();
          status = visibility::VisibilityWorstViewpoint::Status::kUntrackable;
          break;
        }
        out.witnesses.push_back(worst.direction);
        if (!worst.certified())
          status = visibility::VisibilityWorstViewpoint::Status::kNotCertified;
        value = std::max(value, worst.rms_bound);
        if (!(value < level)) break;
      }
    }
    if (!(value < level)) {
      out.t_upper = value;
      out.worst_member = static_cast<int>(m);
      out.status = status;
      return out;
    }
    if (value > out.t_upper) {
      out.t_upper = value;
      out.worst_member = static_cast<int>(m);
      out.status = status;
    }
  }
  out.below = true;
  return out;
}

std::vector<int> without_position(const std::vector<int>& chosen, std::size_t m) {
  std::vector<int> out;
  out.reserve(chosen.size() - 1);
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    if (k != m) out.push_back(chosen[k]);
  }
  return out;
}

}  // namespace vantage::design::internal
