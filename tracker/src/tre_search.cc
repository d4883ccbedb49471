// The branch and bound of docs/math.md §23 ("Worst and best"): best first over cube-sphere
// patches, each bounded over every visible set it allows by the cap bound of the quadratic.

#include "vantage/tracker/tre_search.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>

#include "vantage/analysis/common.h"
#include "vantage/analysis/cube_sphere.h"
#include "vantage/visibility/internal/cone_classes.h"

namespace vantage::tracker {
namespace {

constexpr int kTreMaxMarkers = 63;  // visible sets are bit masks of a 64-bit word
constexpr double kTreInfinity = std::numeric_limits<double>::infinity();
// A patch that meets at most this many cells of the occlusion grid is bounded cell by cell
// (TreSearch::decide): at most 2 x 2 once patches are no wider than a cell.
constexpr int kMaxPieces = 4;

enum class TreSeen : std::uint8_t { kVisible, kHidden, kConeEdge, kMixed };

// s * (c + a^T M a) for one visible set, with the eigenvalues of s * M.
struct TreObjective {
  bool registrable = false;
  double c = 0.0;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  double lambda_max = 0.0;
  Eigen::Vector3d top = Eigen::Vector3d::UnitZ();
};

// The cap bound of §23 for a . M a + c over the patch (centre c0, radius r < pi/2), and the
// point where the sinusoid peaks.
double tre_cap_bound(const TreObjective& f, const Eigen::Vector3d& c0, double r,
                     Eigen::Vector3d* peak) {
  const Eigen::Vector3d Mc = f.M * c0;
  const double fc = c0.dot(Mc);
  Eigen::Vector3d tangent = Mc - fc * c0;
  double g = tangent.norm();
  if (g > 0.0) {
    tangent /= g;
  } else {
    tangent = f.top - f.top.dot(c0) * c0;
    if (tangent.norm() == 0.0) tangent = c0.unitOrthogonal();
    tangent.normalize();
    g = 0.0;
  }
  const double mean = 0.5 * (fc + f.lambda_max);
  const double p = 0.5 * (fc - f.lambda_max);
  const double amplitude = std::hypot(p, g);
  const double phase = std::atan2(g, p);  // in [0, pi]
  const double x = std::min(phase, 2.0 * r);
  *peak = (std::cos(0.5 * x) * c0 + std::sin(0.5 * x) * tangent).normalized();
  const double value =
      phase <= 2.0 * r ? mean + amplitude : mean + p * std::cos(x) + g * std::sin(x);
  return f.c + value;
}

class TreSearch {
 public:
  TreSearch(const visibility::VisibilityProblem& problem, const Eigen::Vector3d& target,
            const FleModel& fle, double sign, const TreSearchOptions& options)
      : problem_(problem),
        target_(target),
        fle_(fle),
        sign_(sign),
        options_(options),
        n_(static_cast<int>(problem.points.cols())),
        classes_(problem.normals, problem.cos_cone) {
    cone_angle_.resize(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i)
      cone_angle_[static_cast<std::size_t>(i)] = std::acos(problem.cos_cone(i));
    if (problem.workspace) workspace_angle_ = std::acos(problem.workspace->cos_half_angle);
  }

  TreExtreme run() {
    for (int face = 0; face < 6; ++face) open_.push({face, 0.0, 0.0, 1.0, kTreInfinity});
    while (!open_.empty()) {
      const Patch patch = open_.top();
      if (have_best_ && patch.bound <= best_value_ + tolerance()) break;
      if (stopped_above()) {
        exhausted_ = true;
        break;
      }
      if (patches_ >= options_.max_patches) {
        exhausted_ = true;
        break;
      }
      open_.pop();
      ++patches_;
      expand(patch);
    }
    return result();
  }

 private:
  struct Patch {
    int face;
    double u, v, h;
    double bound;
    bool operator<(const Patch& other) const { return bound < other.bound; }
  };

