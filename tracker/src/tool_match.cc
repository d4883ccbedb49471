// The distance mismatch between k markers of one tool and k of another (docs/math.md §24,
// Eq. 24.4): a depth-first branch and bound over subsets and injective assignments, and the
// rigid fits (proper and improper) of the best match.

#include "vantage/tracker/tool_match.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "orthogonal_fit.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage::tracker {
namespace {

constexpr double kMatchInfinity = std::numeric_limits<double>::infinity();
// Two fits whose RMS residuals differ by at most this fraction of the subset's RMS radius are
// one: the q-method's residuals carry rounding of about 1e-15 of the radius, and a coplanar
// subset fits a rotation and a reflection exactly equally.
constexpr double kTransformTie = 1e-9;

Eigen::MatrixXd distance_matrix(const Eigen::Matrix3Xd& p) {
  const Eigen::Index n = p.cols();
  Eigen::MatrixXd d(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) d(i, j) = (p.col(i) - p.col(j)).norm();
  }
  return d;
}

class MatchSearch {
 public:
  MatchSearch(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, int k, bool self, long budget)
      : da_(distance_matrix(a)),
        db_(distance_matrix(b)),
        na_(static_cast<int>(a.cols())),
        nb_(static_cast<int>(b.cols())),
        k_(k),
        self_(self),
        budget_(budget),
        subset_(static_cast<std::size_t>(k)),
        image_(static_cast<std::size_t>(k)),
        used_(static_cast<std::size_t>(nb_), false) {}

  ToolMatch run() {
    descend(0, 0.0, false);
    ToolMatch out;
    out.mismatch = best_;
    out.certified = !aborted_;
    out.mismatch_lower = std::min(best_, unexplored_lower_);
    out.subset = best_subset_;
    out.assignment = best_image_;
    out.comparisons = comparisons_;
    return out;
  }

 private:
  // The first `t` pairs (subset_[s], image_[s]) are set; `current` is their mismatch and `moved`
  // says whether some image differs from its marker (self-ambiguity only counts those).
  void descend(int t, double current, bool moved) {
    const int first = t == 0 ? 0 : subset_[static_cast<std::size_t>(t - 1)] + 1;
    for (int i = first; i <= na_ - (k_ - t); ++i) {
      for (int j = 0; j < nb_; ++j) {
        if (used_[static_cast<std::size_t>(j)]) continue;
        double mismatch = current;
        for (int s = 0; s < t; ++s) {
          mismatch = std::max(mismatch, std::abs(da_(subset_[static_cast<std::size_t>(s)], i) -
                                                 db_(image_[static_cast<std::size_t>(s)], j)));
        }
        comparisons_ += t;
        if (mismatch >= best_) continue;
        const bool now_moved = moved || (self_ && i != j);
        if (t + 1 == k_) {
          if (self_ && !now_moved) continue;
          subset_[static_cast<std::size_t>(t)] = i;
          image_[static_cast<std::size_t>(t)] = j;
          best_ = mismatch;
          best_subset_ = subset_;
          best_image_ = image_;
          continue;
        }
        if (aborted_ || comparisons_ > budget_) {
          aborted_ = true;
          unexplored_lower_ = std::min(unexplored_lower_, mismatch);
          continue;
        }
        subset_[static_cast<std::size_t>(t)] = i;
        image_[static_cast<std::size_t>(t)] = j;
        used_[static_cast<std::size_t>(j)] = true;
        descend(t + 1, mismatch, now_moved);
        used_[static_cast<std::size_t>(j)] = false;
      }
    }
  }

  const Eigen::MatrixXd da_;
  const Eigen::MatrixXd db_;
  const int na_;
  const int nb_;
  const int k_;
  const bool self_;
  const long budget_;
  std::vector<int> subset_;
  std::vector<int> image_;
  std::vector<bool> used_;
  double best_ = kMatchInfinity;
  std::vector<int> best_subset_;
  std::vector<int> best_image_;
  bool aborted_ = false;
  double unexplored_lower_ = kMatchInfinity;
  long comparisons_ = 0;
};

void check_tool(const std::string& arg, const Eigen::Matrix3Xd& p,
                const ToolMatchOptions& options) {
  internal::check_min_count(arg, p.cols(), options.min_visible, "markers (min_visible)");
  internal::check_finite_columns(arg, p);
}

