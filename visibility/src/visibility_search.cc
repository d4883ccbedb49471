// The branch and bound of docs/math.md §20: the worst viewpoint over the trackable directions of
// a workspace, markers visible per patch by their cones and occlusion grids.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <queue>
#include <sstream>

#include "vantage/analysis/common.h"
#include "vantage/analysis/cube_sphere.h"
#include "vantage/analysis/internal/checks.h"
#include "vantage/sdp/internal/min_norm_point.h"
#include "vantage/sdp/layout_analysis.h"
#include "vantage/sdp/worst_viewpoint.h"
#include "vantage/visibility/visibility.h"
#include "visibility_units.h"

namespace vantage::visibility {
namespace {
// Its own namespace: in a unity batch with the other sources of this module, whose constants
// and helpers of the same names mean the same but are theirs.
namespace search {

using internal::is_mixed;
using internal::Seen;
using internal::sin_plus;
using sdp::internal::min_norm_point;
using sdp::internal::MinNormPoint;

// Initial grid per cube face (kGrid x kGrid patches, six faces: the whole sphere).
constexpr int kGrid = 4;
// Patches whose angular radius is below this are leaves (t is 1-Lipschitz: their bound exceeds
// their values by at most this). Far above the rounding of a patch's radius, so that the
// subdivision always ends.
constexpr double kMinPatchRadius = 1e-10;
// Viewpoints closer than this (1 - a.b) are one optimum.
constexpr double kSameViewpoint = 1e-9;
// Values equal to rounding (min over unit dot products) are ordered lexicographically.
constexpr double kSameValue = 1e-14;
// A circle this close to a patch's bounding cap (in sin of the angle) counts as crossing it.
constexpr double kCrossingSlack = 1e-15;
// Fibonacci directions tried before the branch and bound, for a first attained value.
constexpr int kSeedSamples = 2000;

// The angle between unit vectors, to full precision near 0 and pi.
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool lexicographically_before(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (a.z() != b.z()) return a.z() > b.z();
  if (a.y() != b.y()) return a.y() > b.y();
  return a.x() > b.x();
}

struct Candidate {
  Eigen::Vector3d a;
  double value;
};

class VisibilitySearch {
 public:
  VisibilitySearch(const VisibilityProblem& problem, const VisibilitySearchOptions& options)
      : problem_(problem),
        options_(options),
        n_(static_cast<int>(problem.points.cols())),
        classes_(problem.normals, problem.cos_cone) {
    for (int i = 0; i < n_; ++i) {
      for (int j = i + 1; j < n_; ++j) pairs_.emplace_back(i, j);
    }
    Eigen::Matrix3Xd free(3, static_cast<Eigen::Index>(pairs_.size()));
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      free.col(static_cast<Eigen::Index>(k)) =
          problem.points.col(pairs_[k].second) - problem.points.col(pairs_[k].first);
    }
    u_ = sdp::normalized_columns(free, "points");
    cone_angle_.resize(n_);
    for (int i = 0; i < n_; ++i) cone_angle_[i] = std::acos(problem.cos_cone(i));
    if (problem.workspace) workspace_angle_ = std::acos(problem.workspace->cos_half_angle);
  }

  VisibilityWorstViewpoint run() {
    seed();
    const auto all =
        std::make_shared<const std::vector<Seen>>(static_cast<std::size_t>(n_), Seen::kMixed);
    auto every = std::make_shared<std::vector<int>>(pairs_.size());
    for (std::size_t k = 0; k < pairs_.size(); ++k) (*every)[k] = static_cast<int>(k);
    const double h = 1.0 / kGrid;
    for (int face = 0; face < 6; ++face) {
      for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
          open_.push({face, -1.0 + (2 * i + 1) * h, -1.0 + (2 * j + 1) * h, h, 1.0, all, every});
        }
      }
    }
    // Best first: the patch of largest bound is refined next, so the attained level rises as
    // fast as the bounds allow and no region is refined below what the certificate needs.
    while (!open_.empty()) {
      const Patch patch = open_.top();
      if (level_ >= options_.stop_above) {
        stopped_ = true;
        upper_ = std::max(upper_, patch.bound);
        break;
      }
      if (patch.bound < level_ - options_.tie_tolerance) break;  // every open patch is pruned
      if (patch.bound <= level_ + 0.5 * options_.certificate_tolerance) {
        upper_ = std::max(upper_, patch.bound);  // the largest bound left open
        break;
      }
      if (patches_ >= options_.max_patches) {
        exhausted_ = true;
        upper_ = std::max(upper_, patch.bound);
        break;
      }
      open_.pop();
      process(patch);
    }
    return result();
  }

