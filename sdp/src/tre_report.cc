#include "vantage/sdp/tre_report.h"

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/sdp/visibility_model.h"

namespace vantage::sdp {
namespace {

constexpr long kTreMinTrials = 1000;

TreAtDirection tre_at(const VisibilityProblem& problem, const Eigen::Vector3d& target,
                      const FleModel& fle, const Eigen::Vector3d& a) {
  TreAtDirection at;
  at.direction = a;
  const DirectionVisibility seen = direction_visibility(problem, a);
  at.visible_markers = seen.visible;
  if (!seen.trackable) return at;
  at.covariance = tre_covariance(problem.points, seen.visible, target, fle, a);
  at.tracked = true;
  at.rms = std::sqrt(at.covariance.trace());
  return at;
}

}  // namespace

bool TreOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!fle.is_valid(&inner)) {
    if (why != nullptr) *why = "fle." + inner;
    return false;
  }
  if (direction && !(direction->allFinite() && direction->norm() > 0.0)) {
    if (why != nullptr) *why = "direction: must be finite and non-zero";
    return false;
  }
  if (monte_carlo_trials != 0 && monte_carlo_trials < kTreMinTrials) {
    if (why != nullptr) *why = "monte_carlo_trials: must be 0 or >= 1000";
    return false;
  }
  if (threads < 0) {
    if (why != nullptr) *why = "threads: must be >= 0";
    return false;
  }
  return search.is_valid(why);
}

VisibilityProblem tre_visibility_problem(const Layout& layout) {
  if (layout.visibility) return VisibilityModel::of(layout).problem();
  VisibilityProblem problem;
  problem.points = layout.entries;
  const Eigen::Index n = layout.entries.cols();
  problem.normals = Eigen::Matrix3Xd::Zero(3, n);
  problem.normals.row(2).setOnes();
  problem.cos_cone = Eigen::VectorXd::Constant(n, -1.0);
  problem.min_visible = 3;
  if (layout.workspace) {
    problem.workspace = Workspace{layout.workspace->axis,
                                  std::cos(layout.workspace->half_angle_deg * M_PI / 180.0)};
    if (layout.workspace->half_angle_deg >= 180.0) problem.workspace.reset();
  }
  return problem;
}

TreReport tre_report(const Layout& layout, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& options) {
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument("points", "the TRE needs a layout of marker points, not vectors");
  }
  if (targets.empty()) throw InvalidArgument("target", "give at least one target");
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!targets[i].allFinite()) {
      throw InvalidArgument("target", static_cast<long>(i), "must be finite");
    }
  }
  std::string why;
  if (!options.is_valid(&why)) throw InvalidArgument(why);
  layout.validate();
  // The model owns the occlusion grid the problem points to.
  std::optional<VisibilityModel> model;
  VisibilityProblem problem;
  if (layout.visibility) {
    model = VisibilityModel::of(layout);
    problem = model->problem();
  } else {
    problem = tre_visibility_problem(layout);
  }
  TreReport report;
  report.fle = options.fle;
  report.markers = static_cast<int>(layout.entries.cols());
  report.min_visible = problem.min_visible;
  report.with_normals = layout.visibility.has_value();
  report.with_body = model && model->has_body();
  for (const Eigen::Vector3d& target : targets) {
    TreTargetReport t;
    t.target = target;
    if (options.fle.from_rms) {
      t.rms_isotropic = tre_rms_isotropic(problem.points, target, options.fle.rms());
    }
    if (options.direction) {
      t.at_direction = tre_at(problem, target, options.fle, options.direction->normalized());
    }
    t.extremes = tre_extremes(problem, target, options.fle, options.search);
    if (options.monte_carlo_trials > 0) {
      const bool at_given = t.at_direction && t.at_direction->tracked;
      const Eigen::Vector3d a = at_given ? t.at_direction->direction : t.extremes.worst.direction;
      const std::vector<int>& visible =
          at_given ? t.at_direction->visible_markers : t.extremes.worst.visible_markers;
      if (at_given || t.extremes.worst.status != TreExtreme::Status::kUntracked) {
        t.monte_carlo_direction = a;
        t.monte_carlo = tre_monte_carlo(problem.points, visible, target, options.fle, a,
                                        options.monte_carlo_trials, options.seed, options.threads);
      }
    }
    report.targets.push_back(std::move(t));
  }
  return report;
}

}  // namespace vantage::sdp
