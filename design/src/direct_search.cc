#include "direct_search.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "text.h"
#include "vantage/analysis/build_options.h"
#include "vantage/analysis/common.h"

#if VANTAGE_WITH_NLOPT
#include <nlopt.hpp>
#endif

namespace vantage::design::internal {
namespace {

// AugmentOptions::min_distance_difference for the base markers and the K positions packed in x
// (point mode; always true without the constraint).
bool keeps_distance_difference(const Designer& designer, const Eigen::Matrix3Xd& base_markers,
                               const std::vector<double>& x) {
  if (!(designer.options().min_distance_difference > 0.0)) return true;
  const Eigen::Index k = static_cast<Eigen::Index>(x.size() / 3);
  Eigen::Matrix3Xd markers(3, base_markers.cols() + k);
  markers.leftCols(base_markers.cols()) = base_markers;
  for (Eigen::Index j = 0; j < k; ++j) {
    markers.col(base_markers.cols() + j) = Eigen::Vector3d(x[3 * j], x[3 * j + 1], x[3 * j + 2]);
  }
  return designer.keeps_distance_difference(markers);
}

#if VANTAGE_WITH_NLOPT
// The objective value of a degenerate set of additions, or of one that breaks
// min_distance_difference: t = 1 is the worst any layout can have (p-bar_min = 0), so the
// optimiser moves away from it, and it is never kept as the best.
constexpr double kDegenerateObjective = 1.0;

struct DirectObjective {
  Designer* designer;
  const Eigen::Matrix3Xd* base_vectors;
  const Eigen::Matrix3Xd* base_markers;
  double min_separation;
  double best_t = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  Eigen::Matrix3Xd work;
};

double direct_objective(const std::vector<double>& x, std::vector<double>&, void* data) {
  auto* o = static_cast<DirectObjective*>(data);
  if (!o->designer->space().all_new_vectors(*o->base_vectors, *o->base_markers, o->min_separation,
                                            x, &o->work) ||
      !keeps_distance_difference(*o->designer, *o->base_markers, x)) {
    return kDegenerateObjective;
  }
  const double t =
      o->designer->evaluate_added(o->work.rightCols(o->work.cols() - o->base_vectors->cols())).t;
  if (t < o->best_t) {
    o->best_t = t;
    o->best_x = x;
  }
  return t;
}
#endif

// The result for the additions packed in x: their worst case and the solve count.
void finish(const Layout& layout, const std::vector<double>& x, long solves_before,
            Designer* designer, DirectResult* out) {
  Eigen::Matrix3Xd work;
  designer->space().all_new_vectors(data_vectors(layout).vectors, layout.entries, 0.0, x, &work);
  out->worst = designer->evaluate(work);
  out->status = DirectResult::Status::kOk;
  out->global_solves = designer->solves() - solves_before;
}

}  // namespace

DirectResult exhaustive_candidates(const Layout& layout, const AugmentOptions& options,
                                   double expected_t, Designer* designer) {
  DirectResult out;
  const int k = options.add;
  const long solves_before = designer->solves();
  const AdditionSpace& space = designer->space();
  const Eigen::Matrix3Xd base_vectors = data_vectors(layout).vectors;
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
  const double min_separation = kMinSeparation * std::max(1.0, space.scale());
  designer->prepare(base_vectors, expected_t);
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
    if (!space.all_new_vectors(base_vectors, layout.entries, min_separation, x, &work) ||
        !keeps_distance_difference(*designer, layout.entries, x)) {
      continue;
    }
    // Only a subset that beats the best so far needs its exact t.
    const double t =
        designer->evaluate_added(work.rightCols(work.cols() - base_vectors.cols()), best).t;
    if (t < best) {
      best = t;
      best_idx = idx;
    }
  } while (std::prev_permutation(pick.begin(), pick.end()));
  if (best_idx.empty()) {
    out.message = "not run: every candidate subset is degenerate or breaks min_distance_difference";
    return out;
  }
  std::vector<double> x;
  for (int c : best_idx) {
    out.candidate_indices.push_back(c);
    const Eigen::Vector3d v = layout.candidates.col(c);
    out.added.push_back(space.addition(v));
    for (int r = 0; r < 3; ++r) x.push_back(v(r));
  }
  finish(layout, x, solves_before, designer, &out);
  return out;
}

#if !VANTAGE_WITH_NLOPT
DirectResult multistart_search(const Layout&, const AugmentOptions&, const AugmentResult&,
                               Designer*) {
  DirectResult out;
  out.message = std::string("not run: ") + kWithoutNlopt;
  return out;
}
#else
DirectResult multistart_search(const Layout& layout, const AugmentOptions& options,
                               const AugmentResult& greedy, Designer* designer) {
  DirectResult out;
  const int k = options.add;
  const long solves_before = designer->solves();
  const AdditionSpace& space = designer->space();
  const Eigen::Matrix3Xd base_vectors = data_vectors(layout).vectors;
  out.method = "nlopt_sbplx_multistart";
  DirectObjective obj;
  obj.designer = designer;
  obj.base_vectors = &base_vectors;
  obj.base_markers = &layout.entries;
  obj.min_separation = kMinSeparation * space.scale();
  designer->prepare(base_vectors,
                    greedy.steps.empty() ? greedy.initial.t : greedy.steps.back().worst.t);
  RandomStarts random(options.seed);
  for (int start = 0; start < options.direct_starts; ++start) {
    if (options.progress) {
      options.progress("direct optimiser, start " + std::to_string(start + 1) + "/" +
                       std::to_string(options.direct_starts));
    }
    std::vector<double> x(3 * k);
    for (int j = 0; j < k; ++j) {
      const Eigen::Vector3d v = start == 0 ? greedy.steps[j].added : space.random_addition(&random);
      for (int r = 0; r < 3; ++r) x[3 * j + r] = v(r);
    }
    nlopt::opt opt(nlopt::LN_SBPLX, 3 * k);
    opt.set_min_objective(direct_objective, &obj);
    opt.set_maxeval(options.direct_evaluations_per_start);
    opt.set_xtol_abs(options.refine_tolerance);
    const AdditionSpace::DirectBox box = space.direct_box(k);
    if (!box.lower.empty()) {
      opt.set_lower_bounds(box.lower);
      opt.set_upper_bounds(box.upper);
    }
    opt.set_initial_step(box.initial_step);
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
    const Eigen::Vector3d v(obj.best_x[3 * j], obj.best_x[3 * j + 1], obj.best_x[3 * j + 2]);
    out.added.push_back(space.addition(v));
  }
  finish(layout, obj.best_x, solves_before, designer, &out);
  return out;
}
#endif

}  // namespace vantage::design::internal
