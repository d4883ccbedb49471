#include "global_search.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "vantage/analysis/parallel.h"
#include "vantage/sdp/internal/min_norm_point.h"

namespace vantage::sdp::internal {
namespace {

// A circle this close to a patch's bounding cap (in sin of the angle) counts as crossing it.
constexpr double kCrossingSlack = 1e-15;
// A subset-cell optimum is exact for the full cell when the full objective at its point is
// within this of it (both are computed to ~1e-14).
constexpr double kCellExact = 1e-12;
// Viewpoints closer than this (1 - |a.b|) are the same optimum.
constexpr double kSameViewpoint = 1e-9;
// Patches with an angular radius below 1e-11 (sin 1e-11 to rounding) are not subdivided further.
constexpr double kMinPatchSin = 1e-11;
// Initial grid per cube face (kGrid x kGrid patches).
constexpr int kGrid = 4;
// Recursion depth limit; patches halve per level, so kMinPatchRadius is reached long before.
constexpr int kMaxDepth = 120;
// Layouts with at least this many distinct directions are searched in two halves (see
// search_worst_viewpoint()). Below it a search takes tens of ms at most (about 15 ms at
// m = 1000, 40-50 ms just below 2000), and callers that make many of them (the augmenter) would
// pay a thread start and the halves' lost pruning (+19 % patches at m = 5000) on every call.
constexpr int kSplitColumns = 2000;
// Circles scanned between early-prune checks.
constexpr int kScanBlock = 8;
// Margin of the early prune against the rounding of sin_minus and sin_plus (a few ulps of 1).
constexpr double kPruneRounding = 1e-15;
// Unit vectors whose components all agree to this (up to sign) are one direction: a few ulps,
// what normalising z and k z for a grid layout's free vectors leaves.
constexpr double kSameDirection = 1e-15;

Eigen::Vector3d face_point(int face, double u, double v) {
  const double inverse_norm = 1.0 / std::sqrt(1.0 + u * u + v * v);
  const double one = inverse_norm, a = u * inverse_norm, b = v * inverse_norm;
  switch (face) {
    case 0:
      return Eigen::Vector3d(one, a, b);
    case 1:
      return Eigen::Vector3d(a, one, b);
    default:
      return Eigen::Vector3d(a, b, one);
  }
}

// cos of the angular radius of the patch of centre (u, v) and half-width h on any face: the
// smallest cos(c, corner). On every face the point is a permutation of (1, u, v), which leaves
// dot products alone, and 1 + u cu + v cv >= 1 inside a face, so cos^2 decides.
double patch_cos_radius(double u, double v, double h) {
  double worst = std::numeric_limits<double>::infinity();  // min over corners of dot^2 / |q|^2
  for (int corner = 0; corner < 4; ++corner) {
    const double cu = u + ((corner & 1) ? h : -h);
    const double cv = v + ((corner & 2) ? h : -h);
    const double dot = 1.0 + u * cu + v * cv;
    worst = std::min(worst, dot * dot / (1.0 + cu * cu + cv * cv));
  }
  return std::clamp(std::sqrt(worst / (1.0 + u * u + v * v)), 0.0, 1.0);
}

// sin(min(pi/2, asin(s) + r)) for s in [0, 1], given cos r and sin r: the largest |a.n| over a
// cap of radius r whose centre has |c.n| = s.
double sin_plus(double s, double cos_r, double sin_r) {
  if (s >= cos_r) return 1.0;
  return s * cos_r + std::sqrt(std::max(0.0, 1.0 - s * s)) * sin_r;
}

// sin(asin(s) - r) for s in (-1, 1] with cos_s = sqrt(1 - s^2), given cos r and sin r, or -1
// when asin(s) <= r: the largest |c.n| of a circle that keeps every point of a cap of radius r
// below s.
double sin_minus(double s, double cos_s, double cos_r, double sin_r) {
  if (s <= sin_r) return -1.0;
  return s * cos_r - cos_s * sin_r;
}

// The circles a patch passes to its sub-patches: unit normals as a structure of arrays.
struct CircleList {
  std::vector<double> x, y, z;

