#include "vantage/design/augment.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <random>
#include <sstream>

#include "vantage/analysis/common.h"

namespace vantage::design {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Cross products shorter than this do not define a direction.
constexpr double kMinCross = 1e-12;
// Point mode: a new marker closer than this (times the box's largest side) to another marker
// would make a zero free vector; such positions are rejected.
constexpr double kMinSeparation = 1e-9;
// Compass search iteration cap (each iteration either moves or halves the step).
constexpr int kMaxCompassIterations = 400;

std::string fmt(double v, int precision = 6) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

// Two unit vectors spanning the plane perpendicular to unit a.
void perpendicular_basis(const Eigen::Vector3d& a, Eigen::Vector3d* u, Eigen::Vector3d* v) {
  Eigen::Index i;
  a.cwiseAbs().minCoeff(&i);
  *u = a.cross(Eigen::Vector3d::Unit(i)).normalized();
  *v = a.cross(*u).normalized();
}

// Score of a candidate addition; lower t is better, then fewer worst viewpoints, then the larger
// kill margin.
struct Score {
  double t = std::numeric_limits<double>::infinity();
  int n_worst = std::numeric_limits<int>::max();
  double kill_margin = -std::numeric_limits<double>::infinity();
};

bool better(const Score& a, const Score& b, double tie) {
  if (a.t < b.t - tie) return true;
  if (a.t > b.t + tie) return false;
  if (a.n_worst != b.n_worst) return a.n_worst < b.n_worst;
  return a.kill_margin > b.kill_margin;
}

// min over unit c of max_k |a_k.c| (see augment.h) and a minimiser.
double best_kill_level(const std::vector<Eigen::Vector3d>& a, Eigen::Vector3d* argmin,
                       std::vector<Eigen::Vector3d>* points) {
  const int k = static_cast<int>(a.size());
  auto level = [&a](const Eigen::Vector3d& c) {
    double m = 0.0;
    for (const Eigen::Vector3d& ak : a) m = std::max(m, std::abs(ak.dot(c)));
    return m;
  };
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](const Eigen::Vector3d& d) {
    if (d.norm() < kMinCross) return;
    const Eigen::Vector3d c = d.normalized();
    points->push_back(c);
    const double l = level(c);
    if (l < best) {
      best = l;
      *argmin = c;
    }
  };
  if (k == 1) {
    Eigen::Vector3d u, v;
    perpendicular_basis(a[0], &u, &v);
    consider(u);
  }
  for (int i = 0; i < k; ++i) {
    for (int j = i + 1; j < k; ++j) {
      consider(a[i].cross(a[j]));
      for (int l = j + 1; l < k; ++l) {
        for (double s1 : {1.0, -1.0}) {
          for (double s2 : {1.0, -1.0}) consider((a[i] - s1 * a[j]).cross(a[i] - s2 * a[l]));
        }
      }
    }
  }
  return best;
}

// The search for one greedy step and the objective of the direct optimiser.
class Designer {
 public:
  Designer(const Layout& layout, const AugmentOptions& options)
      : layout_(layout), options_(options), points_(layout.mode == LayoutMode::kPoints) {
    const DataVectors data = data_vectors(layout);
    vectors_ = data.vectors;
    markers_ = layout.entries;
    if (points_) {
      const Eigen::Vector3d lo = markers_.rowwise().minCoeff();
      const Eigen::Vector3d hi = markers_.rowwise().maxCoeff();
      const double side = (hi - lo).maxCoeff();
      box_lo_ = lo.array() - options.margin * side;
      box_hi_ = hi.array() + options.margin * side;
      scale_ = (box_hi_ - box_lo_).maxCoeff();
    }
    used_.assign(layout.candidates.cols(), false);
  }

  int vector_count() const { return static_cast<int>(vectors_.cols()); }
  const Eigen::Matrix3Xd& vectors() const { return vectors_; }
  bool points() const { return points_; }
  Eigen::Vector3d box_lo() const { return box_lo_; }
  Eigen::Vector3d box_hi() const { return box_hi_; }
  double scale() const { return scale_; }
  long solves() const { return solves_; }

  WorstCase evaluate(const Eigen::Matrix3Xd& vectors) {
    ++solves_;
    return evaluate_worst_case(vectors);
  }