  // The worst's search has attained options.stop_above: the caller needs no more.
  bool stopped_above() const {
    return sign_ > 0.0 && have_best_ &&
           std::sqrt(std::max(0.0, best_value_)) >= options_.stop_above;
  }

  // The tolerance in the objective s * RMS^2 for relative_tolerance in the RMS.
  double tolerance() const { return 2.0 * options_.relative_tolerance * std::abs(best_value_); }

  const TreObjective& objective(std::uint64_t mask) {
    auto found = cache_.find(mask);
    if (found != cache_.end()) return found->second;
    std::vector<int> visible;
    for (int i = 0; i < n_; ++i) {
      if (mask >> i & 1u) visible.push_back(i);
    }
    const TreQuadratic q = tre_quadratic(problem_.points, visible, target_, fle_);
    TreObjective f;
    f.registrable = q.registrable;
    f.c = sign_ * q.c;
    f.M = sign_ * q.M;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(f.M);
    f.lambda_max = eigen.eigenvalues()(2);
    f.top = eigen.eigenvectors().col(2);
    return cache_.emplace(mask, f).first->second;
  }

  void attain(const Eigen::Vector3d& a) {
    const visibility::DirectionVisibility seen = visibility::direction_visibility(problem_, a);
    if (!seen.trackable) return;
    std::uint64_t mask = 0;
    for (int i : seen.visible) mask |= std::uint64_t{1} << i;
    const TreObjective& f = objective(mask);
    if (!f.registrable) return;
    const double value = f.c + a.dot(f.M * a);
    if (!have_best_ || value > best_value_) {
      have_best_ = true;
      best_value_ = value;
      best_direction_ = a;
      best_visible_ = seen.visible;
    }
  }

  // Marker i on the patch's cap by its cone alone: visible, hidden or at the cone's edge.
  TreSeen decide_cone(int i, const Eigen::Vector3d& c, double r) const {
    if (problem_.cos_cone(i) <= -1.0) return TreSeen::kVisible;
    const double delta =
        std::atan2(c.cross(problem_.normals.col(i)).norm(), c.dot(problem_.normals.col(i)));
    if (delta - r > cone_angle_[static_cast<std::size_t>(i)]) return TreSeen::kHidden;
    return delta + r <= cone_angle_[static_cast<std::size_t>(i)] ? TreSeen::kVisible
                                                                 : TreSeen::kConeEdge;
  }

  // The cone's decisions with the occlusion grid's span of the whole patch.
  std::vector<TreSeen> decide_spanned(const std::vector<TreSeen>& cone, const Patch& p) const {
    std::vector<TreSeen> seen = cone;
    for (int i = 0; i < n_; ++i) {
      TreSeen& s = seen[static_cast<std::size_t>(i)];
      if (s == TreSeen::kHidden) continue;
      switch (problem_.occlusion->span(problem_.occlusion_marker(i), p.face, p.u - p.h, p.u + p.h,
                                       p.v - p.h, p.v + p.h)) {
        case OcclusionGrid::Span::kBlocked:
          s = TreSeen::kHidden;
          break;
        case OcclusionGrid::Span::kClear:
          break;
        case OcclusionGrid::Span::kMixed:
          s = TreSeen::kMixed;
          break;
      }
    }
    return seen;
  }

