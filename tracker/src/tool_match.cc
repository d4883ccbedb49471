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

ToolLibraryMatches match_tool_library(const std::vector<Eigen::Matrix3Xd>& tools,
                                      const ToolMatchOptions& options) {
  internal::check_options("options", options);
  if (tools.empty()) internal::fail("tools", "need at least one tool");
  for (std::size_t t = 0; t < tools.size(); ++t) {
    const std::string arg = "tools[" + std::to_string(t) + "]";
    check_tool(arg, tools[t], options);
  }
  ToolLibraryMatches out;
  out.min_visible = options.min_visible;
  out.certified = true;
  const int n = static_cast<int>(tools.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a; b < n; ++b) {
      const Eigen::Matrix3Xd& ta = tools[static_cast<std::size_t>(a)];
      const Eigen::Matrix3Xd& tb = tools[static_cast<std::size_t>(b)];
      out.pairs.push_back({a, b, best_match(ta, tb, a == b, options)});
      const ToolMatch& m = out.pairs.back().match;
      out.certified = out.certified && m.certified;
      if (out.closest < 0 ||
          m.mismatch < out.pairs[static_cast<std::size_t>(out.closest)].match.mismatch) {
        out.closest = static_cast<int>(out.pairs.size()) - 1;
      }
    }
  }
  return out;
}

}  // namespace vantage::tracker