  // New free vectors of an addition: the direction itself, or p - z_i for every marker. False
  // when the position coincides with a marker (or `extra` markers).
  bool new_vectors(const Eigen::Vector3d& x, const Eigen::Matrix3Xd& markers,
                   Eigen::Matrix3Xd* out) const {
    if (!points_) {
      out->resize(3, 1);
      out->col(0) = x.normalized();
      return true;
    }
    out->resize(3, markers.cols());
    for (Eigen::Index i = 0; i < markers.cols(); ++i) {
      out->col(i) = x - markers.col(i);
      if (out->col(i).norm() < kMinSeparation * scale_) return false;
    }
    return true;
  }

  // Score of adding x given the current worst case; solves only when x kills every worst
  // viewpoint.
  Score score(const Eigen::Vector3d& x, const WorstCase& current, long* screened) {
    Score s;
    Eigen::Matrix3Xd added;
    if (!new_vectors(x, markers_, &added)) return s;
    int survivors = 0;
    double margin = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& a : current.worst_viewpoints) {
      double proj = std::numeric_limits<double>::infinity();
      for (Eigen::Index i = 0; i < added.cols(); ++i) {
        proj = std::min(proj, std::abs(a.dot(added.col(i).normalized())));
      }
      if (proj < current.t - options_.tie_tolerance) {
        margin = std::min(margin, current.t - proj);
      } else {
        ++survivors;
      }
    }
    s.kill_margin = std::isfinite(margin) ? margin : 0.0;
    if (survivors > 0) {
      ++*screened;
      s.t = current.t;
      s.n_worst = survivors;
      return s;
    }
    Eigen::Matrix3Xd all(3, vectors_.cols() + added.cols());
    all << vectors_, added;
    const WorstCase w = evaluate(all);
    s.t = w.t;
    s.n_worst = static_cast<int>(w.worst_viewpoints.size());
    return s;
  }

  // Compass search from x (on the sphere in direction mode, in the box in point mode).
  Eigen::Vector3d polish(Eigen::Vector3d x, Score* s, double step, const WorstCase& current,
                         long* screened) {
    const double stop = options_.refine_tolerance;
    for (int it = 0; it < kMaxCompassIterations && step > stop; ++it) {
      // Axis and diagonal moves: the objective is a max-min with ridges that axis moves alone
      // cannot follow.
      Eigen::Vector3d dirs[14];
      int count = 0;
      if (points_) {
        for (int k = 0; k < 3; ++k) {
          dirs[count++] = Eigen::Vector3d::Unit(k);
          dirs[count++] = -Eigen::Vector3d::Unit(k);
        }
        for (int k = 0; k < 8; ++k) {
          dirs[count++] =
              Eigen::Vector3d(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1) / std::sqrt(3.0);
        }
      } else {
        Eigen::Vector3d u, v;
        perpendicular_basis(x, &u, &v);
        for (int k = 0; k < 8; ++k) {
          const double phi = kPi * k / 4.0;
          dirs[count++] = std::cos(phi) * u + std::sin(phi) * v;
        }
      }
      Eigen::Vector3d best_x = x;
      Score best_s = *s;
      for (int k = 0; k < count; ++k) {
        Eigen::Vector3d y;
        if (points_) {
          y = (x + step * scale_ * dirs[k]).cwiseMax(box_lo_).cwiseMin(box_hi_);
        } else {
          y = (x + step * dirs[k]).normalized();
        }
        const Score sy = score(y, current, screened);
        if (better(sy, best_s, options_.tie_tolerance)) {
          best_s = sy;
          best_x = y;
        }
      }
      if (best_x == x) {
        step *= 0.5;
      } else {
        x = best_x;
        *s = best_s;
      }
    }
    return x;
  }

  // One greedy step.
  AugmentStep step(const WorstCase& current, bool* out_of_candidates) {
    AugmentStep st;
    const long solves_before = solves_;
    struct Option {
      Eigen::Vector3d x;
      int candidate_index;
      Score s;
    };
    std::vector<Option> options;
    auto add = [&](const Eigen::Vector3d& x, int index) {
      options.push_back({x, index, score(x, current, &st.screened)});
    };
    for (Eigen::Index c = 0; c < layout_.candidates.cols(); ++c) {
      if (used_[c]) continue;
      const Eigen::Vector3d x = layout_.candidates.col(c);
      add(points_ ? x : Eigen::Vector3d(x.normalized()), static_cast<int>(c));
    }
    Eigen::Vector3d kill_point = Eigen::Vector3d::UnitX();
    std::vector<Eigen::Vector3d> kill_points;
    st.best_kill_level = best_kill_level(current.worst_viewpoints, &kill_point, &kill_points);
    st.single_vector_can_improve =
        points_ || st.best_kill_level < current.t - options_.tie_tolerance;
    if (!options_.candidates_only) {
      if (points_) {
        const int g = options_.grid_samples;
        for (int i = 0; i < g; ++i) {
          for (int j = 0; j < g; ++j) {
            for (int k = 0; k < g; ++k) {
              const Eigen::Vector3d f(i / (g - 1.0), j / (g - 1.0), k / (g - 1.0));
              add(box_lo_ + f.cwiseProduct(box_hi_ - box_lo_), -1);
            }
          }
        }
      } else {
        for (const Eigen::Vector3d& a : current.worst_viewpoints) {
          Eigen::Vector3d u, v;
          perpendicular_basis(a, &u, &v);
          for (int j = 0; j < options_.circle_samples; ++j) {
            const double th = kPi * j / options_.circle_samples;
            add(std::cos(th) * u + std::sin(th) * v, -1);
          }
        }
        for (const Eigen::Vector3d& c : kill_points) add(c, -1);
      }
    }
    if (options.empty()) {
      *out_of_candidates = true;
      return st;
    }
    std::stable_sort(options.begin(), options.end(), [this](const Option& a, const Option& b) {
      return better(a.s, b.s, options_.tie_tolerance);
    });
    Option chosen = options.front();
    if (!options_.candidates_only) {
      const double step0 =
          points_ ? 1.0 / std::max(2, options_.grid_samples - 1) : kPi / options_.circle_samples;
      const int starts = std::min<int>(options_.refine_starts, static_cast<int>(options.size()));
      for (int r = 0; r < starts; ++r) {
        Option o = options[r];
        o.x = polish(o.x, &o.s, step0, current, &st.screened);
        if (o.x != options[r].x) o.candidate_index = -1;
        if (better(o.s, chosen.s, options_.tie_tolerance)) chosen = o;
      }
    }
    if (chosen.candidate_index >= 0) used_[chosen.candidate_index] = true;
    Eigen::Matrix3Xd added;
    VANTAGE_CHECK(new_vectors(chosen.x, markers_, &added), "chosen addition is degenerate");
    Eigen::Matrix3Xd all(3, vectors_.cols() + added.cols());
    all << vectors_, added;
    vectors_ = all;
    if (points_) {
      Eigen::Matrix3Xd m(3, markers_.cols() + 1);
      m << markers_, chosen.x;
      markers_ = m;
    }
    st.added = chosen.x;
    st.candidate_index = chosen.candidate_index;
    st.worst = evaluate(vectors_);
    st.vector_count = vector_count();
    st.ceiling = pbar_ceiling(st.vector_count);
    st.improved = st.worst.t < current.t - options_.tie_tolerance;
    if (!points_) {
      double nearest = 1.0;
      for (const Eigen::Vector3d& a : current.worst_viewpoints) {
        nearest = std::min(nearest, std::abs(a.dot(chosen.x)));
      }
      st.angle_from_worst_plane_deg = std::asin(std::min(1.0, nearest)) * 180.0 / kPi;
    }
    st.global_solves = solves_ - solves_before;
    std::ostringstream note;
    const int k = static_cast<int>(current.worst_viewpoints.size());
    if (st.improved) {
      note << "p-bar_min rose from " << fmt(current.pbar_min) << " to " << fmt(st.worst.pbar_min);
    } else if (!points_ && !st.single_vector_can_improve) {
      note << "no single vector can raise p-bar_min = " << fmt(current.pbar_min) << ": the " << k
           << " worst viewpoint(s) cannot all be killed at once (min over unit c of max_k |a_k.c| "
           << "= " << fmt(st.best_kill_level) << " >= t = " << fmt(current.t)
           << "); added the vector leaving the fewest worst viewpoints ("
           << st.worst.worst_viewpoints.size() << ")";
    } else if (options_.candidates_only) {
      note << "p-bar_min unchanged at " << fmt(current.pbar_min)
           << ": no remaining candidate kills all " << k << " worst viewpoint(s)";
    } else {
      note << "p-bar_min unchanged at " << fmt(current.pbar_min) << ": no addition found in the "
           << (points_ ? "search box" : "search") << " kills all " << k
           << " worst viewpoint(s); added the one leaving the fewest ("
           << st.worst.worst_viewpoints.size() << ")";
    }
    st.note = note.str();
    return st;
  }

  const Eigen::Matrix3Xd& markers() const { return markers_; }

 private:
  const Layout& layout_;
  const AugmentOptions& options_;
  bool points_;
  Eigen::Matrix3Xd vectors_;
  Eigen::Matrix3Xd markers_;
  Eigen::Vector3d box_lo_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d box_hi_ = Eigen::Vector3d::Zero();
  double scale_ = 1.0;
  std::vector<bool> used_;
  long solves_ = 0;
};