  // The markers' decisions on the patch: one vector for the whole patch, or, when the patch
  // meets at most kMaxPieces cells of the occlusion grid, one per cell, each with that cell's
  // flags. Every direction of the patch lies in one of the cells and is seen as its cell says,
  // so the largest of the pieces' bounds bounds the patch; a marker blocked in one cell and clear
  // in the next is then never counted as hidden together with another marker that is hidden only
  // in the first (a combination no direction has, whose bound would never close).
  std::vector<std::vector<TreSeen>> decide(const Eigen::Vector3d& c, double r,
                                           const Patch& p) const {
    std::vector<TreSeen> cone(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) cone[static_cast<std::size_t>(i)] = decide_cone(i, c, r);
    if (problem_.occlusion == nullptr) return {cone};
    const OcclusionGrid::Cells cells =
        problem_.occlusion->cells(p.u - p.h, p.u + p.h, p.v - p.h, p.v + p.h);
    if ((cells.i1 - cells.i0 + 1) * (cells.j1 - cells.j0 + 1) > kMaxPieces) {
      return {decide_spanned(cone, p)};
    }
    std::vector<std::vector<TreSeen>> pieces;
    for (int i = cells.i0; i <= cells.i1; ++i) {
      for (int j = cells.j0; j <= cells.j1; ++j) {
        std::vector<TreSeen> seen = cone;
        for (int m = 0; m < n_; ++m) {
          if (problem_.occlusion->blocked_cell(problem_.occlusion_marker(m), p.face, i, j)) {
            seen[static_cast<std::size_t>(m)] = TreSeen::kHidden;
          }
        }
        pieces.push_back(std::move(seen));
      }
    }
    return pieces;
  }

  // A unit of mixed markers, seen whole or not at all (§20): one marker mixed by the body, or the
  // markers of one cone class mixed at their cone's edge only.
  struct Unit {
    std::uint64_t mask = 0;
    int cone_class = -1;  ///< the class of a cone-edge unit, -1 for a marker mixed by the body
  };

  std::vector<Unit> units(const std::vector<TreSeen>& seen) const {
    std::vector<Unit> out;
    for (int i = 0; i < n_; ++i) {
      const TreSeen s = seen[static_cast<std::size_t>(i)];
      const std::uint64_t bit = std::uint64_t{1} << i;
      if (s == TreSeen::kMixed) out.push_back({bit, -1});
      if (s != TreSeen::kConeEdge) continue;
      const int k = classes_.of(i);
      const auto same =
          std::find_if(out.begin(), out.end(), [k](const Unit& u) { return u.cone_class == k; });
      if (same != out.end()) {
        same->mask |= bit;
      } else {
        out.push_back({bit, k});
      }
    }
    return out;
  }

  // Pairs of choice bits (units) that cannot both be hidden: cone-edge units whose cones' hidden
  // sides do not meet, so that every direction sees one of them.
  std::vector<std::uint64_t> apart_pairs(const std::vector<Unit>& mixed) const {
    std::vector<std::uint64_t> out;
    for (std::size_t x = 0; x < mixed.size(); ++x) {
      for (std::size_t y = x + 1; y < mixed.size(); ++y) {
        const int a = mixed[x].cone_class, b = mixed[y].cone_class;
        if (a >= 0 && b >= 0 && classes_.hidden_apart(a, b)) {
          out.push_back(std::uint64_t{1} << x | std::uint64_t{1} << y);
        }
      }
    }
    return out;
  }

  void expand(const Patch& p) {
    const Eigen::Vector3d c = cube_face_direction(p.face, p.u, p.v);
    const double r = cube_patch_radius(p.u, p.v, p.h);
    if (problem_.workspace) {
      const Eigen::Vector3d& w = problem_.workspace->axis;
      if (std::atan2(c.cross(w).norm(), c.dot(w)) - r > workspace_angle_) return;
    }
    const std::vector<std::vector<TreSeen>> pieces = decide(c, r, p);
    std::vector<const std::vector<TreSeen>*> possible;
    for (const std::vector<TreSeen>& seen : pieces) {
      const auto hidden = std::count(seen.begin(), seen.end(), TreSeen::kHidden);
      if (n_ - hidden >= problem_.min_visible) possible.push_back(&seen);
    }
    if (possible.empty()) return;
    attain(c);
    double bound = -kTreInfinity;
    for (const std::vector<TreSeen>* seen : possible) {
      bound = std::max(bound, seen_bound(*seen, c, r));
    }
    if (bound == -kTreInfinity) return;  // no registrable set: nothing tracked on the patch
    bound = std::min(bound, p.bound);
    if (have_best_ && bound <= best_value_ + tolerance()) {
      // Closed within the tolerance, not below the best: its bound stays part of the answer's.
      pruned_bound_ = std::max(pruned_bound_, bound);
      return;
    }
    const double q = 0.5 * p.h;
    for (int k = 0; k < 4; ++k) {
      open_.push({p.face, p.u + ((k & 1) ? q : -q), p.v + ((k & 2) ? q : -q), q, bound});
    }
  }