  void ensure(int count) {
    if (static_cast<int>(x.size()) >= count) return;
    x.resize(count);
    y.resize(count);
    z.resize(count);
  }
};

class BranchAndBound {
 public:
  BranchAndBound(const Eigen::Matrix3Xd& n, const WorstViewpointOptions& options)
      : n_(n), m_(static_cast<int>(n.cols())), options_(options), nt_(n.transpose()) {
    scratch_.resize(m_);
    cell_points_.resize(3, m_);
    // Sized up front: the recursion holds references into both.
    lists_.resize(kMaxDepth + 2);
    dots_.resize(kMaxDepth + 2);
    CircleList& all = lists_[0];
    all.ensure(m_);
    for (int i = 0; i < m_; ++i) {
      all.x[i] = n_(0, i);
      all.y[i] = n_(1, i);
      all.z[i] = n_(2, i);
    }
  }

  // A patch of the initial grid (kGrid x kGrid per cube face) and the objective at its centre.
  struct Root {
    int face;
    double u, v;
    double value;
  };

  // What every search does first: the hints, then the initial grid sorted by the objective at
  // the patch centres (best first) and the exact cells of the best four centres, so that the
  // branch and bound prunes with a good attained value from its first patch.
  std::vector<Root> prepare() {
    apply_hints();
    if (stopped_) return {};
    std::vector<Root> roots;
    const double h = 1.0 / kGrid;
    for (int face = 0; face < 3; ++face) {
      for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
          const double u = -1.0 + (2 * i + 1) * h;
          const double v = -1.0 + (2 * j + 1) * h;
          roots.push_back({face, u, v, full_objective(face_point(face, u, v))});
        }
      }
    }
    std::sort(roots.begin(), roots.end(),
              [](const Root& a, const Root& b) { return a.value > b.value; });
    for (int s = 0; s < std::min<int>(4, static_cast<int>(roots.size())) && !stopped_; ++s) {
      solve_full_cell(face_point(roots[s].face, roots[s].u, roots[s].v));
    }
    return roots;
  }

  // The branch and bound below roots[first], roots[first + stride], ...
  void search_roots(const std::vector<Root>& roots, int first, int stride) {
    for (std::size_t k = first; k < roots.size(); k += stride) {
      process(roots[k].face, roots[k].u, roots[k].v, 1.0 / kGrid, m_, 0);
    }
  }

  void run() { search_roots(prepare(), 0, 1); }

  // Adds what `other`, a copy of this search made after prepare() and run on other roots, found
  // and proved. prepared_cells: the cells both counted in prepare().
  void absorb(const BranchAndBound& other, long prepared_cells) {
    candidates_.insert(candidates_.end(), other.candidates_.begin(), other.candidates_.end());
    lower_ = std::max(lower_, other.lower_);
    upper_ = std::max(upper_, other.upper_);
    cells_solved_ += other.cells_solved_ - prepared_cells;
    patches_ += other.patches_;
    exhausted_ = exhausted_ || other.exhausted_;
    if (!stopped_ && other.stopped_) {
      stopped_ = true;
      stop_point_ = other.stop_point_;
    }
  }

  long cells_solved() const { return cells_solved_; }

