// The best rigid fit of a tool to its mirror image over every marker assignment (docs/math.md
// §24, Eqs. 24.2-24.3): a depth-first branch and bound with the distance bound of Eq. (24.3).

#include "vantage/tracker/mirror_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "orthogonal_fit.h"
#include "vantage/analysis/internal/checks.h"

namespace vantage::tracker {
namespace {

constexpr double kMirrorInfinity = std::numeric_limits<double>::infinity();
// The budget counts a fit (centring, the cross-covariance, §3's 4 x 4 eigenvector) as this many
// distance comparisons plus 4 per marker: about its CPU time.
constexpr long kFitComparisons = 200;

class MirrorSearch {
 public:
  MirrorSearch(const Eigen::Matrix3Xd& points, long budget)
      : points_(points),
        n_(static_cast<int>(points.cols())),
        distances_(n_, n_),
        budget_(budget),
        assignment_(static_cast<std::size_t>(n_)),
        used_(static_cast<std::size_t>(n_), false) {
    for (int i = 0; i < n_; ++i) {
      for (int j = 0; j < n_; ++j) distances_(i, j) = (points.col(i) - points.col(j)).norm();
    }
    const Eigen::Vector3d centroid = points.rowwise().mean();
    radius_ = (points.colwise() - centroid).colwise().norm().transpose();
  }

  MirrorFit run() {
    std::vector<int> identity(static_cast<std::size_t>(n_));
    std::iota(identity.begin(), identity.end(), 0);
    best_sum_ = fitted_sum(identity);
    best_ = identity;
    descend(0);
    MirrorFit out;
    const double n = static_cast<double>(n_);
    out.rms = std::sqrt(best_sum_ / n);
    out.certified = !aborted_;
    out.rms_lower = std::sqrt(std::min(best_sum_, unexplored_lower_) / n);
    out.own_mirror = out.rms <= kOwnMirrorTolerance * internal::rms_radius(points_);
    out.assignment = best_;
    out.comparisons = comparisons_;
    out.fits = fits_;
    return out;
  }

 private:
  // N mu^2 of one complete assignment: sum_i |R p_i + t - M p_pi(i)|^2 at the best R, t.
  double fitted_sum(const std::vector<int>& pi) {
    ++fits_;
    comparisons_ += kFitComparisons + 4L * n_;
    Eigen::Matrix3Xd target(3, n_);
    for (int i = 0; i < n_; ++i) target.col(i) = points_.col(pi[static_cast<std::size_t>(i)]);
    const double rms = internal::orthogonal_fit_rms(points_, target, true);
    return rms * rms * static_cast<double>(n_);
  }

  double delta(int i, int j) const {
    return std::abs(distances_(i, j) - distances_(assignment_[static_cast<std::size_t>(i)],
                                                  assignment_[static_cast<std::size_t>(j)]));
  }

  // A lower bound on N mu^2 for every completion of the first `assigned` markers (docs/math.md
  // §24): at the completion's best fit (R*, t*), the assigned markers' residuals are at least the
  // best fit of those markers alone, at least their centroid radii's differences, and at least
  // Eq. (24.3) over a greedy matching; the others' at least the sorted matching of their radii.
  double bound(int assigned) {
    double fixed = std::max(subset_fit(assigned), radius_sum(assigned));
    fixed = std::max(fixed, matching_sum(assigned));
    return fixed + free_radius_sum(assigned);
  }

  double subset_fit(int assigned) {
    if (assigned < 2) return 0.0;
    Eigen::Matrix3Xd from = points_.leftCols(assigned);
    Eigen::Matrix3Xd to(3, assigned);
    for (int i = 0; i < assigned; ++i) {
      to.col(i) = points_.col(assignment_[static_cast<std::size_t>(i)]);
    }
    const double rms = internal::orthogonal_fit_rms(from, to, true);
    comparisons_ += kFitComparisons + 4L * assigned;
    return rms * rms * assigned;
  }

  double radius_sum(int assigned) const {
    double sum = 0.0;
    for (int i = 0; i < assigned; ++i) {
      const double d = radius_(i) - radius_(assignment_[static_cast<std::size_t>(i)]);
      sum += d * d;
    }
    return sum;
  }