// Data vectors of `base_vectors` plus the K additions in x (3K numbers), or false when an
// addition is degenerate.
bool direct_vectors(const Eigen::Matrix3Xd& base_vectors, const Eigen::Matrix3Xd& base_markers,
                    bool points, double min_separation, const std::vector<double>& x,
                    Eigen::Matrix3Xd* out) {
  const int k = static_cast<int>(x.size() / 3);
  if (!points) {
    out->resize(3, base_vectors.cols() + k);
    out->leftCols(base_vectors.cols()) = base_vectors;
    for (int j = 0; j < k; ++j) {
      const Eigen::Vector3d d(x[3 * j], x[3 * j + 1], x[3 * j + 2]);
      if (!(d.norm() > kMinCross)) return false;
      out->col(base_vectors.cols() + j) = d.normalized();
    }
    return true;
  }
  const Eigen::Index n = base_markers.cols();
  Eigen::Matrix3Xd markers(3, n + k);
  markers.leftCols(n) = base_markers;
  for (int j = 0; j < k; ++j)
    markers.col(n + j) = Eigen::Vector3d(x[3 * j], x[3 * j + 1], x[3 * j + 2]);
  out->resize(3, base_vectors.cols() + k * n + k * (k - 1) / 2);
  out->leftCols(base_vectors.cols()) = base_vectors;
  Eigen::Index col = base_vectors.cols();
  for (int j = 0; j < k; ++j) {
    for (Eigen::Index i = 0; i < n + j; ++i) {
      const Eigen::Vector3d d = markers.col(n + j) - markers.col(i);
      if (d.norm() < min_separation) return false;
      out->col(col++) = d;
    }
  }
  return true;
}

