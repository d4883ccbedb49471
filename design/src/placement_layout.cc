#include "vantage/design/placement_layout.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "vantage/analysis/common.h"

namespace vantage::design {
namespace {

constexpr const char* kObjective =
    "every workspace direction trackable, then the largest certified p-bar_min under visibility";
constexpr const char* kRobustObjective =
    "every workspace direction trackable, then under the loss of any one marker the largest "
    "coverage and certified p-bar_min";

}  // namespace

Layout surface_sites_layout(const SurfaceSites& sites, const Mesh& body,
                            const std::string& body_path, double cone_half_angle_deg) {
  const Eigen::Index n = sites.points.cols();
  Layout layout;
  layout.mode = LayoutMode::kPoints;
  layout.entries = sites.points;
  layout.weights = Eigen::VectorXd::Ones(n);
  MarkerVisibility visibility;
  visibility.normals = sites.normals;
  visibility.cone_half_angle_deg = Eigen::VectorXd::Constant(n, cone_half_angle_deg);
  visibility.body = body;
  visibility.body_path = body_path;
  layout.visibility = std::move(visibility);
  return layout;
}

void check_marker_diameter(double diameter, double extent) {
  if (!(diameter >= 0.0) || !std::isfinite(diameter)) {
    throw InvalidArgument("marker_diameter", "must be a finite number >= 0");
  }
  if (diameter > extent) {
    std::ostringstream message;
    message.precision(6);
    message << "a sphere of diameter " << diameter << " is wider than the whole body (size "
            << extent << "): another unit?";
    throw InvalidArgument("marker_diameter", message.str());
  }
}

double extent(const Eigen::Matrix3Xd& points) {
  if (points.cols() == 0) return 0.0;
  return (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
}

Eigen::Matrix3Xd sphere_centres(const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
                                double diameter) {
  check_marker_diameter(diameter, std::numeric_limits<double>::max());
  return points + 0.5 * diameter * normals;
}

Layout sphere_centres(Layout sites, double diameter) {
  if (!sites.visibility) throw InvalidArgument("sites", "the sites need normals");
  sites.entries = sphere_centres(sites.entries, sites.visibility->normals, diameter);
  return sites;
}

std::string site_name(const Layout& sites, int s) {
  return sites.names.empty() ? "site" + std::to_string(s) : sites.entry_name(s);
}

Layout placed_layout(const Layout& sites, const PlacementResult& result,
                     const PlacedLayoutRecord& record) {
  if (!sites.visibility) throw InvalidArgument("sites", "the sites need normals");
  const MarkerVisibility& from = *sites.visibility;
  const int n_candidates = record.n_candidates;
  Layout layout;
  const std::string suffix = " (placed)";
  const bool placed_before =
      sites.name.size() >= suffix.size() &&
      sites.name.compare(sites.name.size() - suffix.size(), suffix.size(), suffix) == 0;
  layout.name = sites.name.empty() ? "placed" : placed_before ? sites.name : sites.name + suffix;
  const Eigen::Index k = static_cast<Eigen::Index>(result.chosen.size());
  layout.description =
      "vantage place: " + std::to_string(k) + " of " + std::to_string(n_candidates) + " sites";
  layout.mode = LayoutMode::kPoints;
  layout.entries.resize(3, k);
  layout.weights = Eigen::VectorXd::Ones(k);
  MarkerVisibility visibility;
  visibility.normals.resize(3, k);
  visibility.cone_half_angle_deg.resize(k);
  visibility.min_visible = from.min_visible;
  visibility.body_path = from.body_path;
  visibility.body = from.body;
  LayoutPlacement placement;
  placement.sites = record.sites;
  placement.objective = !record.objective.empty() ? record.objective
                        : record.robust_dropout   ? kRobustObjective
                                                  : kObjective;
  for (Eigen::Index j = 0; j < k; ++j) {
    const int s = result.chosen[static_cast<std::size_t>(j)];
    layout.entries.col(j) = sites.entries.col(s);
    visibility.normals.col(j) = from.normals.col(s);
    visibility.cone_half_angle_deg(j) = from.cone_half_angle_deg(s);
    layout.names.push_back(site_name(sites, s));
    placement.chosen.push_back(s < n_candidates ? s : -1);
  }
  placement.site_points = sites.entries.leftCols(n_candidates);
  placement.site_normals = from.normals.leftCols(n_candidates);
  placement.min_separation = record.min_separation;
  placement.marker_diameter = record.marker_diameter;
  for (const PlacementStep& s : result.steps) {
    placement.steps.push_back({s.k, s.value.pbar_min, s.value.coverage});
  }
  placement.random_trials = result.random_baseline.trials;
  placement.random_best_pbar_min = result.random_baseline.best_pbar_min;
  placement.random_median_pbar_min = result.random_baseline.median_pbar_min;
  layout.visibility = std::move(visibility);
  layout.workspace = sites.workspace;
  layout.placement = std::move(placement);
  return layout;
}

}  // namespace vantage::design
