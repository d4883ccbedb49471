#include "box_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

namespace vantage::design::internal {
namespace {

/// A viewpoint and g(a) = min_j |a.n_j| over the current data vectors.
struct View {
  Eigen::Vector3d a;
  double g;
};

struct Cell {
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  double bound = 0.0;  // no position of the cell has t below this
  int depth = 0;       // halvings from the whole box: coarse cells go first
  std::array<int, kCellViewpoints> views{};
  int view_count = 0;
};

struct MostPromisingFirst {
  bool operator()(const Cell& x, const Cell& y) const {
    if (x.depth != y.depth) return x.depth > y.depth;
    return x.bound > y.bound;
  }
};

class Search {
 public:
  Search(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Matrix3Xd& markers,
         const Eigen::Matrix3Xd& unit_vectors)
      : markers_(markers),
        unit_vectors_(unit_vectors),
        min_width_(kMinCellFraction * (hi - lo).maxCoeff()),
        min_marker_width_(kMinMarkerCellFraction * (hi - lo).maxCoeff()) {}

  int add_view(const Eigen::Vector3d& a) {
    views_.push_back({a, (unit_vectors_.transpose() * a).cwiseAbs().minCoeff()});
    return static_cast<int>(views_.size()) - 1;
  }

  // min(g(a), min_i inf over the cell of |a.u_i(p)|).
  double view_bound(const Cell& c, const View& v) const {
    double bound = v.g;
    for (Eigen::Index i = 0; i < markers_.cols() && bound > 0.0; ++i) {
      double lowest = std::numeric_limits<double>::infinity();
      double highest = -lowest;
      double cosine = lowest;
      for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d corner(k & 1 ? c.hi.x() : c.lo.x(), k & 2 ? c.hi.y() : c.lo.y(),
                                     k & 4 ? c.hi.z() : c.lo.z());
        const Eigen::Vector3d d = corner - markers_.col(i);
        const double s = v.a.dot(d);
        lowest = std::min(lowest, s);
        highest = std::max(highest, s);
        const double length = d.norm();
        cosine = std::min(cosine, length > 0.0 ? std::abs(s) / length : 0.0);
      }
      bound = std::min(bound, lowest <= 0.0 && highest >= 0.0 ? 0.0 : cosine);
    }
    return bound;
  }

  // Keeps the kCellViewpoints views (of the cell's and `extra`) that bound it best; sets bound.
  void rebound(Cell* c, const std::vector<int>& extra) const {
    std::vector<std::pair<double, int>> ranked;
    for (int k = 0; k < c->view_count; ++k) {
      ranked.emplace_back(view_bound(*c, views_[c->views[k]]), c->views[k]);
    }
    for (int v : extra) ranked.emplace_back(view_bound(*c, views_[v]), v);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    c->view_count = static_cast<int>(std::min<std::size_t>(ranked.size(), kCellViewpoints));
    for (int k = 0; k < c->view_count; ++k) c->views[k] = ranked[k].second;
    if (c->view_count > 0) c->bound = std::max(c->bound, ranked.front().first);
  }

  // The width below which `c` is not halved: larger when it touches a marker.
  double min_width(const Cell& c) const {
    const double width = (c.hi - c.lo).maxCoeff();
    for (Eigen::Index i = 0; i < markers_.cols(); ++i) {
      const Eigen::Vector3d outside =
          (c.lo - markers_.col(i)).cwiseMax(markers_.col(i) - c.hi).cwiseMax(0.0);
      if (outside.norm() <= width) return min_marker_width_;
    }
    return min_width_;
  }

 private:
  const Eigen::Matrix3Xd& markers_;
  const Eigen::Matrix3Xd& unit_vectors_;
  const double min_width_;
  const double min_marker_width_;
  std::vector<View> views_;
};

}  // namespace

BoxSearchResult search_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                           const Eigen::Matrix3Xd& markers, const Eigen::Matrix3Xd& unit_vectors,
                           const std::vector<Eigen::Vector3d>& worst_viewpoints,
                           const Eigen::Vector3d& x, const Score& score, double tolerance,
                           double tie_tolerance, long max_solves, const BoxSearchCalls& calls) {
  Search search(lo, hi, markers, unit_vectors);
  BoxSearchResult out;
  out.x = x;
  out.score = score;
  const long first_solve = calls.solves();
  const double side = (hi - lo).maxCoeff();

  std::priority_queue<Cell, std::vector<Cell>, MostPromisingFirst> queue;
  Cell root;
  root.lo = lo;
  root.hi = hi;
  std::vector<int> initial;
  for (const Eigen::Vector3d& a : worst_viewpoints) initial.push_back(search.add_view(a));
  search.rebound(&root, initial);
  queue.push(root);
  while (!queue.empty() && calls.solves() - first_solve < max_solves) {
    Cell c = queue.top();
    queue.pop();
    if (c.bound >= out.score.t - tolerance) continue;  // U fell since it was queued
    const Eigen::Vector3d centre = 0.5 * (c.lo + c.hi);
    std::vector<Eigen::Vector3d> viewpoints;
    Score s = calls.probe(centre, &viewpoints);
    std::vector<int> fresh;
    for (const Eigen::Vector3d& a : viewpoints) fresh.push_back(search.add_view(a));
    search.rebound(&c, fresh);
    if (s.t < out.score.t - tie_tolerance) {
      const Eigen::Vector3d polished = calls.polish(centre, &s, (c.hi - c.lo).maxCoeff() / side);
      if (better(s, out.score, tie_tolerance)) {
        out.x = polished;
        out.score = s;
      }
    }
    if (c.bound >= out.score.t - tolerance) continue;
    Eigen::Index axis = 0;
    (c.hi - c.lo).maxCoeff(&axis);
    if (c.hi(axis) - c.lo(axis) < search.min_width(c)) {
      ++out.unresolved;
      continue;
    }
    const double middle = 0.5 * (c.lo(axis) + c.hi(axis));
    ++c.depth;
    for (int half = 0; half < 2; ++half) {
      Cell child = c;
      (half == 0 ? child.hi : child.lo)(axis) = middle;
      search.rebound(&child, {});
      if (child.bound < out.score.t - tolerance) queue.push(child);
    }
  }
  // Cells the budget left unexamined bound t by their own bounds.
  double lowest_queued = std::numeric_limits<double>::infinity();
  out.closed = true;
  for (; !queue.empty(); queue.pop()) {
    if (queue.top().bound >= out.score.t - tolerance) continue;
    out.closed = false;
    lowest_queued = std::min(lowest_queued, queue.top().bound);
  }
  out.t_lower = std::max(0.0, std::min(out.score.t - tolerance, lowest_queued));
  out.solves = calls.solves() - first_solve;
  return out;
}

}  // namespace vantage::design::internal