struct DirectObjective {
  Designer* designer;
  const Eigen::Matrix3Xd* base_vectors;
  const Eigen::Matrix3Xd* base_markers;
  bool points;
  double min_separation;
  double best_t = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  Eigen::Matrix3Xd work;
};

double direct_objective(const std::vector<double>& x, std::vector<double>&, void* data) {
  auto* o = static_cast<DirectObjective*>(data);
  if (!direct_vectors(*o->base_vectors, *o->base_markers, o->points, o->min_separation, x,
                      &o->work)) {
    return 1.0;
  }
  const double t = o->designer->evaluate(o->work).t;
  if (t < o->best_t) {
    o->best_t = t;
    o->best_x = x;
  }
  return t;
}

DirectResult run_direct(const Layout& layout, const AugmentOptions& options,
                        const AugmentResult& greedy, Designer* designer) {
  DirectResult out;
  const int k = options.add;
  const bool points = layout.mode == LayoutMode::kPoints;
  const Eigen::Matrix3Xd base_vectors = data_vectors(layout).vectors;
  const Eigen::Matrix3Xd& base_markers = layout.entries;
  const long solves_before = designer->solves();
  if (options.candidates_only) {
    const int nc = static_cast<int>(layout.candidates.cols());
    double subsets = 1.0;
    for (int j = 0; j < k; ++j) subsets = subsets * (nc - j) / (j + 1);
    const double budget =
        static_cast<double>(options.direct_starts) * options.direct_evaluations_per_start;
    if (nc < k || subsets > budget) {
      out.message = "not run: " + fmt(subsets) + " candidate subsets exceed the budget of " +
                    fmt(budget) + " evaluations";
      return out;
    }
    out.method = "exhaustive_candidates";
    std::vector<bool> pick(nc, false);
    std::fill(pick.begin(), pick.begin() + k, true);
    double best = std::numeric_limits<double>::infinity();
    std::vector<int> best_idx;
    Eigen::Matrix3Xd work;
    do {
      std::vector<double> x;
      std::vector<int> idx;
      for (int c = 0; c < nc; ++c) {
        if (!pick[c]) continue;
        idx.push_back(c);
        for (int r = 0; r < 3; ++r) x.push_back(layout.candidates(r, c));
      }
      if (!direct_vectors(base_vectors, base_markers, points,
                          kMinSeparation * std::max(1.0, designer->scale()), x, &work)) {
        continue;
      }
      const double t = designer->evaluate(work).t;
      if (t < best) {
        best = t;
        best_idx = idx;
      }
    } while (std::prev_permutation(pick.begin(), pick.end()));
    if (best_idx.empty()) {
      out.message = "not run: every candidate subset is degenerate";
      return out;
    }
    std::vector<double> x;
    for (int c : best_idx) {
      out.candidate_indices.push_back(c);
      const Eigen::Vector3d v = layout.candidates.col(c);
      out.added.push_back(points ? v : Eigen::Vector3d(v.normalized()));
      for (int r = 0; r < 3; ++r) x.push_back(v(r));
    }
    direct_vectors(base_vectors, base_markers, points, 0.0, x, &work);
    out.worst = designer->evaluate(work);
    out.status = DirectResult::Status::kOk;
    out.global_solves = designer->solves() - solves_before;
    return out;
  }
  out.method = "nlopt_sbplx_multistart";
  DirectObjective obj;
  obj.designer = designer;
  obj.base_vectors = &base_vectors;
  obj.base_markers = &base_markers;
  obj.points = points;
  obj.min_separation = kMinSeparation * designer->scale();
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d lo = designer->box_lo(), hi = designer->box_hi();
  for (int start = 0; start < options.direct_starts; ++start) {
    std::vector<double> x(3 * k);
    for (int j = 0; j < k; ++j) {
      Eigen::Vector3d v;
      if (start == 0) {
        v = greedy.steps[j].added;
      } else if (points) {
        v = lo + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(hi - lo);
      } else {
        v = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
      }
      for (int r = 0; r < 3; ++r) x[3 * j + r] = v(r);
    }
    nlopt::opt opt(nlopt::LN_SBPLX, 3 * k);
    opt.set_min_objective(direct_objective, &obj);
    opt.set_maxeval(options.direct_evaluations_per_start);
    opt.set_xtol_abs(options.refine_tolerance);
    if (points) {
      std::vector<double> lb(3 * k), ub(3 * k);
      for (int j = 0; j < k; ++j) {
        for (int r = 0; r < 3; ++r) {
          lb[3 * j + r] = lo(r);
          ub[3 * j + r] = hi(r);
        }
      }
      opt.set_lower_bounds(lb);
      opt.set_upper_bounds(ub);
      opt.set_initial_step(0.1 * designer->scale());
    } else {
      opt.set_initial_step(0.3);
    }
    double value = 0.0;
    try {
      opt.optimize(x, value);
    } catch (const std::exception&) {
      // NLopt reports round-off or forced stops by exception; the best point seen is kept in
      // the objective, so nothing is lost.
    }
  }
  VANTAGE_CHECK(!obj.best_x.empty(), "direct optimiser evaluated nothing");
  for (int j = 0; j < k; ++j) {
    Eigen::Vector3d v(obj.best_x[3 * j], obj.best_x[3 * j + 1], obj.best_x[3 * j + 2]);
    out.added.push_back(points ? v : Eigen::Vector3d(v.normalized()));
  }
  Eigen::Matrix3Xd work;
  direct_vectors(base_vectors, base_markers, points, 0.0, obj.best_x, &work);
  out.worst = designer->evaluate(work);
  out.status = DirectResult::Status::kOk;
  out.global_solves = designer->solves() - solves_before;
  return out;
}

}  // namespace