  // Collection of the frontier at a fixed level (collect_frontier()).
  void collect(double level, Frontier* frontier) {
    collect_ = frontier;
    frontier->level = level;
    raise_level(level);
    const double h = 1.0 / kGrid;
    for (int face = 0; face < 3; ++face) {
      for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
          process(face, -1.0 + (2 * i + 1) * h, -1.0 + (2 * j + 1) * h, h, m_, 0);
        }
      }
    }
    frontier->patches_visited = patches_;
  }

  // The search over a frontier's patches: each with its own circles plus columns base_count..m-1.
  void run_frontier(const Frontier& frontier, int base_count) {
    apply_hints();
    if (stopped_) return;
    if (frontier.level > level_) raise_level(frontier.level);
    const int extra = m_ - base_count;
    for (const Frontier::Patch& p : frontier.patches) {
      CircleList& list = lists_[p.depth];
      list.ensure(p.count + extra);
      std::copy_n(frontier.x.begin() + p.first, p.count, list.x.begin());
      std::copy_n(frontier.y.begin() + p.first, p.count, list.y.begin());
      std::copy_n(frontier.z.begin() + p.first, p.count, list.z.begin());
      for (int k = 0; k < extra; ++k) {
        list.x[p.count + k] = n_(0, base_count + k);
        list.y[p.count + k] = n_(1, base_count + k);
        list.z[p.count + k] = n_(2, base_count + k);
      }
      process(p.face, p.u, p.v, p.h, p.count + extra, p.depth);
    }
    below_level_ = !stopped_ && lower_ < frontier.level;
  }

  SearchOutcome outcome() const {
    SearchOutcome out;
    for (const AttainedViewpoint& c : candidates_) {
      if (c.value < lower_ - options_.tie_tolerance) continue;
      bool duplicate = false;
      for (AttainedViewpoint& k : out.optima) {
        if (1.0 - std::abs(k.a.dot(c.a)) <= kSameViewpoint) {
          duplicate = true;
          if (c.value > k.value) k = c;
        }
      }
      if (!duplicate) out.optima.push_back(c);
    }
    out.lower = lower_;
    out.upper = std::max(upper_, lower_);
    out.cells_solved = cells_solved_;
    out.patches = patches_;
    out.exhausted = exhausted_;
    out.stopped = stopped_;
    out.stop_point = stop_point_;
    out.below_level = below_level_;
    return out;
  }

 private:
  void apply_hints() {
    for (const Eigen::Vector3d& hint : options_.hints) {
      const Eigen::Vector3d a = hint.normalized();
      const double value = full_objective(a);
      if (value > level_) raise_level(value);
      stop_if_above(a, value);
    }
  }

  double full_objective(const Eigen::Vector3d& a) {
    scratch_.noalias() = nt_ * a;
    return scratch_.cwiseAbs().minCoeff();
  }

  void offer(const Eigen::Vector3d& a, double value) {
    stop_if_above(a, value);
    if (value < lower_ - options_.tie_tolerance) return;
    if (value > lower_) {
      lower_ = value;
      if (value > level_) raise_level(value);
    }
    candidates_.push_back({a, value});
  }

  // The pruning level: the best attained value, of a cell optimum or a hint.
  void raise_level(double value) {
    level_ = value;
    prune_below_ = level_ - options_.tie_tolerance;
    prune_below_cos_ = std::sqrt(std::max(0.0, 1.0 - prune_below_ * prune_below_));
  }

  void stop_if_above(const Eigen::Vector3d& a, double value) {
    if (stopped_ || !(value > options_.stop_above)) return;
    stopped_ = true;
    stop_point_ = a;
  }

  // Exact optimum of the cell containing c (all circles); returns it and offers its point.
  double solve_full_cell(const Eigen::Vector3d& c) {
    scratch_.noalias() = nt_ * c;
    for (int i = 0; i < m_; ++i) {
      cell_points_.col(i) = scratch_(i) >= 0.0 ? n_.col(i) : Eigen::Vector3d(-n_.col(i));
    }
    ++cells_solved_;
    const MinNormPoint p = min_norm_point(cell_points_.data(), m_);
    if (p.contains_origin) return 0.0;
    const double t_cell = p.x.norm();
    const Eigen::Vector3d a = p.x / t_cell;
    offer(a, full_objective(a));
    return t_cell;
  }

  // The patch of centre (u, v) and half-width h on `face`; its circles are the first `count` of
  // lists_[depth]. Keeps the circles that can still bound a sub-patch in lists_[depth + 1].
  void process(int face, double u, double v, double h, int count, int depth) {
    if (stopped_) return;
    ++patches_;
    const Eigen::Vector3d c = face_point(face, u, v);
    const double cos_r = patch_cos_radius(u, v, h);
    const double sin_r = std::sqrt(1.0 - cos_r * cos_r);

    const CircleList& in = lists_[depth];
    std::vector<double>& dot_store = dots_[depth];
    if (static_cast<int>(dot_store.size()) < count) dot_store.resize(count);
    double* dots = dot_store.data();
    const double cx = c.x(), cy = c.y(), cz = c.z();
    // Most patches are pruned by one near circle: stop scanning once one is found (checked per
    // block so the loop stays simple). Below prune_limit the bound is certainly below the
    // attained value; the full test after the loop decides every other case.
    const double prune_limit =
        sin_minus(prune_below_, prune_below_cos_, cos_r, sin_r) - kPruneRounding;
    double centre_value = 1.0;
    for (int start = 0; start < count; start += kScanBlock) {
      const int end = std::min(count, start + kScanBlock);
      for (int k = start; k < end; ++k) {
        const double d = cx * in.x[k] + cy * in.y[k] + cz * in.z[k];
        dots[k] = d;
        centre_value = std::min(centre_value, std::abs(d));
      }
      if (centre_value < prune_limit) return;
    }
    // min_i sin(min(pi/2, asin|c.n_i| + r)): increasing in |c.n_i|, so set by the nearest circle.
    const double bound = sin_plus(centre_value, cos_r, sin_r);
    if (bound < level_ - options_.tie_tolerance) return;  // pruned: bound < attained value

    if (collect_ == nullptr && centre_value > level_ && full_objective(c) > level_) {
      solve_full_cell(c);
    }

    // A circle whose minimum of |a.n| over the patch, sin(asin|c.n| - r), exceeds the attained
    // value (or the bound) cannot decide a prune of any sub-patch: drop it from the sub-patches'
    // lists. Crossing circles (|c.n| <= sin r) are always kept.
    const double crossing_limit = sin_r + kCrossingSlack;
    const bool crossing = centre_value <= crossing_limit;
    const double keep_limit =
        std::max(crossing_limit, sin_plus(std::min(level_, bound), cos_r, sin_r));
    CircleList& out = lists_[depth + 1];
    out.ensure(count);
    int kept = 0;
    for (int k = 0; k < count; ++k) {
      out.x[kept] = in.x[k];
      out.y[kept] = in.y[k];
      out.z[kept] = in.z[k];
      kept += std::abs(dots[k]) <= keep_limit ? 1 : 0;
    }

    if (collect_ != nullptr && (!crossing || sin_r < kMinPatchSin || depth >= kMaxDepth ||
                                patches_ >= options_.max_patches)) {
      store(face, u, v, h, depth, out, kept);
      return;
    }
    if (!crossing) {
      close_single_cell(c, out, kept);
      return;
    }
    if (sin_r < kMinPatchSin || patches_ >= options_.max_patches || depth >= kMaxDepth) {
      upper_ = std::max(upper_, bound);
      if (patches_ >= options_.max_patches) exhausted_ = true;
      return;
    }
    const double q = 0.5 * h;
    for (int child = 0; child < 4; ++child) {
      process(face, u + ((child & 1) ? q : -q), v + ((child & 2) ? q : -q), q, kept, depth + 1);
    }
  }

  // The patch lies in one cell: its optimum over the kept circles bounds the patch; it is the
  // exact cell optimum when the full objective attains it.
  void close_single_cell(const Eigen::Vector3d& c, const CircleList& list, int count) {
    if (count == 0) {
      solve_full_cell_and_bound(c);
      return;
    }
    for (int k = 0; k < count; ++k) {
      const double d = c.x() * list.x[k] + c.y() * list.y[k] + c.z() * list.z[k];
      const double s = d >= 0.0 ? 1.0 : -1.0;
      cell_points_.col(k) << s * list.x[k], s * list.y[k], s * list.z[k];
    }
    ++cells_solved_;
    const MinNormPoint p = min_norm_point(cell_points_.data(), count);
    const double t_sub = p.contains_origin ? 0.0 : p.x.norm();
    if (t_sub < level_ - options_.tie_tolerance) {
      upper_ = std::max(upper_, std::min(t_sub, level_));
      return;
    }
    const Eigen::Vector3d a = p.x / t_sub;
    const double value = full_objective(a);
    offer(a, value);
    if (value >= t_sub - kCellExact) {
      upper_ = std::max(upper_, t_sub);
      return;
    }
    solve_full_cell_and_bound(c);
  }

  void store(int face, double u, double v, double h, int depth, const CircleList& list, int count) {
    const int first = static_cast<int>(collect_->x.size());
    collect_->patches.push_back({face, u, v, h, depth, first, count});
    collect_->x.insert(collect_->x.end(), list.x.begin(), list.x.begin() + count);
    collect_->y.insert(collect_->y.end(), list.y.begin(), list.y.begin() + count);
    collect_->z.insert(collect_->z.end(), list.z.begin(), list.z.begin() + count);
  }

  void solve_full_cell_and_bound(const Eigen::Vector3d& c) {
    upper_ = std::max(upper_, solve_full_cell(c));
  }

  const Eigen::Matrix3Xd& n_;
  const int m_;
  const WorstViewpointOptions& options_;
  const Eigen::Matrix<double, Eigen::Dynamic, 3> nt_;
  Eigen::VectorXd scratch_;
  Eigen::Matrix3Xd cell_points_;
  std::vector<CircleList> lists_;
  std::vector<std::vector<double>> dots_;
  std::vector<AttainedViewpoint> candidates_;
  double lower_ = 0.0;            // best attained cell optimum
  double level_ = 0.0;            // max(lower_, best hint value): what patches are pruned against
  double prune_below_ = -1.0;     // level_ - tie_tolerance once level_ is set
  double prune_below_cos_ = 0.0;  // sqrt(1 - prune_below_^2)
  double upper_ = 0.0;
  long cells_solved_ = 0;
  long patches_ = 0;
  bool exhausted_ = false;
  bool stopped_ = false;
  Eigen::Vector3d stop_point_ = Eigen::Vector3d::UnitZ();
  bool below_level_ = false;
  Frontier* collect_ = nullptr;  // collecting a frontier instead of solving
};

}  // namespace

