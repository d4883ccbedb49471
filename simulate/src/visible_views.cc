#include "vantage/simulate/visible_views.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "vantage/analysis/common.h"

namespace vantage::simulate {
namespace {

// Visible markers are collinear when every free vector from the first is parallel to this.
constexpr double kCollinearTolerance = 1e-12;

std::string percent(double fraction) {
  std::ostringstream s;
  s.precision(3);
  s << 100.0 * fraction << " %";
  return s.str();
}

VisibilitySetup make_setup(const Layout& layout, const visibility::VisibilityModel& model) {
  const visibility::VisibilityProblem& problem = model.problem();
  VisibilitySetup setup;
  setup.with_body = model.has_body();
  setup.min_visible = problem.min_visible;
  setup.workspace = layout.workspace;
  setup.occlusion_resolution_deg = model.resolution_deg();
  const visibility::VisibilityCoverage coverage =
      visibility::visibility_coverage(problem, VisibleViews::kCoverageSamples);
  setup.trackable_fraction = coverage.trackable_fraction;
  setup.coverage_samples = coverage.samples;
  const std::string sees = "no direction of the workspace sees " +
                           std::to_string(problem.min_visible) +
                           " markers (min_visible) that are not collinear";
  if (coverage.trackable_fraction == 0.0) {
    throw InvalidArgument("visibility", sees + " in " + std::to_string(coverage.samples) +
                                            " sampled directions: there is no view to simulate");
  }
  if (coverage.trackable_fraction < VisibleViews::kMinTrackableFraction) {
    throw InvalidArgument("visibility", "only " + percent(coverage.trackable_fraction) +
                                            " of the workspace is trackable (below " +
                                            percent(VisibleViews::kMinTrackableFraction) +
                                            "): too few directions to draw random views from");
  }
  const visibility::VisibilityWorstViewpoint worst =
      visibility::visibility_worst_viewpoint(problem);
  if (worst.status == visibility::VisibilityWorstViewpoint::Status::kUntrackable) {
    throw InvalidArgument("visibility", sees + ": there is no view to simulate");
  }
  if (!worst.certified()) {
    throw std::runtime_error("the worst viewpoint under visibility is not certified: " +
                             worst.message);
  }
  setup.worst_viewpoint = worst.viewpoint;
  setup.worst_visible = worst.visible_markers;
  setup.t_lower = worst.t_lower;
  setup.t_upper = worst.t_upper;
  setup.pbar_min = worst.pbar_min;
  setup.bound_rad = std::asin(std::min(1.0, worst.t_upper));
  return setup;
}

/// The columns `index` of `m`.
template <class Matrix>
Matrix columns(const Matrix& m, const std::vector<int>& index) {
  Matrix out(m.rows(), static_cast<Eigen::Index>(index.size()));
  for (std::size_t k = 0; k < index.size(); ++k) {
    out.col(static_cast<Eigen::Index>(k)) = m.col(index[k]);
  }
  return out;
}

// min |a.u_ij| over the pairs of `visible` (1 with fewer than two), as direction_visibility.
double pair_t(const Eigen::Matrix3Xd& points, const std::vector<int>& visible,
              const Eigen::Vector3d& a) {
  double t = 1.0;
  for (std::size_t x = 0; x < visible.size(); ++x) {
    for (std::size_t y = x + 1; y < visible.size(); ++y) {
      const Eigen::Vector3d u = (points.col(visible[y]) - points.col(visible[x])).normalized();
      t = std::min(t, std::abs(a.dot(u)));
    }
  }
  return t;
}

}  // namespace

VisibleViews::VisibleViews(const Layout& layout)
    : model_(visibility::VisibilityModel::of(layout)),
      camera_(layout),
      setup_(make_setup(layout, model_)) {}

void VisibleViews::look_from(const Eigen::Vector3d& a, const std::string& field,
                             bool by_direction) {
  if (by_direction && !model_.at(a).trackable) {
    throw InvalidArgument(field,
                          "the body is not trackable from this direction (too few markers "
                          "visible, collinear ones, or outside the workspace)");
  }
  fixed_ = a;
}

Eigen::Vector3d VisibleViews::uniform_direction(TrialRandom& random) const {
  if (!setup_.workspace) return random.unit_vector();
  // Uniform on the cap by area: the height along the axis is uniform on [cos phi, 1].
  const LayoutWorkspace& w = *setup_.workspace;
  const double cos_phi = std::cos(w.half_angle_deg / kDegreesPerRadian);
  const double z = random.uniform(cos_phi, 1.0);
  const double azimuth = random.uniform(0.0, 2.0 * kPi);
  const double r = std::sqrt(std::max(0.0, (1.0 - z) * (1.0 + z)));
  const Eigen::Matrix3d frame = rotation_with_viewpoint(w.axis, 0.0);
  const Eigen::Vector3d a = r * std::cos(azimuth) * frame.row(0).transpose() +
                            r * std::sin(azimuth) * frame.row(1).transpose() +
                            z * frame.row(2).transpose();
  return a / a.norm();
}

VisibleView VisibleViews::draw(TrialRandom& random) const {
  VisibleView view;
  if (fixed_) {
    view.direction = *fixed_;
    view.visibility = model_.at(*fixed_);
    return view;
  }
  for (view.draws = 1; view.draws <= kMaxDraws; ++view.draws) {
    view.direction = uniform_direction(random);
    view.visibility = model_.at(view.direction);
    if (view.visibility.trackable) return view;
  }
  throw std::runtime_error("no trackable view in " + std::to_string(kMaxDraws) +
                           " random directions (the trackable fraction of the workspace is "
                           "estimated at " +
                           percent(setup_.trackable_fraction) + ")");
}

bool VisibleViews::trackable_set(const Eigen::Matrix3Xd& points,
                                 const std::vector<int>& visible) const {
  if (static_cast<int>(visible.size()) < std::max(3, setup_.min_visible)) return false;
  const Eigen::Vector3d first = (points.col(visible[1]) - points.col(visible[0])).normalized();
  for (std::size_t k = 2; k < visible.size(); ++k) {
    const Eigen::Vector3d u = (points.col(visible[k]) - points.col(visible[0])).normalized();
    if (u.cross(first).norm() > kCollinearTolerance) return true;
  }
  return false;
}

VisibleScenes VisibleViews::scenes(const Eigen::Matrix3Xd& points,
                                   const LayoutSceneOptions& options, TrialRandom& random) const {
  const bool pinhole = options.camera == CameraModel::kPinhole;
  for (long attempt = 1;; ++attempt) {
    VisibleScenes out;
    if (!pinhole) {
      out.view = draw(random);
    } else if (fixed_) {
      out.view.direction = *fixed_;
    } else {
      out.view.direction = uniform_direction(random);
      out.view.draws = attempt;
    }
    LayoutSceneOptions whole = options;
    whole.viewpoint = -out.view.direction;
    TrialRandom same_roll = random;  // both scenes draw the roll first
    out.whole = make_layout_scene(points, false, whole, same_roll);
    if (pinhole) {
      // The camera centre in the object frame, and what each marker's line of sight to it sees.
      const Eigen::Vector3d centre = -out.whole.R_true.transpose() * out.whole.p_true;
      out.view.visibility.visible = camera_.visible_from(centre);
      if (!trackable_set(points, out.view.visibility.visible)) {
        if (fixed_) {
          throw InvalidArgument("scene.viewpoint",
                                "the pinhole camera's centre sees fewer than min_visible markers "
                                "that are not collinear (each by its own line of sight)");
        }
        if (attempt >= kMaxDraws) {
          throw std::runtime_error("no trackable pinhole view in " + std::to_string(kMaxDraws) +
                                   " random views");
        }
        continue;
      }
      out.view.visibility.t = pair_t(points, out.view.visibility.visible, out.view.direction);
    }
    const std::vector<int>& visible = out.view.visibility.visible;
    const Eigen::Matrix3Xd seen = columns(points, visible);
    // The visible markers at the whole layout's depth and offset (sizes are the whole layout's,
    // both about the aim point).
    const double scale = (points.colwise() - options.aim).colwise().norm().maxCoeff() /
                         (seen.colwise() - options.aim).colwise().norm().maxCoeff();
    LayoutSceneOptions part = whole;
    part.range = options.range * scale;
    part.lateral_offset = options.lateral_offset * scale;
    out.visible = make_layout_scene(seen, false, part, random);
    return out;
  }
}

}  // namespace vantage::simulate