const char* to_string(DirectResult::Status status) {
  return status == DirectResult::Status::kOk ? "ok" : "skipped";
}

const char* to_string(AugmentResult::Status status) {
  switch (status) {
    case AugmentResult::Status::kOk:
      return "ok";
    case AugmentResult::Status::kNotCertified:
      return "not_certified";
    case AugmentResult::Status::kNoCandidates:
      return "no_candidates";
  }
  return "unknown";
}

bool AugmentOptions::is_valid(std::string* why) const {
  auto fail = [why](const char* text) {
    if (why != nullptr) *why = text;
    return false;
  };
  if (add < 0) return fail("add: must be >= 0");
  if (!(margin >= 0.0) || !std::isfinite(margin)) return fail("margin: must be finite and >= 0");
  if (circle_samples < 4) return fail("circle_samples: must be >= 4");
  if (grid_samples < 2) return fail("grid_samples: must be >= 2");
  if (refine_starts < 1) return fail("refine_starts: must be >= 1");
  if (!(refine_tolerance > 0.0 && refine_tolerance <= 0.1)) {
    return fail("refine_tolerance: must be in (0, 0.1]");
  }
  if (!(tie_tolerance >= 0.0 && tie_tolerance <= 1e-3)) {
    return fail("tie_tolerance: must be in [0, 1e-3]");
  }
  if (direct_starts < 1) return fail("direct_starts: must be >= 1");
  if (direct_evaluations_per_start < 10) return fail("direct_evaluations_per_start: must be >= 10");
  if (!(coplanarity_threshold >= 0.0)) return fail("coplanarity_threshold: must be >= 0");
  return true;
}