 private:
  // t at a with the exact visible set, offered when trackable; -1 when not trackable.
  double exact(const Eigen::Vector3d& a) {
    const std::vector<int> visible = visible_at(a);
    if (!trackable(a, visible)) return -1.0;
    const double value = pair_min(visible, a);
    offer(a, value);
    return value;
  }

  std::vector<int> visible_at(const Eigen::Vector3d& a) const {
    std::vector<int> visible;
    for (int i = 0; i < n_; ++i) {
      if (problem_.normals.col(i).dot(a) < problem_.cos_cone(i)) continue;
      if (problem_.occlusion != nullptr &&
          problem_.occlusion->blocked(problem_.occlusion_marker(i), a))
        continue;
      visible.push_back(i);
    }
    return visible;
  }

  bool trackable(const Eigen::Vector3d& a, const std::vector<int>& visible) const {
    if (static_cast<int>(visible.size()) < problem_.min_visible) return false;
    if (problem_.workspace &&
        a.dot(problem_.workspace->axis) < problem_.workspace->cos_half_angle) {
      return false;
    }
    return !collinear(visible);
  }

  // Whether markers (increasing) lie on one line, §20's test (fewer than three: true).
  bool collinear(const std::vector<int>& markers) const {
    if (markers.size() < 3) return true;
    const Eigen::Vector3d first = u_.col(pair_index(markers[0], markers[1]));
    for (std::size_t y = 2; y < markers.size(); ++y) {
      if (u_.col(pair_index(markers[0], markers[y])).cross(first).norm() >
          sdp::kParallelTolerance) {
        return false;
      }
    }
    return true;
  }

  // The column of pair (i, j), i < j, in the lexicographic pair order.
  Eigen::Index pair_index(int i, int j) const {
    return static_cast<Eigen::Index>(i) * n_ - static_cast<Eigen::Index>(i) * (i + 1) / 2 +
           (j - i - 1);
  }