Eigen::Matrix3Xd distinct_directions(const Eigen::Matrix3Xd& n) {
  const int m = static_cast<int>(n.cols());
  // Each direction up to sign, canonical in the upper hemisphere, sorted lexicographically:
  // repeats are then neighbours (within kSameDirection) unless a coordinate straddles a tie,
  // which only leaves a repeat in (harmless).
  Eigen::Matrix3Xd canonical(3, m);
  for (int i = 0; i < m; ++i) canonical.col(i) = upper_hemisphere(n.col(i));
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    for (int k = 2; k >= 0; --k) {
      if (canonical(k, a) != canonical(k, b)) return canonical(k, a) < canonical(k, b);
    }
    return a < b;
  });
  // Each run of equal directions keeps its earliest column.
  std::vector<char> keep(m, 0);
  for (int start = 0; start < m;) {
    const int head = order[start];
    int earliest = head;
    int end = start + 1;
    while (end < m && (canonical.col(order[end]) - canonical.col(head)).cwiseAbs().maxCoeff() <=
                          kSameDirection) {
      earliest = std::min(earliest, order[end]);
      ++end;
    }
    keep[earliest] = 1;
    start = end;
  }
  const int kept = static_cast<int>(std::count(keep.begin(), keep.end(), 1));
  Eigen::Matrix3Xd distinct(3, kept);
  for (int i = 0, k = 0; i < m; ++i) {
    if (keep[i]) distinct.col(k++) = n.col(i);
  }
  return distinct;
}