  // The bound of s (c + a^T M a) on the cap (c, r) over every visible set that the decisions
  // `seen` allow (the peaks attained on the way); -inf when none is registrable, +inf when the
  // mixed units are too many to enumerate.
  double seen_bound(const std::vector<TreSeen>& seen, const Eigen::Vector3d& c, double r) {
    std::uint64_t certain = 0;
    for (int i = 0; i < n_; ++i) {
      if (seen[static_cast<std::size_t>(i)] == TreSeen::kVisible) certain |= std::uint64_t{1} << i;
    }
    const std::vector<Unit> mixed = units(seen);
    if (static_cast<int>(mixed.size()) > options_.max_enumerated_units) return kTreInfinity;
    const std::vector<std::uint64_t> apart = apart_pairs(mixed);
    double bound = -kTreInfinity;
    const std::uint64_t choices = std::uint64_t{1} << mixed.size();
    for (std::uint64_t choice = 0; choice < choices; ++choice) {
      if (std::any_of(apart.begin(), apart.end(),
                      [choice](std::uint64_t pair) { return (choice & pair) == 0; })) {
        continue;  // both hidden: no direction
      }
      std::uint64_t mask = certain;
      for (std::size_t u = 0; u < mixed.size(); ++u) {
        if (choice >> u & 1u) mask |= mixed[u].mask;
      }
      if (__builtin_popcountll(mask) < problem_.min_visible) continue;
      const TreObjective& f = objective(mask);
      if (!f.registrable) continue;
      Eigen::Vector3d peak;
      const double b = tre_cap_bound(f, c, r, &peak);
      attain(peak);
      bound = std::max(bound, b);
    }
    return bound;
  }

  TreExtreme result() {
    TreExtreme out;
    out.patches = patches_;
    if (!have_best_) {
      out.status = TreExtreme::Status::kUntracked;
      return out;
    }
    // The largest bound of every patch not shown below the best: those left open and those
    // closed within the tolerance. Not the attained value: a direction of a patch closed within
    // the tolerance may exceed it (by up to the tolerance), never this.
    double upper = std::max(best_value_, pruned_bound_);
    if (!open_.empty()) upper = std::max(upper, open_.top().bound);
    out.status = exhausted_ ? TreExtreme::Status::kNotCertified : TreExtreme::Status::kCertified;
    out.direction = best_direction_;
    out.rms = std::sqrt(std::max(0.0, sign_ * best_value_));
    out.rms_bound = std::sqrt(std::max(0.0, sign_ * upper));
    out.visible_markers = best_visible_;
    return out;
  }