AugmentResult augment_layout(const Layout& layout, const AugmentOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument("AugmentOptions: " + why);
  layout.validate();
  if (options.candidates_only && layout.candidates.cols() == 0) {
    throw InvalidArgument("candidates: candidates_only needs a layout with candidates");
  }
  Designer designer(layout, options);
  AugmentResult result;
  result.initial = designer.evaluate(designer.vectors());
  result.initial_vector_count = designer.vector_count();
  result.initial_ceiling = pbar_ceiling(result.initial_vector_count);
  result.initial_coplanarity = coplanarity(designer.vectors(), options.coplanarity_threshold);
  bool certified = result.initial.certified;
  WorstCase current = result.initial;
  for (int s = 0; s < options.add; ++s) {
    if (options.progress) {
      options.progress("step " + std::to_string(s + 1) + "/" + std::to_string(options.add));
    }
    bool out_of_candidates = false;
    AugmentStep st = designer.step(current, &out_of_candidates);
    if (out_of_candidates) {
      result.status = AugmentResult::Status::kNoCandidates;
      result.message = "the candidates ran out after " + std::to_string(s) + " step(s)";
      break;
    }
    certified = certified && st.worst.certified;
    current = st.worst;
    result.steps.push_back(st);
  }
  result.final_pbar_min = current.pbar_min;
  result.final_coplanarity = coplanarity(designer.vectors(), options.coplanarity_threshold);
  result.augmented = layout;
  const Eigen::Index n0 = layout.entries.cols();
  const Eigen::Index added = static_cast<Eigen::Index>(result.steps.size());
  result.augmented.entries.conservativeResize(3, n0 + added);
  result.augmented.weights.conservativeResize(n0 + added);
  for (Eigen::Index j = 0; j < added; ++j) {
    result.augmented.entries.col(n0 + j) = result.steps[j].added;
    result.augmented.weights(n0 + j) = 1.0;
  }
  if (options.run_direct && options.add > 0 &&
      result.status != AugmentResult::Status::kNoCandidates) {
    if (options.progress) options.progress("direct optimiser");
    result.direct = run_direct(layout, options, result, &designer);
    if (result.direct.status == DirectResult::Status::kOk) {
      certified = certified && result.direct.worst.certified;
    }
  } else {
    result.direct.message = "not run";
  }
  if (!certified && result.status == AugmentResult::Status::kOk) {
    result.status = AugmentResult::Status::kNotCertified;
    result.message = "a global worst-viewpoint certificate did not close";
  }
  result.global_solves = designer.solves();
  return result;
}

}  // namespace vantage::design