ToolMatch best_match(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, bool self,
                     const ToolMatchOptions& options) {
  ToolMatch out = MatchSearch(a, b, options.min_visible, self, options.max_comparisons).run();
  if (out.subset.empty()) return out;
  Eigen::Matrix3Xd from(3, options.min_visible);
  Eigen::Matrix3Xd to(3, options.min_visible);
  for (int s = 0; s < options.min_visible; ++s) {
    from.col(s) = a.col(out.subset[static_cast<std::size_t>(s)]);
    to.col(s) = b.col(out.assignment[static_cast<std::size_t>(s)]);
  }
  out.proper_rms = internal::orthogonal_fit_rms(from, to, false);
  out.improper_rms = internal::orthogonal_fit_rms(from, to, true);
  const double tie = kTransformTie * internal::rms_radius(from);
  if (out.proper_rms < out.improper_rms - tie) {
    out.transform = ToolMatch::Transform::kRotation;
  } else if (out.improper_rms < out.proper_rms - tie) {
    out.transform = ToolMatch::Transform::kReflection;
  } else {
    out.transform = ToolMatch::Transform::kEither;
  }
  return out;
}

}  // namespace

const char* to_string(ToolMatch::Transform transform) {
  switch (transform) {
    case ToolMatch::Transform::kRotation:
      return "rotation";
    case ToolMatch::Transform::kReflection:
      return "reflection";
    case ToolMatch::Transform::kEither:
      break;
  }
  return "either";
}

bool ToolMatchOptions::is_valid(std::string* why) const {
  if (min_visible < 2) return internal::invalid_option(why, "min_visible", "must be >= 2");
  if (max_comparisons < 1) return internal::invalid_option(why, "max_comparisons", "must be >= 1");
  return true;
}

ToolMatch match_tools(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                      const ToolMatchOptions& options) {
  internal::check_options("options", options);
  check_tool("a", a, options);
  check_tool("b", b, options);
  return best_match(a, b, false, options);
}

ToolMatch self_ambiguity(const Eigen::Matrix3Xd& a, const ToolMatchOptions& options) {
  internal::check_options("options", options);
  check_tool("a", a, options);
  return best_match(a, a, true, options);
}

const char* to_string(ToolPairMatch::Verdict verdict) {
  switch (verdict) {
    case ToolPairMatch::Verdict::kSelf:
      return "self";
    case ToolPairMatch::Verdict::kSameTool:
      return "same_tool";
    case ToolPairMatch::Verdict::kMirror:
      return "mirror";
    case ToolPairMatch::Verdict::kDistinct:
      break;
  }
  return "distinct";
}

Eigen::MatrixXd ToolLibraryMatches::mismatch_matrix() const {
  const Eigen::Index n = static_cast<Eigen::Index>(min_visible.size());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  for (const ToolPairMatch& p : pairs) {
    out(p.a, p.b) = p.match.mismatch;
    out(p.b, p.a) = p.match.mismatch;
  }
  return out;
}

