#include "vantage/viewer/body_placement.h"

#include <chrono>
#include <exception>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/design/placement_layout.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::viewer {
namespace {

design::PlacementProblem placement_problem(const visibility::VisibilityModel& model,
                                           const PlaceSettings& settings) {
  design::PlacementProblem problem;
  problem.sites = model.problem();
  problem.markers = settings.markers;
  problem.min_separation = settings.min_separation;
  return problem;
}

design::PlaceOptions place_options(const PlaceSettings& settings) {
  design::PlaceOptions options;
  options.robust_dropout = settings.robust_dropout;
  options.random_trials = settings.random_trials;
  options.seed = settings.seed;
  options.threads = settings.threads;
  return options;
}

}  // namespace

bool is_on_body(const Layout& layout) {
  return layout.mode == LayoutMode::kPoints && layout.visibility && layout.visibility->body;
}

Layout body_sites(const Layout& layout, const PlaceSettings& settings) {
  if (!is_on_body(layout)) {
    throw InvalidArgument("body", "the layout has no body mesh to place markers on");
  }
  const MarkerVisibility& v = *layout.visibility;
  const design::SurfaceSites sampled = design::sample_surface_sites(
      *v.body, settings.candidates, settings.min_separation, settings.seed);
  const double cone = v.cone_half_angle_deg.size() > 0 ? v.cone_half_angle_deg(0)
                                                       : MarkerVisibility::kDefaultConeDeg;
  Layout sites = design::surface_sites_layout(sampled, *v.body, v.body_path, cone);
  sites.name = layout.name;
  sites.visibility->min_visible = v.min_visible;
  sites.workspace = layout.workspace;
  return sites;
}

PlaceOutcome place_on_body(const Layout& layout, std::uint64_t revision,
                           const PlaceSettings& settings,
                           const std::function<void(const std::string&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  PlaceOutcome outcome;
  outcome.revision = revision;
  outcome.settings = settings;
  try {
    if (progress) progress("sampling sites");
    const Layout sites = body_sites(layout, settings);
    outcome.n_candidates = static_cast<int>(sites.entries.cols());
    if (progress) progress("occlusion grid");
    const visibility::VisibilityModel model = visibility::VisibilityModel::of(
        sites, visibility::VisibilityModel::kDefaultResolutionDeg, settings.threads);
    const design::PlacementProblem problem = placement_problem(model, settings);
    design::PlaceOptions options = place_options(settings);
    options.progress = progress;
    outcome.result = design::place_markers(problem, options);
    if (outcome.result.status == design::PlacementResult::Status::kComplete) {
      design::PlacedLayoutRecord record;
      record.sites = layout.visibility->body_path;
      record.n_candidates = outcome.n_candidates;
      record.robust_dropout = settings.robust_dropout;
      outcome.placed = design::placed_layout(sites, outcome.result, record);
    }
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace vantage::viewer
