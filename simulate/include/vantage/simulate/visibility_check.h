#pragma once

/// The bound check under visibility (docs/math.md §20; bound_check.h is the check seen whole).
///
/// At a trackable view a the data vectors are the free vectors between the markers visible from
/// a, so the paper's promise at that view is the one of those vectors: on the noise-free image
/// of the visible markers, every measured angle(v_i, v_e_i) equals Eq. (26) at that image's p_i
/// and p_bar, and is at most arccos p_bar(a) = asin t(a), with t(a) = min |a.u_ij| over the
/// visible pairs as the visibility model evaluates it (VisibilityModel::at), not as the image
/// measures it; and at most asin(t_upper) of the certified worst viewpoint under visibility.
/// The view's own t(a) must not exceed t_upper either: a drawn trackable view above the
/// certificate would disprove it.
///
/// Tolerances. The ratio to asin(t_upper) is the seen-whole check's (kBoundRatioTolerance). The
/// per-view bound asin t(a) can be tiny (a view nearly perpendicular to a visible pair), where
/// the ratio means nothing: there a vector's measured angle may exceed it by the rounding its
/// inputs allow (VectorErrors::tolerance_rad, the conditioning of Eq. 26 at p near 1), and the
/// excess over the bound in units of that tolerance is what must stay below 1.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "vantage/simulate/bound_check.h"
#include "vantage/simulate/scene.h"
#include "vantage/simulate/statistics.h"
#include "vantage/simulate/visible_views.h"

namespace vantage::simulate {

/// One trial of the check under visibility.
struct VisibilityTrial {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< a, body -> camera
  std::vector<int> visible;                              ///< markers in the image
  long draws = 0;                                        ///< directions drawn for the view
  double t = 1.0;                   ///< t(a) of the visible pairs (the visibility model)
  double pbar = 1.0;                ///< p_bar measured on the visible image (Eq. 24)
  double max_error_rad = 0.0;       ///< largest measured angle over the visible data vectors
  double max_mismatch_rad = 0.0;    ///< largest |measured - Eq. 26|
  double max_mismatch_ratio = 0.0;  ///< largest |measured - Eq. 26| / tolerance
  /// Largest max(0, angle - asin t(a)) / tolerance over the visible data vectors (<= 1: within
  /// the per-view bound).
  double view_excess_ratio = 0.0;
};

/// The check on the noise-free image `visible` of the markers `view` sees.
VisibilityTrial check_visibility_trial(const VisibleView& view, const Scene& visible);

/// Summary over the trials (`vantage simulate --json` "visibility").
struct VisibilityCheck {
  VisibilitySetup setup;
  /// Affine camera: the bound check ran. Pinhole: only the views are summarised (trials, draws,
  /// visible_markers, max_view_t) and the check's fields mean nothing.
  bool bound_checked = true;
  long trials = 0;
  long draws = 0;              ///< directions drawn in all (rejections included)
  Summary visible_markers;     ///< markers per image
  double max_view_t = 0.0;     ///< largest t(a) over the drawn views (<= t_upper)
  long worst_view_trial = 0;   ///< the trial of max_view_t
  double max_error_deg = 0.0;  ///< over the visible data vectors of every trial
  double bound_deg = 0.0;      ///< asin(t_upper) under visibility
  double max_ratio = 0.0;      ///< max_error_deg / bound_deg
  /// Largest error / asin t(a) of a trial (informative: may exceed 1 by rounding where t(a) is
  /// tiny; max_view_excess_over_tolerance decides).
  double max_view_ratio = 0.0;
  double max_view_excess_over_tolerance = 0.0;
  double max_abs_eq26_mismatch_deg = 0.0;
  double max_eq26_mismatch_over_tolerance = 0.0;
  /// max_ratio <= 1 + kBoundRatioTolerance, max_view_t <= t_upper, the view excess and the
  /// Eq. (26) mismatch within their tolerances.
  bool passed = false;
  std::string message;  ///< empty when passed; otherwise which promise failed, and the trial
};

/// The check folded one trial at a time, in trial order, in memory that does not grow with the
/// trials.
class VisibilityCheckAccumulator {
 public:
  /// bound_checked: the trials carry the check (affine camera), not only their views.
  VisibilityCheckAccumulator(VisibilitySetup setup, bool bound_checked);
  void add(long trial, const VisibilityTrial& result);
  VisibilityCheck result() const;

 private:
  VisibilitySetup setup_;
  bool bound_checked_;
  long trials_ = 0;
  long draws_ = 0;
  SummaryAccumulator visible_;
  double max_view_t_ = 0.0;
  double max_error_rad_ = 0.0;
  double max_view_ratio_ = 0.0;
  double max_view_excess_ = 0.0;
  double max_mismatch_rad_ = 0.0;
  double max_mismatch_ratio_ = 0.0;
  long worst_view_trial_ = 0;
  long worst_error_trial_ = 0;
  long worst_excess_trial_ = 0;
  long worst_mismatch_trial_ = 0;
};

}  // namespace vantage::simulate