  const visibility::VisibilityProblem& problem_;
  Eigen::Vector3d target_;
  FleModel fle_;
  double sign_;
  TreSearchOptions options_;
  int n_;
  visibility::internal::ConeClasses classes_;
  std::vector<double> cone_angle_;
  double workspace_angle_ = kPi;
  std::priority_queue<Patch> open_;
  std::unordered_map<std::uint64_t, TreObjective> cache_;
  long patches_ = 0;
  bool exhausted_ = false;
  bool have_best_ = false;
  double best_value_ = 0.0;
  double pruned_bound_ = -kTreInfinity;  ///< the largest bound of the patches closed within tol
  Eigen::Vector3d best_direction_ = Eigen::Vector3d::UnitZ();
  std::vector<int> best_visible_;
};

bool tre_sees_everything(const visibility::VisibilityProblem& problem) {
  return problem.occlusion == nullptr && !problem.workspace &&
         (problem.cos_cone.array() <= -1.0).all();
}

// No normals, whole sphere: the extreme eigenvector of M (sign chosen: largest z, then y, x).
TreExtreme tre_closed_form(const visibility::VisibilityProblem& problem,
                           const Eigen::Vector3d& target, const FleModel& fle, bool worst) {
  std::vector<int> all(static_cast<std::size_t>(problem.points.cols()));
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const TreQuadratic q = tre_quadratic(problem.points, all, target, fle);
  TreExtreme out;
  out.closed_form = true;
  if (!q.registrable) {
    out.status = TreExtreme::Status::kUntracked;
    return out;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(q.M);
  const int k = worst ? 2 : 0;
  Eigen::Vector3d a = eigen.eigenvectors().col(k).normalized();
  for (int j = 2; j >= 0; --j) {
    if (a(j) != 0.0) {
      if (a(j) < 0.0) a = -a;
      break;
    }
  }
  out.status = TreExtreme::Status::kCertified;
  out.direction = a;
  out.rms = out.rms_bound = std::sqrt(std::max(0.0, q.c + eigen.eigenvalues()(k)));
  out.visible_markers = all;
  return out;
}

}  // namespace

bool TreSearchOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* message) {
    if (why != nullptr) *why = message;
    return false;
  };
  if (!(relative_tolerance >= 1e-12 && relative_tolerance <= 1e-2)) {
    return fail("relative_tolerance: must be in [1e-12, 1e-2]");
  }
  if (max_patches < 1) return fail("max_patches: must be >= 1");
  if (max_enumerated_units < 0 || max_enumerated_units > 16) {
    return fail("max_enumerated_units: must be in [0, 16]");
  }
  if (std::isnan(stop_above)) return fail("stop_above: must not be NaN");
  return true;
}

const char* to_string(TreExtreme::Status status) {
  switch (status) {
    case TreExtreme::Status::kCertified:
      return "certified";
    case TreExtreme::Status::kNotCertified:
      return "not_certified";
    case TreExtreme::Status::kUntracked:
      return "untracked";
  }
  return "unknown";
}

namespace {

void check_tre_search(const visibility::VisibilityProblem& problem,
                      const Eigen::Vector3d& target_tool, const FleModel& fle,
                      const TreSearchOptions& options) {
  problem.validate();
  std::string why;
  if (!fle.is_valid(&why) || !options.is_valid(&why)) throw InvalidArgument(why);
  if (problem.points.cols() > kTreMaxMarkers) {
    throw InvalidArgument("points", "more than 63 markers: the TRE search takes at most 63");
  }
  if (!target_tool.allFinite()) throw InvalidArgument("target", "must be finite");
}

}  // namespace

TreExtreme tre_worst(const visibility::VisibilityProblem& problem,
                     const Eigen::Vector3d& target_tool, const FleModel& fle,
                     const TreSearchOptions& options) {
  check_tre_search(problem, target_tool, fle, options);
  if (tre_sees_everything(problem)) return tre_closed_form(problem, target_tool, fle, true);
  return TreSearch(problem, target_tool, fle, 1.0, options).run();
}

TreExtremes tre_extremes(const visibility::VisibilityProblem& problem,
                         const Eigen::Vector3d& target_tool, const FleModel& fle,
                         const TreSearchOptions& options) {
  check_tre_search(problem, target_tool, fle, options);
  TreExtremes out;
  if (tre_sees_everything(problem)) {
    out.worst = tre_closed_form(problem, target_tool, fle, true);
    out.best = tre_closed_form(problem, target_tool, fle, false);
    return out;
  }
  out.worst = TreSearch(problem, target_tool, fle, 1.0, options).run();
  out.best = TreSearch(problem, target_tool, fle, -1.0, options).run();
  return out;
}

}  // namespace vantage::tracker
