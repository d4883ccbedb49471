// `vantage place`'s run on the candidate sites: the placement, the placed layout and its analysis,
// why an incomplete one is not written, and the JSON object of `vantage place --json`.

#include "vantage/commands/place_json.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "place_internal.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/against_source.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/report/json_number.h"
#include "vantage/visibility/visibility_model.h"

namespace vantage::place_json {

using internal::check_tracker_range;
using internal::place_refuse;

namespace {

std::string place_percent(double fraction) {
  std::ostringstream out;
  out.precision(4);
  const double x = 100.0 * fraction;
  out << (x == 0.0 ? 0.0 : x);  // never "-0", as the CLI's format_number
  return out.str() + " %";
}

// Site s as the JSON names it: its index among the candidates, or -1 for a kept marker.
int place_candidate_index(int s, int n_candidates) { return s < n_candidates ? s : -1; }

Json place_steps_json(const design::PlacementResult& r) {
  Json steps = Json::array();
  for (const design::PlacementStep& s : r.steps) {
    steps.push_back({{"k", s.k},
                     {"added", s.added},
                     {"coverage", s.value.coverage},
                     {"pbar_min", s.value.pbar_min}});
  }
  return steps;
}

// A camera objective's search value: null past the first-order limit (§22, "Unbounded"), as
// when nothing is trackable; the search ranks by it, but it is not a figure.
Json camera_search_number(double value_deg) {
  return value_deg > camera::PoseCrbAt::kMaxRotRmsDeg ? Json() : report::json_number(value_deg);
}

// A camera or tracker search value as the layout file records it: +inf (null) when the choice
// is incomplete (the search's +inf) or covers nothing, or, for a camera, past the first-order
// limit (no figure, §22 "Unbounded").
double recorded_objective(double value, double coverage, LayoutSensor::Kind kind) {
  const bool unbounded =
      kind == LayoutSensor::Kind::kCamera && value > camera::PoseCrbAt::kMaxRotRmsDeg;
  return coverage > 0.0 && !unbounded ? value : std::numeric_limits<double>::infinity();
}

// The objective's steps, random baseline and value in the placement record (the figure's chart).
void record_objective(const design::PlacementResult& result,
                      const sensor_json::Evaluation& evaluation, LayoutPlacement* placement) {
  const LayoutSensor::Kind kind = evaluation.sensor.kind;
  for (std::size_t i = 0; i < placement->steps.size(); ++i) {
    const design::PlacementValue& v = result.steps[i].value;
    placement->steps[i].objective = recorded_objective(v.objective, v.coverage, kind);
  }
  const design::RandomBaseline& b = result.random_baseline;
  if (b.trials > 0) {
    // The median's incomplete trials are +inf already: no coverage of its own to test.
    placement->random_best_objective = recorded_objective(b.best_objective, b.best_coverage, kind);
    placement->random_median_objective = recorded_objective(b.median_objective, 1.0, kind);
  }
  placement->objective_value = evaluation.value;
}

Json place_vector(const Eigen::Vector3d& v) { return Json{v.x(), v.y(), v.z()}; }

// The tracker objective's block: `vantage tre`'s worst of each target on the placed layout.
void place_tracker_json(const Outcome& outcome, Json* out) {
  const tracker::TreReport& tre = *outcome.placed.tre;
  (*out)["search_value"] = report::json_number(outcome.result.value.objective);
  Json fle = {{"sigma_perp", tre.fle.sigma_perp}, {"sigma_axial", tre.fle.sigma_axial}};
  if (tre.fle.from_rms) fle["rms"] = tre.fle.rms();
  (*out)["fle"] = fle;
  Json targets = Json::array();
  for (const tracker::TreTargetReport& t : tre.targets) {
    const tracker::TreExtreme& w = t.extremes.worst;
    targets.push_back({{"target", place_vector(t.target)},
                       {"status", tracker::to_string(w.status)},
                       {"rms", w.rms},
                       {"rms_bound", w.rms_bound},
                       {"direction", place_vector(w.direction)}});
  }
  (*out)["targets"] = targets;
}

Json place_objective_json(const Request& request, const Outcome& outcome) {
  const design::PlacementResult& r = outcome.result;
  Json out;
  out["name"] = request.objective;
  if (outcome.placed.tre) {
    // A length in the layout's unit, not degrees.
    out["value"] = report::json_number(outcome.objective_value);
  } else {
    out["value_deg"] = report::json_number(outcome.objective_value);
  }
  out["min_coverage"] = request.min_coverage == -1.0 ? Json("all lattice directions but one")
                                                     : Json(request.min_coverage);
  if (outcome.placed.tre) {
    place_tracker_json(outcome, &out);
    return out;
  }
  if (!outcome.placed.crb) {
    out["scale_free"] = true;
    return out;
  }
  const camera::PoseCrbOptions& c = *outcome.placed.camera;
  const camera::PoseCrbMap& map = *outcome.placed.crb;
  out["statistic"] = request.statistic;
  out["search_value_deg"] = camera_search_number(r.value.objective);
  const std::vector<sensor_json::ApproachStep>& approach = outcome.placed.sensor->approach;
  if (approach.empty()) {
    out["camera"] = {{"distance", c.distance}};
  } else {
    out["camera"] = {{"distances", outcome.placed.layout.sensor->distances}};
  }
  out["camera"]["focal_px"] = c.focal_length;
  out["camera"]["noise_px"] = c.noise_px;
  out["camera"]["samples"] = c.samples;
  out["camera"]["aim"] = {c.aim->x(), c.aim->y(), c.aim->z()};
  if (!approach.empty()) {
    out["approach"] = sensor_json::approach_json(approach);
    out["deciding_distance"] = c.distance;
  }
  out["crb"] = sensor_json::crb_json(map, c.distance);
  return out;
}

}  // namespace

design::PlaceOptions place_options(const Request& request, const Layout& sites,
                                   const std::function<void(const std::string&)>& progress) {
  design::PlaceOptions options;
  options.robust_dropout = request.robust_dropout;
  options.random_trials = request.random_trials;
  options.perturbations = request.perturbations;
  options.exhaustive_limit = request.exhaustive_limit;
  options.seed = request.seed;
  options.threads = request.threads;
  options.search.certificate_tolerance = request.certificate_tolerance;
  options.progress = progress;
  if (request.min_coverage != -1.0) options.min_coverage = request.min_coverage;
  options.camera = camera_objective(request, sites);
  options.tracker = tracker_objective(request);
  return options;
}

Outcome place(const Request& request, const Sites& sites,
              const std::function<void(const std::string&)>& progress) {
  if (progress) progress("occlusion grid");
  const visibility::VisibilityModel model = commands::against_source(request.source(), [&] {
    return visibility::VisibilityModel::of(
        sites.layout, visibility::VisibilityModel::kDefaultResolutionDeg, request.threads);
  });
  design::PlacementProblem problem;
  problem.sites = model.problem();
  problem.keep = sites.keep;
  problem.markers = request.markers;
  problem.min_separation = request.separation();
  problem.min_distance_difference = request.min_distance_difference;
  const design::PlaceOptions options = place_options(request, sites.layout, progress);
  Outcome out;
  try {
    if (options.tracker) check_tracker_range(request, problem.sites.points);
    out.result = design::place_markers(problem, options);
  } catch (const InvalidArgument& e) {
    if (e.field() == "distance") {
      place_refuse(request.distances.empty() ? "--distance" : "--distances", e.what());
    }
    place_refuse(e.field() == "min_separation" ? "--min-separation" : "--markers", e.what());
  }
  if (progress) progress("final analysis");
  out.placed = placed_layout(request, sites.layout, sites.n_candidates, out.result, options.camera,
                             options.tracker);
  const bool covered = out.result.status == design::PlacementResult::Status::kComplete;
  if (out.placed.sensor) {
    out.objective_value = out.placed.sensor->value;
    out.complete = covered && out.placed.sensor->complete;
  } else {
    out.objective_value = out.placed.report.visibility
                              ? out.placed.report.visibility->max_worst_case_error_deg
                              : 90.0;
    out.complete = covered && out.placed.report.visibility &&
                   out.placed.report.visibility->worst.certified() &&
                   !out.placed.report.visibility->exact_viewpoint_disagrees();
  }
  return out;
}

PlacedLayout placed_layout(const Request& request, const Layout& sites, int n_candidates,
                           const design::PlacementResult& result,
                           const std::optional<design::CameraObjective>& camera,
                           const std::optional<design::TrackerObjective>& tracker) {
  PlacedLayout out;
  for (Eigen::Index i = 0; i < sites.entries.cols(); ++i) {
    out.site_names.push_back(design::site_name(sites, static_cast<int>(i)));
  }
  std::optional<LayoutSensor> sensor;
  if (camera) sensor = sensor_json::camera_sensor(*camera);
  if (tracker) {
    // From the request's FLE, as tracker_objective() made the search's: the same RMS, not the
    // RMS of the search's isotropic model (which may differ in the last bit).
    design::TrackerObjective given = *tracker;
    given.fle = *request.fle;
    sensor = sensor_json::tracker_sensor(given);
  }
  design::PlacedLayoutRecord record;
  record.sites = request.source();
  record.n_candidates = n_candidates;
  record.robust_dropout = request.robust_dropout;
  record.min_separation = request.separation();
  record.marker_diameter = request.marker_diameter;
  if (sensor) record.objective = sensor_json::words(*sensor);
  out.layout = design::placed_layout(sites, result, record);
  out.layout.sensor = sensor;
  report::LayoutReportOptions options;
  options.visibility.search.certificate_tolerance = request.certificate_tolerance;
  options.visibility.threads = request.threads;
  out.report = report::analyze_layout(out.layout, options);
  if (sensor) {
    // As `vantage analyze` evaluates the written file's sensor block.
    sensor_json::Evaluation evaluation = sensor_json::evaluate(out.layout, request.threads);
    out.camera = evaluation.camera;
    out.crb = evaluation.crb;
    out.tre = evaluation.tre;
    record_objective(result, evaluation, &*out.layout.placement);
    out.sensor = std::move(evaluation);
  }
  return out;
}

std::string failure_message(const design::PlacementResult& result, const PlacedLayout& placed) {
  if (result.status == design::PlacementResult::Status::kIncomplete) {
    std::string message = result.message + ": the best covers " +
                          place_percent(result.value.coverage) + " of the workspace";
    if (result.covering_markers) {
      message += "; greedy by coverage covers it with " + std::to_string(*result.covering_markers) +
                 " markers";
    } else {
      message += "; all sites together cover " + place_percent(result.all_sites_coverage);
    }
    return message;
  }
  if (placed.tre) {
    return sensor_json::tre_objective(*placed.tre) == std::numeric_limits<double>::infinity()
               ? "the placed layout tracks a target from no direction of the workspace"
               : "the placed layout's worst TRE is not certified at every target";
  }
  if (placed.crb) {
    return "the placed layout is not trackable by the camera: " +
           camera::untrackable_reason(*placed.crb, placed.camera->distance);
  }
  const visibility::VisibilityReport& v = *placed.report.visibility;
  return "the placed layout's analysis is not certified: " + v.message();
}

Json report(const Request& request, const Sites& sites, const Outcome& outcome, bool written) {
  const design::PlacementResult& r = outcome.result;
  const PlacedLayout& placed = outcome.placed;
  const int n_candidates = sites.n_candidates;
  Json out;
  out["sites"] = request.source();
  out["status"] = design::to_string(r.status);
  Json chosen = Json::array();
  Json kept = Json::array();
  for (int s : r.chosen) {
    if (s < n_candidates) {
      chosen.push_back(s);
    } else {
      kept.push_back(placed.site_names[static_cast<std::size_t>(s)]);
    }
  }
  out["chosen"] = chosen;
  out["kept"] = kept;
  out["n_candidates"] = n_candidates;
  if (request.sites.empty()) {
    out["drawn"] = sites.drawn;
    out["excluded"] = sites.excluded;
  }
  out["markers"] = request.markers;
  out["min_separation"] = request.separation();
  out["marker_diameter"] = request.marker_diameter;
  out["search"] = r.search;
  const Json analysis = Json::parse(report::to_json(placed.report));
  out["visibility"] = analysis.contains("visibility") ? analysis["visibility"] : Json();
  out["coverage"] = placed.report.visibility->coverage.trackable_fraction;
  out["pbar_min"] = placed.report.visibility->worst.pbar_min;
  out["random_baseline"] = {{"trials", r.random_baseline.trials},
                            {"complete", r.random_baseline.complete},
                            {"best_coverage", r.random_baseline.best_coverage},
                            {"best_pbar_min", r.random_baseline.best_pbar_min},
                            {"median_pbar_min", r.random_baseline.median_pbar_min}};
  if ((outcome.placed.crb || outcome.placed.tre) && r.random_baseline.trials > 0) {
    // The objective's own values (null: no complete choice, or, for a camera, past the 45 deg
    // limit); the p-bar_min fields are the affine objective's, 0 here.
    const auto value = [&](double v) {
      return outcome.placed.crb ? camera_search_number(v) : report::json_number(v);
    };
    out["random_baseline"]["best_objective"] = value(r.random_baseline.best_objective);
    out["random_baseline"]["median_objective"] = value(r.random_baseline.median_objective);
  }
  out["objective"] = place_objective_json(request, outcome);
  out["steps"] = place_steps_json(r);
  if (r.robust) {
    out["robust"] = {
        {"pbar_min", r.robust->pbar_min},
        {"worst_lost_marker", place_candidate_index(r.robust->worst_lost_marker, n_candidates)},
        {"worst_lost_name",
         placed.site_names[static_cast<std::size_t>(r.robust->worst_lost_marker)]},
        {"coverage", r.robust->coverage}};
    if (outcome.placed.crb || outcome.placed.tre) {
      out["robust"]["objective"] = outcome.placed.crb ? camera_search_number(r.robust->objective)
                                                      : report::json_number(r.robust->objective);
    }
  }
  out["swaps"] = r.swaps;
  if (r.search != "exhaustive") {
    out["perturbations"] = request.perturbations;
    out["improving_perturbations"] = r.improving_perturbations;
  }
  out["evaluations"] = r.evaluations;
  if (r.search == "exhaustive") out["subsets"] = r.subsets;
  if (r.status == design::PlacementResult::Status::kIncomplete) {
    out["covering_markers"] = r.covering_markers ? Json(*r.covering_markers) : Json();
    out["all_sites_coverage"] = r.all_sites_coverage;
  }
  out["written"] = written ? Json(request.out) : Json();
  return out;
}

}  // namespace vantage::place_json