namespace {

// The distances above the diagonal of a distance matrix, sorted.
std::vector<double> sorted_distances(const Eigen::MatrixXd& d) {
  std::vector<double> out;
  for (Eigen::Index i = 0; i < d.rows(); ++i) {
    for (Eigen::Index j = i + 1; j < d.cols(); ++j) out.push_back(d(i, j));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Labellings of every marker of A onto B whose distances all agree within the tolerance: a
// depth-first enumeration (not a minimisation) that stops at a budget of partial assignments.
class WholeLabellings {
 public:
  // da, db: the tools' distance matrices (distance_matrix()).
  WholeLabellings(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, const Eigen::MatrixXd& da,
                  const Eigen::MatrixXd& db, double tolerance, long budget)
      : a_(a),
        b_(b),
        da_(da),
        db_(db),
        tolerance_(tolerance),
        budget_(budget),
        sigma_(static_cast<std::size_t>(a.cols())),
        used_(static_cast<std::size_t>(b.cols()), false) {}

  // The best proper and improper fits (RMS) over every such labelling; false when the budget
  // ran out first (the fits are then over those found).
  bool run(double* proper, double* improper) {
    proper_ = improper_ = kMatchInfinity;
    const bool finished = extend(0);
    *proper = proper_;
    *improper = improper_;
    return finished;
  }

 private:
  bool extend(Eigen::Index i) {
    if (i == a_.cols()) {
      Eigen::Matrix3Xd to(3, a_.cols());
      for (Eigen::Index k = 0; k < a_.cols(); ++k)
        to.col(k) = b_.col(sigma_[static_cast<std::size_t>(k)]);
      proper_ = std::min(proper_, internal::orthogonal_fit_rms(a_, to, false));
      improper_ = std::min(improper_, internal::orthogonal_fit_rms(a_, to, true));
      return true;
    }
    for (Eigen::Index j = 0; j < b_.cols(); ++j) {
      if (used_[static_cast<std::size_t>(j)]) continue;
      if (--budget_ < 0) return false;
      bool fits = true;
      for (Eigen::Index k = 0; k < i && fits; ++k) {
        fits = std::abs(da_(i, k) - db_(j, sigma_[static_cast<std::size_t>(k)])) <= tolerance_;
      }
      if (!fits) continue;
      sigma_[static_cast<std::size_t>(i)] = j;
      used_[static_cast<std::size_t>(j)] = true;
      const bool finished = extend(i + 1);
      used_[static_cast<std::size_t>(j)] = false;
      if (!finished) return false;
    }
    return true;
  }

  const Eigen::Matrix3Xd& a_;
  const Eigen::Matrix3Xd& b_;
  const Eigen::MatrixXd& da_;
  const Eigen::MatrixXd& db_;
  double tolerance_;
  long budget_;
  std::vector<Eigen::Index> sigma_;
  std::vector<bool> used_;
  double proper_ = kMatchInfinity;
  double improper_ = kMatchInfinity;
};

// Two different tools: one tool, mirror images or distinct. Every labelling of all the markers
// whose distances agree within the tolerance is fitted, by a rotation and by a reflection: the
// same tool when some labelling fits by a rotation within the tolerance (RMS), else mirror images
// when some fits by a reflection, else distinct. *finished is false when the enumeration's
// budget ran out (the verdict is then over the labellings found).
ToolPairMatch::Verdict verdict_of(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                                  const ToolMatchOptions& options, bool* finished) {
  *finished = true;
  if (a.cols() != b.cols()) return ToolPairMatch::Verdict::kDistinct;
  // One tool has the other's distances: their sorted lists agree within the tolerance (a
  // necessary condition, which keeps the enumeration to the pairs that may pass).
  const Eigen::MatrixXd da = distance_matrix(a);
  const Eigen::MatrixXd db = distance_matrix(b);
  const std::vector<double> sorted_a = sorted_distances(da);
  const std::vector<double> sorted_b = sorted_distances(db);
  for (std::size_t k = 0; k < sorted_a.size(); ++k) {
    if (std::abs(sorted_a[k] - sorted_b[k]) > options.same_tolerance) {
      return ToolPairMatch::Verdict::kDistinct;
    }
  }
  double proper = kMatchInfinity;
  double improper = kMatchInfinity;
  *finished = WholeLabellings(a, b, da, db, options.same_tolerance, options.max_comparisons)
                  .run(&proper, &improper);
  if (proper <= options.same_tolerance) return ToolPairMatch::Verdict::kSameTool;
  if (improper <= options.same_tolerance) return ToolPairMatch::Verdict::kMirror;
  return ToolPairMatch::Verdict::kDistinct;
}

}  // namespace

ToolLibraryMatches match_tool_library(const std::vector<Eigen::Matrix3Xd>& tools,
                                      const ToolMatchOptions& options,
                                      const std::vector<int>& min_visible) {
  internal::check_options("options", options);
  if (!(options.same_tolerance >= 0.0 && std::isfinite(options.same_tolerance))) {
    internal::fail("options.same_tolerance", "must be finite and >= 0");
  }
  if (tools.empty()) internal::fail("tools", "need at least one tool");
  if (!min_visible.empty() && min_visible.size() != tools.size()) {
    internal::fail("min_visible", "one per tool: " + std::to_string(min_visible.size()) + " for " +
                                      std::to_string(tools.size()) + " tools");
  }
  ToolLibraryMatches out;
  out.min_visible =
      min_visible.empty() ? std::vector<int>(tools.size(), options.min_visible) : min_visible;
  for (std::size_t t = 0; t < tools.size(); ++t) {
    ToolMatchOptions own = options;
    own.min_visible = out.min_visible[t];
    if (own.min_visible < 2) {
      internal::fail("min_visible[" + std::to_string(t) + "]", "must be >= 2");
    }
    check_tool("tools[" + std::to_string(t) + "]", tools[t], own);
  }
  out.certified = true;
  const int n = static_cast<int>(tools.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a; b < n; ++b) {
      const Eigen::Matrix3Xd& ta = tools[static_cast<std::size_t>(a)];
      const Eigen::Matrix3Xd& tb = tools[static_cast<std::size_t>(b)];
      ToolMatchOptions pair_options = options;
      pair_options.min_visible = std::min(out.min_visible[static_cast<std::size_t>(a)],
                                          out.min_visible[static_cast<std::size_t>(b)]);
      ToolPairMatch pair{a, b, pair_options.min_visible, best_match(ta, tb, a == b, pair_options),
                         ToolPairMatch::Verdict::kSelf};
      if (a != b) {
        bool finished = true;
        pair.verdict = verdict_of(ta, tb, options, &finished);
        out.certified = out.certified && finished;
      }
      out.pairs.push_back(pair);
      const ToolMatch& m = out.pairs.back().match;
      out.certified = out.certified && m.certified;
      const int index = static_cast<int>(out.pairs.size()) - 1;
      auto smaller = [&](int current) {
        return current < 0 ||
               m.mismatch < out.pairs[static_cast<std::size_t>(current)].match.mismatch;
      };
      if (smaller(out.closest)) out.closest = index;
      if (pair.verdict == ToolPairMatch::Verdict::kDistinct && smaller(out.closest_distinct)) {
        out.closest_distinct = index;
      }
    }
  }
  return out;
}

}  // namespace vantage::tracker