Frontier collect_frontier(const Eigen::Matrix3Xd& n, double level,
                          const WorstViewpointOptions& options) {
  Frontier frontier;
  BranchAndBound search(n, options);
  search.collect(level, &frontier);
  return frontier;
}

SearchOutcome search_frontier(const Frontier& frontier, const Eigen::Matrix3Xd& n, int base_count,
                              const WorstViewpointOptions& options) {
  BranchAndBound search(n, options);
  search.run_frontier(frontier, base_count);
  return search.outcome();
}

SearchOutcome search_worst_viewpoint(const Eigen::Matrix3Xd& n,
                                     const WorstViewpointOptions& options) {
  // A search that may stop early (stop_above) stays serial: a half could not stop the other
  // without making the outcome depend on timing.
  if (n.cols() < kSplitColumns || options.stop_above < std::numeric_limits<double>::infinity()) {
    BranchAndBound search(n, options);
    search.run();
    return search.outcome();
  }
  // Two halves of the initial grid (alternate roots in the sorted order), each searched with its
  // own attained values from the common start and half the patch budget: what each finds and
  // proves does not depend on the other, so the outcome is the same whether the halves run on
  // two threads or one.
  WorstViewpointOptions half = options;
  half.max_patches = std::max(1L, options.max_patches / 2);
  BranchAndBound search(n, half);
  const auto roots = search.prepare();
  const long prepared_cells = search.cells_solved();
  BranchAndBound second = search;
  BranchAndBound* halves[] = {&search, &second};
  parallel_blocks(2, options.threads, [&](long begin, long end) {
    for (long k = begin; k < end; ++k) halves[k]->search_roots(roots, static_cast<int>(k), 2);
  });
  search.absorb(second, prepared_cells);
  return search.outcome();
}

}  // namespace vantage::sdp::internal
