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
    : problem_(problem),
      options_(options),
      camera_(camera),
      separation_(problem.least_separation()) {}

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
    if ((p.col(s) - p.col(c)).norm() < separation_) return false;
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

namespace {

using Status = visibility::VisibilityWorstViewpoint::Status;

// One member's value against the level: `reaches` when it is known at or above the level (the
// family cannot beat it; `value` is then what the family reports).
struct MemberValue {
  double value = 1.0;
  bool reaches = false;
  Status status = Status::kUntrackable;
};

// The largest member value, stopping at the first member that reaches the level. `value(m, out)`
// evaluates member m and may add its witnesses and searches to `out`.
template <class Value>
FamilyValue worst_member_value(std::size_t members, Value value) {
  FamilyValue out;
  out.t_upper = -1.0;
  for (std::size_t m = 0; m < members; ++m) {
    const MemberValue v = value(m, out);
    if (v.reaches || v.value > out.t_upper) {
      out.t_upper = v.value;
      out.worst_member = static_cast<int>(m);
      out.status = v.status;
    }
    if (v.reaches) return out;
  }
  out.below = true;
  return out;
}

// Some member attains `level` or more at a witness direction (attained(p, w) < 0: not tracked).
template <class Attained>
bool witness_reaches(const std::vector<visibility::VisibilityProblem>& problems,
                     const std::vector<Eigen::Vector3d>& witnesses, double level,
                     Attained attained) {
  for (const Eigen::Vector3d& w : witnesses) {
    for (const visibility::VisibilityProblem& p : problems) {
      if (attained(p, w) >= level) return true;
    }
  }
  return false;
}

// t at the trackable direction a of `p`, or -1 when a is not trackable.
double affine_attained(const visibility::VisibilityProblem& p, const Eigen::Vector3d& a) {
  const visibility::DirectionVisibility seen = visibility::direction_visibility(p, a);
  return seen.trackable ? seen.t : -1.0;
}

// Markers all on one line: a 5-DoF tool to `vantage tre`, but place designs 6-DoF tools (a member
// left collinear by a lost marker gives no pose), so it is tracked nowhere.
bool collinear_member(const visibility::VisibilityProblem& p) {
  Eigen::Vector3d point;
  Eigen::Vector3d axis;
  return tracker::tool_axis(p.points, &point, &axis);
}

// The largest RMS TRE over the targets attained at the tracked direction a of `p` (what tre's
// search attains there), or -1 when a is not tracked.
double tracker_attained(const visibility::VisibilityProblem& p, const TrackerObjective& tracker,
                        const Eigen::Vector3d& a) {
  if (p.points.cols() < p.min_visible) return -1.0;
  const visibility::DirectionVisibility seen = visibility::direction_visibility(p, a);
  if (!seen.trackable) return -1.0;
  double out = -1.0;
  for (const Eigen::Vector3d& target : tracker.targets) {
    const tracker::TreQuadratic q =
        tracker::tre_quadratic(p.points, seen.visible, target, tracker.fle);
    // Place designs 6-DoF tools: a set on one line is no pose (collinear_member()).
    if (!q.registrable || q.registration == tracker::Registration::kOnAxis) return -1.0;
    out = std::max(out, std::sqrt(std::max(0.0, q.rms_squared(a))));
  }
  return out;
}

}  // namespace

std::vector<visibility::VisibilityProblem> PlacementEvaluator::subproblems(
    const std::vector<std::vector<int>>& family) const {
  std::vector<visibility::VisibilityProblem> out;
  out.reserve(family.size());
  for (const std::vector<int>& member : family) out.push_back(subproblem(member));
  return out;
}

FamilyValue PlacementEvaluator::family_t(const std::vector<std::vector<int>>& family, double level,
                                         const std::vector<Eigen::Vector3d>& witnesses,
                                         double tolerance) const {
  if (camera_ != nullptr) return camera_family(family, level);
  if (options_.tracker) return tracker_family(family, level, witnesses);
  const std::vector<visibility::VisibilityProblem> problems = subproblems(family);
  if (witness_reaches(problems, witnesses, level, affine_attained)) return FamilyValue{};
  visibility::VisibilitySearchOptions search = options_.search;
  search.stop_above = level;
  if (tolerance > 0.0) search.certificate_tolerance = tolerance;
  return worst_member_value(problems.size(), [&](std::size_t m, FamilyValue& out) {
    // A member with fewer markers than a direction must see tracks nothing (robust_dropout's
    // losses early in the greedy): no search, t = 1.
    MemberValue v;
    if (problems[m].points.cols() < problems[m].min_visible) {
      v.reaches = !(v.value < level);
      return v;
    }
    const visibility::VisibilityWorstViewpoint r =
        visibility::visibility_worst_viewpoint(problems[m], search);
    ++out.searches;
    v.status = r.status;
    if (r.status == Status::kUntrackable) {
      v.reaches = !(v.value < level);
      return v;
    }
    out.witnesses.push_back(r.viewpoint);
    v.value = r.t_upper;
    if (r.t_upper >= level || r.t_lower >= level) {
      v.value = 1.0;
      v.reaches = true;
    }
    return v;
  });
}

FamilyValue PlacementEvaluator::camera_family(const std::vector<std::vector<int>>& family,
                                              double level) const {
  return worst_member_value(family.size(), [&](std::size_t m, FamilyValue& out) {
    int hint = camera_hint_.load(std::memory_order_relaxed);
    MemberValue v;
    v.value = camera_->value(family[m], level, &hint);
    camera_hint_.store(hint, std::memory_order_relaxed);
    ++out.searches;
    v.status = std::isinf(v.value) ? Status::kUntrackable : Status::kCertified;
    v.reaches = !(v.value < level);
    return v;
  });
}

FamilyValue PlacementEvaluator::tracker_family(
    const std::vector<std::vector<int>>& family, double level,
    const std::vector<Eigen::Vector3d>& witnesses) const {
  const TrackerObjective& tracker = *options_.tracker;
  const std::vector<visibility::VisibilityProblem> problems = subproblems(family);
  const auto attained = [&](const visibility::VisibilityProblem& p, const Eigen::Vector3d& a) {
    return tracker_attained(p, tracker, a);
  };
  if (witness_reaches(problems, witnesses, level, attained)) {
    FamilyValue out;
    out.t_upper = std::numeric_limits<double>::infinity();
    return out;
  }
  tracker::TreSearchOptions search = tracker.search;
  search.stop_above = level;
  return worst_member_value(problems.size(), [&](std::size_t m, FamilyValue& out) {
    // Fewer markers than a direction must see: tracked nowhere (robust_dropout early on).
    MemberValue v;
    v.value = std::numeric_limits<double>::infinity();
    if (problems[m].points.cols() >= problems[m].min_visible && collinear_member(problems[m])) {
      v.status = Status::kUntrackable;
    } else if (problems[m].points.cols() >= problems[m].min_visible) {
      v.status = Status::kCertified;
      v.value = -1.0;
      for (const Eigen::Vector3d& target : tracker.targets) {
        const tracker::TreExtreme worst =
            tracker::tre_worst(problems[m], target, tracker.fle, search);
        ++out.searches;
        if (worst.status == tracker::TreExtreme::Status::kUntracked) {
          v.value = std::numeric_limits<double>::infinity();
          v.status = Status::kUntrackable;
          break;
        }
        out.witnesses.push_back(worst.direction);
        if (!worst.certified()) v.status = Status::kNotCertified;
        v.value = std::max(v.value, worst.rms_bound);
        if (!(v.value < level)) break;
      }
    }
    v.reaches = !(v.value < level);
    return v;
  });
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
