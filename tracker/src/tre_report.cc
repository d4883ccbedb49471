#include "vantage/tracker/tre_report.h"

#include <cmath>

#include "vantage/analysis/common.h"
#include "vantage/analysis/scaling.h"

namespace vantage::tracker {
namespace {

constexpr long kTreMinTrials = 1000;

void check_tre_targets(const std::vector<Eigen::Vector3d>& targets) {
  if (targets.empty()) throw InvalidArgument("target", "give at least one target");
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!targets[i].allFinite()) {
      throw InvalidArgument("target", static_cast<long>(i), "must be finite");
    }
  }
}

// An option out of range as an error naming its field ("monte_carlo_trials", "threads",
// "fle.sigma_perp", "direction" or the search's), for each front end to name as it calls it.
void check_tre_options(const TreOptions& options) {
  std::string why;
  if (options.is_valid(&why)) return;
  const std::size_t colon = why.find(": ");
  if (colon == std::string::npos) throw InvalidArgument(why);
  throw InvalidArgument(why.substr(0, colon), why.substr(colon + 2));
}

// The trials_done callback of tre_monte_carlo() that words options.progress's stage; target 0:
// the only one.
std::function<void(long)> monte_carlo_progress(const TreOptions& options, std::size_t target,
                                               std::size_t targets) {
  if (!options.progress) return {};
  const std::string prefix =
      target == 0 ? std::string()
                  : "target " + std::to_string(target) + "/" + std::to_string(targets) + ", ";
  return [&options, prefix](long done) {
    options.progress(prefix + "Monte Carlo " + std::to_string(done) + "/" +
                     std::to_string(options.monte_carlo_trials) + " trials");
  };
}

}  // namespace

bool TreOptions::is_valid(std::string* why) const {
  std::string inner;
  if (!fle.is_valid(&inner)) {
    if (why != nullptr) *why = "fle." + inner;
    return false;
  }
  if (direction && unit_direction(*direction).isZero()) {
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

visibility::VisibilityProblem tre_visibility_problem(const Layout& layout) {
  if (layout.visibility) return visibility::VisibilityModel::of(layout).problem();
  visibility::VisibilityProblem problem;
  problem.points = layout.entries;
  const Eigen::Index n = layout.entries.cols();
  problem.normals = Eigen::Matrix3Xd::Zero(3, n);
  problem.normals.row(2).setOnes();
  problem.cos_cone = Eigen::VectorXd::Constant(n, -1.0);
  problem.min_visible = 3;
  if (layout.workspace) {
    problem.workspace = visibility::Workspace{
        layout.workspace->axis, std::cos(layout.workspace->half_angle_deg * kPi / 180.0)};
    if (layout.workspace->half_angle_deg >= 180.0) problem.workspace.reset();
  }
  return problem;
}

TreModel::TreModel(const Layout& layout, const FleModel& fle) : fle_(fle) {
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument("points", "the TRE needs a layout of marker points, not vectors");
  }
  std::string why;
  if (!fle.is_valid(&why)) throw InvalidArgument("fle." + why);
  layout.validate();
  if (layout.visibility) {
    visibility_ = visibility::VisibilityModel::of(layout);
    problem_ = visibility_->problem();
  } else {
    problem_ = tre_visibility_problem(layout);
  }
}

bool TreModel::in_workspace(const Eigen::Vector3d& a) const {
  return !problem_.workspace ||
         a.dot(problem_.workspace->axis) >= problem_.workspace->cos_half_angle;
}

TreAtDirection TreModel::at(const Eigen::Vector3d& target_tool, const Eigen::Vector3d& a) const {
  TreAtDirection at;
  at.direction = a;
  const visibility::DirectionVisibility seen = visibility::direction_visibility(problem_, a);
  at.visible_markers = seen.visible;
  if (!seen.trackable) return at;
  at.covariance = tre_covariance(problem_.points, seen.visible, target_tool, fle_, a);
  at.tracked = true;
  at.rms = std::sqrt(at.covariance.trace());
  return at;
}

TreReport tre_report(const Layout& layout, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& options) {
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument("points", "the TRE needs a layout of marker points, not vectors");
  }
  check_tre_targets(targets);
  check_tre_options(options);
  return tre_report(TreModel(layout, options.fle), targets, options);
}

TreReport tre_report(const TreModel& model, const std::vector<Eigen::Vector3d>& targets,
                     const TreOptions& given) {
  TreOptions options = given;
  options.fle = model.fle();
  check_tre_targets(targets);
  check_tre_options(options);
  const visibility::VisibilityProblem& problem = model.problem();
  TreReport report;
  report.fle = options.fle;
  report.markers = static_cast<int>(problem.points.cols());
  report.min_visible = problem.min_visible;
  report.with_normals = model.with_normals();
  report.with_body = model.with_body();
  report.five_dof = tool_axis(problem.points, &report.axis_point, &report.axis);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    check_tre_range(problem.points, targets[i], options.fle,
                    targets.size() > 1 ? static_cast<long>(i) : -1L);
  }
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const Eigen::Vector3d& target = targets[i];
    TreTargetReport t;
    t.target = target;
    if (options.fle.from_rms) {
      t.rms_isotropic = tre_rms_isotropic(problem.points, target, options.fle.rms());
    }
    if (options.direction) {
      t.at_direction = model.at(target, unit_direction(*options.direction));
    }
    t.extremes = tre_extremes(problem, target, options.fle, options.search);
    if (options.monte_carlo_trials > 0) {
      const bool at_given = t.at_direction && t.at_direction->tracked;
      const Eigen::Vector3d a = at_given ? t.at_direction->direction : t.extremes.worst.direction;
      const std::vector<int>& visible =
          at_given ? t.at_direction->visible_markers : t.extremes.worst.visible_markers;
      if (at_given || t.extremes.worst.status != TreExtreme::Status::kUntracked) {
        t.monte_carlo_direction = a;
        t.monte_carlo = tre_monte_carlo(
            problem.points, visible, target, options.fle, a, options.monte_carlo_trials,
            options.seed, options.threads,
            monte_carlo_progress(options, targets.size() > 1 ? i + 1 : 0, targets.size()));
      }
    }
    report.targets.push_back(std::move(t));
  }
  return report;
}

}  // namespace vantage::tracker