  // The unassigned markers onto the unused ones: the least sum of squared radius differences
  // over every bijection pairs them in sorted order.
  double free_radius_sum(int assigned) {
    from_radii_.clear();
    to_radii_.clear();
    for (int i = assigned; i < n_; ++i) from_radii_.push_back(radius_(i));
    for (int c = 0; c < n_; ++c) {
      if (!used_[static_cast<std::size_t>(c)]) to_radii_.push_back(radius_(c));
    }
    std::sort(from_radii_.begin(), from_radii_.end());
    std::sort(to_radii_.begin(), to_radii_.end());
    double sum = 0.0;
    for (std::size_t k = 0; k < from_radii_.size(); ++k) {
      const double d = from_radii_[k] - to_radii_[k];
      sum += d * d;
    }
    comparisons_ += n_;
    return sum;
  }

  double matching_sum(int assigned) {
    pairs_.clear();
    for (int i = 0; i < assigned; ++i) {
      for (int j = i + 1; j < assigned; ++j) {
        const double d = delta(i, j);
        if (d > 0.0) pairs_.push_back({d, i, j});
      }
    }
    comparisons_ += static_cast<long>(assigned) * (assigned - 1) / 2;
    std::sort(pairs_.begin(), pairs_.end(), [](const Pair& a, const Pair& b) {
      return a.delta > b.delta || (a.delta == b.delta && (a.i < b.i || (a.i == b.i && a.j < b.j)));
    });
    matched_.assign(static_cast<std::size_t>(assigned), false);
    double sum = 0.0;
    for (const Pair& p : pairs_) {
      if (matched_[static_cast<std::size_t>(p.i)] || matched_[static_cast<std::size_t>(p.j)]) {
        continue;
      }
      matched_[static_cast<std::size_t>(p.i)] = matched_[static_cast<std::size_t>(p.j)] = true;
      sum += 0.5 * p.delta * p.delta;
    }
    return sum;
  }

  // Candidates for marker `level` by increasing largest Delta with the markers before it (or
  // radius difference, when larger).
  std::vector<int> candidates(int level) {
    std::vector<std::pair<double, int>> order;
    for (int c = 0; c < n_; ++c) {
      if (used_[static_cast<std::size_t>(c)]) continue;
      double worst = std::abs(radius_(level) - radius_(c));
      for (int j = 0; j < level; ++j) {
        worst = std::max(worst, std::abs(distances_(j, level) -
                                         distances_(assignment_[static_cast<std::size_t>(j)], c)));
      }
      comparisons_ += level;
      order.push_back({worst, c});
    }
    std::sort(order.begin(), order.end());
    std::vector<int> out;
    for (const auto& [worst, c] : order) out.push_back(c);
    return out;
  }

  void descend(int level) {
    if (level == n_) {
      const double sum = fitted_sum(assignment_);
      if (sum < best_sum_) {
        best_sum_ = sum;
        best_ = assignment_;
      }
      return;
    }
    for (int c : candidates(level)) {
      assignment_[static_cast<std::size_t>(level)] = c;
      used_[static_cast<std::size_t>(c)] = true;
      const double lower = bound(level + 1);
      if (lower < best_sum_) {
        if (aborted_ || comparisons_ > budget_) {
          aborted_ = true;
          unexplored_lower_ = std::min(unexplored_lower_, lower);
        } else {
          descend(level + 1);
        }
      }
      used_[static_cast<std::size_t>(c)] = false;
    }
  }

  struct Pair {
    double delta;
    int i;
    int j;
  };

  const Eigen::Matrix3Xd& points_;
  const int n_;
  Eigen::MatrixXd distances_;
  Eigen::VectorXd radius_;  // |p_i - centroid|
  const long budget_;
  std::vector<int> assignment_;
  std::vector<bool> used_;
  std::vector<int> best_;
  double best_sum_ = kMirrorInfinity;
  bool aborted_ = false;
  double unexplored_lower_ = kMirrorInfinity;
  long comparisons_ = 0;
  long fits_ = 0;
  std::vector<Pair> pairs_;
  std::vector<bool> matched_;
  std::vector<double> from_radii_;
  std::vector<double> to_radii_;
};

}  // namespace

bool MirrorFitOptions::is_valid(std::string* why) const {
  if (max_comparisons < 1) return internal::invalid_option(why, "max_comparisons", "must be >= 1");
  return true;
}

MirrorFit mirror_fit(const Eigen::Matrix3Xd& points, const MirrorFitOptions& options) {
  internal::check_options("options", options);
  internal::check_min_count("points", points.cols(), 1, "points");
  internal::check_finite_columns("points", points);
  return MirrorSearch(points, options.max_comparisons).run();
}

}  // namespace vantage::tracker
