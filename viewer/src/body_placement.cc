#include "vantage/viewer/body_placement.h"

#include <chrono>
#include <exception>
#include <utility>

#include "vantage/analysis/common.h"
#include "vantage/commands/place_json.h"

namespace vantage::viewer {
namespace {

// `vantage place BODY`'s request for the settings (nothing written: no --out).
place_json::Request place_request(const Layout& layout, const PlaceSettings& settings) {
  place_json::Request request;
  const std::string& path = layout.visibility->body_path;
  request.body = path.empty() ? std::string("the layout's body") : path;
  request.candidates = settings.candidates;
  request.markers = settings.markers;
  request.min_separation = settings.min_separation;
  request.marker_diameter = settings.marker_diameter;
  request.robust_dropout = settings.robust_dropout;
  request.seed = settings.seed;
  request.threads = settings.threads;
  request.random_trials = settings.random_trials;
  request.min_coverage = settings.min_coverage;
  request.objective = settings.objective;
  if (settings.objective == "camera") {
    if (settings.distances.empty()) request.distance = settings.distance;
    request.distances = settings.distances;
    request.focal = settings.focal;
    request.noise_px = settings.noise_px;
    request.statistic = settings.statistic;
  }
  if (settings.objective == "tracker") {
    request.targets = {settings.target};
    if (settings.fle_rms > 0.0) request.fle = tracker::FleModel::isotropic(settings.fle_rms);
  }
  request.exclude = settings.exclude;
  request.region = settings.region;
  return request;
}

// `vantage place BODY`'s sites on the body the viewer shows, with the layout's cone (its first
// marker's), min_visible and workspace (or the settings').
place_json::Sites viewer_sites(const Layout& layout, const place_json::Request& request,
                               const PlaceSettings& settings) {
  if (!is_on_body(layout)) {
    throw InvalidArgument("body", "the layout has no body mesh to place markers on");
  }
  const MarkerVisibility& v = *layout.visibility;
  const double cone = v.cone_half_angle_deg.size() > 0 ? v.cone_half_angle_deg(0)
                                                       : MarkerVisibility::kDefaultConeDeg;
  return place_json::sites_on_body(request, *v.body, v.body_path, [&](Layout* sites) {
    sites->name = layout.name;
    sites->visibility->cone_half_angle_deg.setConstant(cone);
    sites->visibility->min_visible = v.min_visible;
    sites->workspace = settings.workspace ? settings.workspace : layout.workspace;
  });
}

}  // namespace

bool is_on_body(const Layout& layout) {
  return layout.mode == LayoutMode::kPoints && layout.visibility && layout.visibility->body;
}

Layout body_sites(const Layout& layout, const PlaceSettings& settings) {
  return viewer_sites(layout, place_request(layout, settings), settings).layout;
}

PlaceOutcome place_on_body(const Layout& layout, std::uint64_t revision,
                           const PlaceSettings& settings,
                           const std::function<void(const std::string&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  PlaceOutcome outcome;
  outcome.revision = revision;
  outcome.settings = settings;
  try {
    if (!is_on_body(layout)) {
      throw InvalidArgument("body", "the layout has no body mesh to place markers on");
    }
    const place_json::Request request = place_request(layout, settings);
    place_json::check_request(request);
    if (progress) progress("sampling sites");
    const place_json::Sites sites = viewer_sites(layout, request, settings);
    outcome.n_candidates = sites.n_candidates;
    outcome.excluded = sites.excluded;
    const place_json::Outcome placed = place_json::place(request, sites, progress);
    outcome.result = placed.result;
    outcome.complete = placed.complete;
    outcome.objective_value = placed.objective_value;
    if (placed.complete) {
      outcome.placed = placed.placed.layout;
    } else {
      outcome.failure = place_json::failure_message(placed.result, placed.placed);
    }
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace vantage::viewer
