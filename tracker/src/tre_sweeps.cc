// The tip-axis and polar sweeps of docs/math.md §23 ("Sweeps and figures").

#include "vantage/tracker/tre_sweeps.h"

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/scaling.h"

namespace vantage::tracker {
namespace {

// A first target this close to the centroid (relative to the markers' radius) has no tip axis.
constexpr double kTreSweepAxisTolerance = 1e-12;
constexpr int kTreSweepMaxSamples = 100000;

// The curve of `targets` at line of sight a (unit): one visible set, since V(a) does not depend
// on the target.
TreCurve tre_sweep_curve(const TreModel& model, const std::string& label, const Eigen::Vector3d& a,
                         const std::vector<Eigen::Vector3d>& targets) {
  TreCurve curve;
  curve.label = label;
  curve.direction = a;
  const TreAtDirection first = model.at(targets.front(), a);
  curve.tracked = first.tracked;
  curve.visible_markers = first.visible_markers;
  if (!curve.tracked) return curve;
  curve.rms.reserve(targets.size());
  for (const Eigen::Vector3d& r : targets) curve.rms.push_back(model.at(r, a).rms);
  return curve;
}

std::vector<double> tre_sweep_isotropic(const TreModel& model,
                                        const std::vector<Eigen::Vector3d>& targets) {
  std::vector<double> rms;
  if (!model.fle().from_rms) return rms;
  rms.reserve(targets.size());
  for (const Eigen::Vector3d& r : targets) {
    rms.push_back(tre_rms_isotropic(model.problem().points, r, model.fle().rms()));
  }
  return rms;
}

// The curve at a reported worst or best direction; none is tracked when no direction is.
TreCurve tre_extreme_curve(const TreModel& model, const std::string& label,
                           const TreExtreme& extreme, const std::vector<Eigen::Vector3d>& targets) {
  if (extreme.status != TreExtreme::Status::kUntracked) {
    return tre_sweep_curve(model, label, extreme.direction, targets);
  }
  TreCurve curve;
  curve.label = label;
  curve.direction = extreme.direction;
  return curve;
}

}  // namespace

bool TreSweepOptions::is_valid(std::string* why) const {
  auto fail = [why](const std::string& message) {
    if (why != nullptr) *why = message;
    return false;
  };
  if (tip_axis_samples < 2 || tip_axis_samples > kTreSweepMaxSamples) {
    return fail("tip_axis_samples: must be in [2, 100000]");
  }
  if (!(std::isfinite(tip_axis_extent) && tip_axis_extent > 0.0)) {
    return fail("tip_axis_extent: must be finite and > 0");
  }
  if (radius && !(std::isfinite(*radius) && *radius > 0.0)) {
    return fail("radius: must be finite and > 0");
  }
  if (polar_step_deg < 1 || polar_step_deg > 90 || 360 % polar_step_deg != 0) {
    return fail("polar_step_deg: must be a divisor of 360 in [1, 90]");
  }
  return true;
}

Eigen::Vector3d TrePolarSweep::target(int axis, std::size_t k) const {
  const double t = angle_deg[k] * kPi / 180.0;
  const Eigen::Vector3d e_i = Eigen::Vector3d::Unit((axis + 1) % 3);
  const Eigen::Vector3d e_j = Eigen::Vector3d::Unit((axis + 2) % 3);
  return centroid + radius * (std::cos(t) * e_i + std::sin(t) * e_j);
}

TreSweeps tre_sweeps(const TreModel& model, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& options, const TreSweepOptions& sweep) {
  std::string why;
  if (!sweep.is_valid(&why)) throw InvalidArgument(why);
  if (sweep.radius && *sweep.radius > kTreMaxLength) {
    throw InvalidArgument("radius",
                          "exceeds 1e50, the largest length the TRE is computed for "
                          "in double precision (docs/math.md §23)");
  }
  TreSweeps out;
  out.report = tre_report(model, targets, options);
  const Eigen::Vector3d g = model.centroid();
  const Eigen::Matrix3Xd& points = model.problem().points;
  const double spread = (points.colwise() - g).colwise().norm().maxCoeff();
  const Eigen::Vector3d offset = targets.front() - g;
  const double d1 = offset.norm();
  if (!(d1 > kTreSweepAxisTolerance * spread)) {
    throw InvalidArgument("target", 0,
                          "is the markers' centroid: the tip axis (centroid to target) is "
                          "undefined");
  }
  const TreTargetReport& first = out.report.targets.front();

  TreTipAxisSweep& tip = out.tip_axis;
  tip.centroid = g;
  tip.axis = offset / d1;
  tip.target_distance = d1;
  const int n = sweep.tip_axis_samples;
  std::vector<Eigen::Vector3d> tip_targets;
  for (int k = 0; k < n; ++k) {
    tip.distance.push_back(sweep.tip_axis_extent * d1 * k / (n - 1));
    tip_targets.push_back(tip.target(static_cast<std::size_t>(k)));
  }
  tip.curves.push_back(tre_extreme_curve(model, "worst", first.extremes.worst, tip_targets));
  tip.curves.push_back(tre_extreme_curve(model, "best", first.extremes.best, tip_targets));
  if (options.direction) {
    tip.curves.push_back(
        tre_sweep_curve(model, "direction", unit_direction(*options.direction), tip_targets));
  }
  tip.rms_isotropic = tre_sweep_isotropic(model, tip_targets);

  TrePolarSweep& polar = out.polar;
  polar.centroid = g;
  polar.radius = sweep.radius ? *sweep.radius : d1;
  for (int deg = 0; deg <= 360; deg += sweep.polar_step_deg) polar.angle_deg.push_back(deg);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Eigen::Vector3d> circle;
    for (std::size_t k = 0; k < polar.angle_deg.size(); ++k)
      circle.push_back(polar.target(axis, k));
    polar.curves[static_cast<std::size_t>(axis)] =
        tre_extreme_curve(model, "worst", first.extremes.worst, circle);
    polar.rms_isotropic[static_cast<std::size_t>(axis)] = tre_sweep_isotropic(model, circle);
  }
  return out;
}

}  // namespace vantage::tracker