  // The data vectors of the visible markers, in the order of the layout's free vectors.
  Eigen::Matrix3Xd visible_vectors(const std::vector<int>& visible) const {
    Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(visible.size() * (visible.size() - 1) / 2));
    Eigen::Index k = 0;
    for (std::size_t x = 0; x < visible.size(); ++x) {
      for (std::size_t y = x + 1; y < visible.size(); ++y) {
        out.col(k++) = u_.col(pair_index(visible[x], visible[y]));
      }
    }
    return out;
  }

  double pair_min(const std::vector<int>& visible, const Eigen::Vector3d& a) const {
    return sdp::min_abs_projection(visible_vectors(visible), a);
  }

  void offer(const Eigen::Vector3d& a, double value) {
    if (value < level_ - options_.tie_tolerance) return;
    level_ = std::max(level_, value);
    candidates_.push_back({a, value});
  }

  void seed() {
    // Fibonacci directions: a first attained value for the pruning.
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < kSeedSamples; ++k) {
      const double z = 1.0 - (2.0 * k + 1.0) / kSeedSamples;
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      exact(Eigen::Vector3d(r * std::cos(golden * k), r * std::sin(golden * k), z));
    }
  }

  // The optimum of V's sign cell at c (all decided markers visible): offered when attained.
  double solve_cell(const std::vector<int>& visible, const Eigen::Vector3d& c) {
    Eigen::Matrix3Xd points = visible_vectors(visible);
    for (Eigen::Index k = 0; k < points.cols(); ++k) {
      if (points.col(k).dot(c) < 0.0) points.col(k) = -points.col(k);
    }
    ++cells_solved_;
    const MinNormPoint p = min_norm_point(points.data(), static_cast<int>(points.cols()));
    if (p.contains_origin) return 0.0;
    const double t_cell = p.x.norm();
    const Eigen::Vector3d a = p.x / t_cell;
    const std::vector<int> seen = visible_at(a);
    if (seen == visible && trackable(a, seen)) offer(a, pair_min(seen, a));
    return t_cell;
  }

  // A patch of the cube: face, centre (u, v), half-width h, its parent's bound, and the markers'
  // decisions and the pairs that its parent left (shared by the four siblings).
  struct Patch {
    int face;
    double u, v, h, bound;
    std::shared_ptr<const std::vector<Seen>> seen;
    std::shared_ptr<const std::vector<int>> pairs;
    bool operator<(const Patch& other) const { return bound < other.bound; }
  };

  void process(const Patch& patch) {
    ++patches_;
    const int face = patch.face;
    const double u = patch.u, v = patch.v, h = patch.h;
    const std::vector<Seen>& parent = *patch.seen;
    const std::vector<int>& parent_pairs = *patch.pairs;
    const Eigen::Vector3d c = cube_face_direction(face, u, v);
    const double r = cube_patch_radius(u, v, h);
    const double cos_r = std::cos(r), sin_r = std::sin(r);

    if (problem_.workspace && angle_between(c, problem_.workspace->axis) - r > workspace_angle_) {
      return;  // no point of the patch is in the workspace
    }

    std::vector<Seen> seen = parent;
    int possible = 0;
    bool mixed = false;
    for (int i = 0; i < n_; ++i) {
      if (is_mixed(seen[i])) seen[i] = decide(i, c, r, face, u, v, h);
      if (seen[i] != Seen::kHidden) ++possible;
      mixed = mixed || is_mixed(seen[i]);
    }
    if (possible < problem_.min_visible) return;  // nothing here is trackable

    // Bound 2 of §20 over the pairs of certainly visible markers; the crossing test for 3.
    std::vector<int> pairs;
    pairs.reserve(parent_pairs.size());
    double nearest = 1.0;
    for (int k : parent_pairs) {
      const auto [i, j] = pairs_[static_cast<std::size_t>(k)];
      if (seen[i] == Seen::kHidden || seen[j] == Seen::kHidden) continue;
      const double d = std::abs(c.dot(u_.col(k)));
      if (seen[i] == Seen::kVisible && seen[j] == Seen::kVisible) nearest = std::min(nearest, d);
      pairs.push_back(k);
    }
    double bound = std::min(patch.bound, sin_plus(nearest, cos_r, sin_r));
    if (mixed) {
      bound = std::min(bound, internal::needed_mixed_bound(
                                  classes_, problem_.min_visible,
                                  {seen, pairs_, u_, pairs, c, cos_r, sin_r, &collinear_}));
    }
    bound = std::min(bound, off_line_bound(seen, c, cos_r, sin_r));
    if (bound < level_ - options_.tie_tolerance) return;

    exact(c);
    // One visible set and one sign cell on the whole patch (bound 3): the cell's optimum bounds
    // it, whether or not the cell optimum lies in the patch or the workspace.
    if (!mixed && nearest > sin_r + kCrossingSlack) {
      std::vector<int> visible;
      for (int i = 0; i < n_; ++i) {
        if (seen[i] == Seen::kVisible) visible.push_back(i);
      }
      if (static_cast<int>(visible.size()) >= problem_.min_visible) {
        bound = std::min(bound, solve_cell(visible, c));
      }
    }
    if (bound < level_ - options_.tie_tolerance) return;
    if (bound <= level_ + 0.5 * options_.certificate_tolerance || r < kMinPatchRadius) {
      upper_ = std::max(upper_, bound);
      return;
    }

    // Pairs whose least |a.u| over the patch exceeds its bound are the least pair at no
    // trackable point of it (t <= bound there), whatever the sub-patches come to see, and they
    // cross none of it: the sub-patches do without them. (The level would not do: it rises
    // later, and a pair above the level now may be the least pair then.)
    const double keep_below = bound;
    auto kept = std::make_shared<std::vector<int>>();
    kept->reserve(pairs.size());
    for (int k : pairs) {
      const double d = std::abs(c.dot(u_.col(k)));
      const double least = d <= sin_r ? 0.0 : d * cos_r - std::sqrt(1.0 - d * d) * sin_r;
      if (least <= keep_below) kept->push_back(k);
    }
    const auto decided = std::make_shared<const std::vector<Seen>>(std::move(seen));
    const double q = 0.5 * h;
    for (int k = 0; k < 4; ++k) {
      open_.push({face, u + ((k & 1) ? q : -q), v + ((k & 2) ? q : -q), q, bound, decided, kept});
    }
  }

  // Unit direction of the pair {i, j}, i != j, in either order.
  Eigen::Vector3d pair_u(int i, int j) const {
    return u_.col(i < j ? pair_index(i, j) : pair_index(j, i));
  }

  // The largest |a.u_ij| over the patch of centre c.
  double pair_bound(int i, int j, const Eigen::Vector3d& c, double cos_r, double sin_r) const {
    return sin_plus(std::abs(c.dot(pair_u(i, j))), cos_r, sin_r);
  }

  // The bound of collinearity (docs/math.md §20, "The search"): when the markers the patch
  // certainly sees, L (two or more), lie on one line, a trackable direction of the patch also
  // sees a marker m off that line, and then t(a) <= min over l in L of |a.u_lm|. So t <= the
  // largest, over the markers m the patch may see off the line, of min_l sin(asin|c.u_lm| + r);
  // -1 (nothing trackable) when there is no such m. 2 (no bound) when L is not collinear.
  double off_line_bound(const std::vector<Seen>& seen, const Eigen::Vector3d& c, double cos_r,
                        double sin_r) const {
    std::vector<int> certain, possible;
    for (int i = 0; i < n_; ++i) {
      if (seen[i] == Seen::kVisible) certain.push_back(i);
      if (seen[i] != Seen::kHidden) possible.push_back(i);
    }
    // Every marker the patch may see on one line: every visible set is collinear.
    if (collinear(possible)) return -1.0;
    if (certain.size() < 2 || !collinear(certain)) return 2.0;
    const Eigen::Vector3d line = pair_u(certain[0], certain[1]);
    const auto on_line = [&](int i) {
      return pair_u(certain[0], i).cross(line).norm() <= sdp::kParallelTolerance;
    };
    double largest = -1.0;
    std::vector<int> unit;  // m and the markers seen whenever m is (its cone class at the edge)
    for (int m = 0; m < n_; ++m) {
      if (seen[m] == Seen::kHidden || seen[m] == Seen::kVisible || on_line(m)) continue;
      unit.assign(1, m);
      if (seen[m] == Seen::kConeEdge) {
        for (int k = 0; k < n_; ++k) {
          if (k != m && seen[k] == Seen::kConeEdge && classes_.of(k) == classes_.of(m)) {
            unit.push_back(k);
          }
        }
      }
      double least = 1.0;
      for (int y : unit) {
        for (int x : certain) least = std::min(least, pair_bound(x, y, c, cos_r, sin_r));
        for (int x : unit) {
          if (x < y) least = std::min(least, pair_bound(x, y, c, cos_r, sin_r));
        }
      }
      largest = std::max(largest, least);
    }
    return largest;
  }

  // Marker i on the patch of centre c and radius r: certainly visible, hidden or mixed.
  Seen decide(int i, const Eigen::Vector3d& c, double r, int face, double u, double v,
              double h) const {
    bool in_cone = problem_.cos_cone(i) <= -1.0;  // a 180-degree cone sees every direction
    if (!in_cone) {
      const double delta = angle_between(c, problem_.normals.col(i));
      if (delta - r > cone_angle_[i]) return Seen::kHidden;
      in_cone = delta + r <= cone_angle_[i];
    }
    if (problem_.occlusion == nullptr) return in_cone ? Seen::kVisible : Seen::kConeEdge;
    switch (
        problem_.occlusion->span(problem_.occlusion_marker(i), face, u - h, u + h, v - h, v + h)) {
      case OcclusionGrid::Span::kBlocked:
        return Seen::kHidden;
      case OcclusionGrid::Span::kClear:
        return in_cone ? Seen::kVisible : Seen::kConeEdge;
      case OcclusionGrid::Span::kMixed:
        break;
    }
    return Seen::kMixed;
  }

  // The attained optima as reported: each re-solved as its cell's canonical minimum-norm point
  // on the visible pairs (as §14 reports), the best value first.
  VisibilityWorstViewpoint result() {
    VisibilityWorstViewpoint out;
    out.patches = patches_;
    out.cells_solved = cells_solved_;
    if (candidates_.empty()) {
      out.status = VisibilityWorstViewpoint::Status::kUntrackable;
      out.t_upper = 0.0;
      out.message = "no direction of the workspace is trackable";
      return out;
    }
    std::vector<Candidate> optima;
    double best = 0.0;
    for (Candidate c : candidates_) {
      canonical(&c);
      best = std::max(best, c.value);
      optima.push_back(c);
    }
    std::vector<Candidate> distinct;
    for (const Candidate& c : optima) {
      if (c.value < best - options_.tie_tolerance) continue;
      bool duplicate = false;
      for (Candidate& k : distinct) {
        if (1.0 - k.a.dot(c.a) <= kSameViewpoint) {
          duplicate = true;
          if (c.value > k.value) k = c;
        }
      }
      if (!duplicate) distinct.push_back(c);
    }
    std::sort(distinct.begin(), distinct.end(), [&](const Candidate& a, const Candidate& b) {
      const bool a_best = a.value >= best - kSameValue;
      const bool b_best = b.value >= best - kSameValue;
      if (a_best != b_best) return a_best;
      if (!a_best && a.value != b.value) return a.value > b.value;
      return lexicographically_before(a.a, b.a);
    });
    out.viewpoint = distinct.front().a;
    for (const Candidate& c : distinct) out.viewpoints.push_back(c.a);
    out.visible_markers = visible_at(out.viewpoint);
    out.t = pair_min(out.visible_markers, out.viewpoint);
    out.t_lower = out.t;
    out.t_upper = std::max(upper_, out.t);
    out.pbar_min = sdp::pbar_at(visible_vectors(out.visible_markers), out.viewpoint);
    const bool certified =
        !exhausted_ && !stopped_ && out.t_upper - out.t_lower <= options_.certificate_tolerance;
    out.status = certified ? VisibilityWorstViewpoint::Status::kCertified
                           : VisibilityWorstViewpoint::Status::kNotCertified;
    if (stopped_) {
      out.message = "stopped: an attained value reached stop_above";
    } else if (!certified) {
      std::ostringstream message;
      message << "not certified: t_upper - t_lower = " << out.t_upper - out.t_lower << " after "
              << patches_ << " patches";
      out.message = message.str();
    }
    return out;
  }

  // The candidate's cell optimum on every visible pair, when it keeps the visible set and value.
  void canonical(Candidate* c) const {
    const std::vector<int> visible = visible_at(c->a);
    Eigen::Matrix3Xd points = visible_vectors(visible);
    for (Eigen::Index k = 0; k < points.cols(); ++k) {
      if (points.col(k).dot(c->a) < 0.0) points.col(k) = -points.col(k);
    }
    const MinNormPoint p = min_norm_point(points.data(), static_cast<int>(points.cols()));
    if (p.contains_origin) return;
    const Eigen::Vector3d a = p.x / p.x.norm();
    const std::vector<int> seen = visible_at(a);
    if (seen != visible || !trackable(a, seen)) return;
    const double value = pair_min(seen, a);
    if (value >= c->value - kCellExactness) *c = {a, value};
  }

  // A canonical optimum replaces its candidate when it is at least as good to rounding.
  static constexpr double kCellExactness = 1e-12;

  const VisibilityProblem& problem_;
  const VisibilitySearchOptions& options_;
  const int n_;
  const internal::ConeClasses classes_;
  std::vector<std::pair<int, int>> pairs_;
  Eigen::Matrix3Xd u_;
  std::vector<double> cone_angle_;
  double workspace_angle_ = kPi;
  std::vector<Candidate> candidates_;
  // collinear(), as bound 2' asks it.
  const internal::CollinearTest collinear_ = [this](const std::vector<int>& markers) {
    return collinear(markers);
  };
  std::priority_queue<Patch> open_;
  double level_ = -1.0;
  double upper_ = 0.0;
  long patches_ = 0;
  long cells_solved_ = 0;
  bool exhausted_ = false;
  bool stopped_ = false;
};

}  // namespace search
}  // namespace

