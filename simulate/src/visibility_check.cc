#include "vantage/simulate/visibility_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"

namespace vantage::simulate {
namespace {

/// The visible markers' data vectors (all pairs), as vector_errors() reads them: no certificate
/// (the per-view bound comes from the visibility model, not from a search).
BoundLayout visible_data(const Eigen::Matrix3Xd& points) {
  BoundLayout layout;
  layout.entries = points;
  layout.vectors = false;
  const FreeVectorsOf<3> free =
      build_free_vectors<3>(points, points, {}, free_vector_pairs(points, FreeVectorSet::kAllPairs),
                            PairWeighting::kGeometricMean);
  layout.data.free_vectors = to_string(FreeVectorSet::kAllPairs);
  layout.data.vectors = free.z_object;
  layout.data.pairs = free.pairs;
  return layout;
}

}  // namespace

VisibilityTrial check_visibility_trial(const VisibleView& view, const Scene& visible) {
  VANTAGE_CHECK(visible.model.cols() == static_cast<Eigen::Index>(view.visibility.visible.size()),
                "the visible scene holds the view's visible markers");
  const VectorErrors errors = vector_errors(visible_data(visible.model), visible);
  VisibilityTrial trial;
  trial.direction = view.direction;
  trial.visible = view.visibility.visible;
  trial.draws = view.draws;
  trial.t = view.visibility.t;
  trial.pbar = errors.pbar;
  trial.max_error_rad = errors.angle_rad.maxCoeff();
  const Eigen::VectorXd mismatch = (errors.angle_rad - errors.eq26_rad).cwiseAbs();
  trial.max_mismatch_rad = mismatch.maxCoeff();
  trial.max_mismatch_ratio = mismatch.cwiseQuotient(errors.tolerance_rad).maxCoeff();
  const double view_bound = std::asin(std::min(1.0, view.visibility.t));
  const Eigen::VectorXd excess =
      (errors.angle_rad.array() - view_bound * (1.0 + kBoundRatioTolerance)).max(0.0).matrix();
  trial.view_excess_ratio = excess.cwiseQuotient(errors.tolerance_rad).maxCoeff();
  return trial;
}

VisibilityCheckAccumulator::VisibilityCheckAccumulator(VisibilitySetup setup, bool bound_checked)
    : setup_(std::move(setup)), bound_checked_(bound_checked) {}

void VisibilityCheckAccumulator::add(long trial, const VisibilityTrial& t) {
  ++trials_;
  const bool first = trials_ == 1;
  draws_ += t.draws;
  visible_.add(static_cast<double>(t.visible.size()));
  const auto keep_max = [&](double value, double& max, long& at) {
    if (value > max || first) {
      max = std::max(max, value);
      at = trial;
    }
  };
  keep_max(t.t, max_view_t_, worst_view_trial_);
  keep_max(t.max_error_rad, max_error_rad_, worst_error_trial_);
  keep_max(t.view_excess_ratio, max_view_excess_, worst_excess_trial_);
  keep_max(t.max_mismatch_ratio, max_mismatch_ratio_, worst_mismatch_trial_);
  max_mismatch_rad_ = std::max(max_mismatch_rad_, t.max_mismatch_rad);
  const double view_bound = std::asin(std::min(1.0, t.t));
  if (view_bound > 0.0) max_view_ratio_ = std::max(max_view_ratio_, t.max_error_rad / view_bound);
}

VisibilityCheck VisibilityCheckAccumulator::result() const {
  VisibilityCheck check;
  check.setup = setup_;
  check.bound_checked = bound_checked_;
  check.trials = trials_;
  check.draws = draws_;
  check.visible_markers = visible_.summary();
  check.max_view_t = max_view_t_;
  check.worst_view_trial = worst_view_trial_;
  check.max_error_deg = max_error_rad_ * kDegreesPerRadian;
  check.bound_deg = setup_.bound_rad * kDegreesPerRadian;
  check.max_ratio = setup_.bound_rad > 0.0 ? max_error_rad_ / setup_.bound_rad : 0.0;
  check.max_view_ratio = max_view_ratio_;
  check.max_view_excess_over_tolerance = max_view_excess_;
  check.max_abs_eq26_mismatch_deg = max_mismatch_rad_ * kDegreesPerRadian;
  check.max_eq26_mismatch_over_tolerance = max_mismatch_ratio_;
  const bool certified_holds = !bound_checked_ || check.max_ratio <= 1.0 + kBoundRatioTolerance;
  // t(a) and t_upper are both exact evaluations of the same pairs: rounding apart at most.
  const bool views_below = max_view_t_ <= setup_.t_upper + kBoundRatioTolerance;
  const bool view_holds = !bound_checked_ || max_view_excess_ <= 1.0;
  const bool eq26_holds = !bound_checked_ || max_mismatch_ratio_ <= 1.0;
  check.passed = certified_holds && views_below && view_holds && eq26_holds;
  std::ostringstream why;
  why.precision(9);
  const auto add = [&](bool holds, const auto& write) {
    if (holds) return;
    if (why.tellp() > 0) why << "; ";
    write();
  };
  add(certified_holds, [&] {
    why << "a visible data vector's error " << check.max_error_deg << " deg (trial "
        << worst_error_trial_ << ") exceeds the bound " << check.bound_deg
        << " deg of the certified worst viewpoint under visibility (max_ratio " << check.max_ratio
        << ")";
  });
  add(views_below, [&] {
    why << "the view of trial " << worst_view_trial_ << " has t = " << max_view_t_
        << " above the certified t_upper = " << setup_.t_upper;
  });
  add(view_holds, [&] {
    why << "a visible data vector's error exceeds arccos p-bar of its view by " << max_view_excess_
        << " times its rounding tolerance (trial " << worst_excess_trial_ << ")";
  });
  add(eq26_holds, [&] {
    why << "a measured error of the visible markers differs from Eq. (26) by "
        << max_mismatch_ratio_ << " times its rounding tolerance (trial " << worst_mismatch_trial_
        << ")";
  });
  check.message = why.str();
  return check;
}

}  // namespace vantage::simulate