bool VisibilitySearchOptions::is_valid(std::string* why) const {
  if (!(certificate_tolerance >= 1e-15 && certificate_tolerance <= 1e-3)) {
    return vantage::internal::invalid_option(why, "certificate_tolerance",
                                             "must be in [1e-15, 1e-3]");
  }
  if (!(tie_tolerance >= 0.0 && tie_tolerance <= 1e-3)) {
    return vantage::internal::invalid_option(why, "tie_tolerance", "must be in [0, 1e-3]");
  }
  if (max_patches < 1) return vantage::internal::invalid_option(why, "max_patches", "must be >= 1");
  if (std::isnan(stop_above)) {
    return vantage::internal::invalid_option(why, "stop_above", "must not be NaN");
  }
  return true;
}

const char* to_string(VisibilityWorstViewpoint::Status status) {
  switch (status) {
    case VisibilityWorstViewpoint::Status::kCertified:
      return "certified";
    case VisibilityWorstViewpoint::Status::kNotCertified:
      return "not_certified";
    case VisibilityWorstViewpoint::Status::kUntrackable:
      return "untrackable";
  }
  return "unknown";
}

VisibilityWorstViewpoint visibility_worst_viewpoint(const VisibilityProblem& problem,
                                                    const VisibilitySearchOptions& options) {
  vantage::internal::check_options("options", options);
  problem.validate();
  search::VisibilitySearch search(problem, options);
  return search.run();
}

}  // namespace vantage::visibility
