// `vantage design --objective camera|tracker`: place's search on the layout's markers (kept) and
// its candidates, seen whole, and the augmented layout with its sensor block (docs/math.md §21,
// "In design").

#include "vantage/commands/design_sensor.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "place_internal.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/design/augment.h"
#include "vantage/report/json_number.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::design_sensor {
namespace {

// A search value as a figure: null when +inf (incomplete, nothing tracked) or, for a camera,
// past the first-order limit (docs/math.md §22, "Unbounded").
Json search_number(double value, bool camera) {
  if (camera && value > camera::PoseCrbAt::kMaxRotRmsDeg) return Json();
  return report::json_number(value);
}

// The sensor the search optimises, as the augmented layout records it (the tracker's FLE as the
// request gives it, so that an RMS is kept to the bit, as `vantage place` records it).
LayoutSensor sensor_of(const place_json::Request& request,
                       const std::optional<design::CameraObjective>& camera,
                       const std::optional<design::TrackerObjective>& tracker) {
  if (camera) return sensor_json::camera_sensor(*camera);
  design::TrackerObjective given = *tracker;
  given.fle = *request.fle;
  return sensor_json::tracker_sensor(given);
}

// The input layout with the chosen candidates appended as markers and dropped from the
// candidates.
Layout augmented_layout(const Layout& layout, const std::vector<int>& added) {
  Layout out = layout;
  std::vector<bool> used(static_cast<std::size_t>(layout.candidates.cols()), false);
  for (const int c : added) {
    append_entry(&out, layout.candidates.col(c), "added");
    used[static_cast<std::size_t>(c)] = true;
  }
  Eigen::Matrix3Xd rest(3, layout.candidates.cols() - static_cast<Eigen::Index>(added.size()));
  Eigen::Index k = 0;
  for (Eigen::Index c = 0; c < layout.candidates.cols(); ++c) {
    if (!used[static_cast<std::size_t>(c)]) rest.col(k++) = layout.candidates.col(c);
  }
  out.candidates = rest;
  return out;
}

}  // namespace

Sites sites_of(const Layout& layout) {
  if (layout.mode != LayoutMode::kPoints) {
    throw InvalidArgument("vectors",
                          "the camera and tracker objectives add markers: give a layout of points");
  }
  if (layout.candidates.cols() == 0) {
    throw InvalidArgument("candidates",
                          "none to choose from: the camera and tracker objectives add the layout's "
                          "candidates (`vantage place` samples a body's surface)");
  }
  if (layout.visibility) {
    throw InvalidArgument("visibility",
                          "the camera and tracker objectives see the layout whole (its candidates "
                          "have no normals to share the model): drop the model (--seen-whole), or "
                          "place on sites with normals (`vantage place --sites`)");
  }
  Sites out;
  out.markers = static_cast<int>(layout.entries.cols());
  const Eigen::Index n = layout.entries.cols() + layout.candidates.cols();
  out.layout.mode = LayoutMode::kPoints;
  out.layout.entries.resize(3, n);
  out.layout.entries << layout.entries, layout.candidates;
  out.layout.weights = Eigen::VectorXd::Ones(n);
  out.layout.workspace = layout.workspace;
  for (int i = 0; i < out.markers; ++i) out.keep.push_back(i);
  return out;
}

void check(const place_json::Request& request, const Sites& sites, int add, const Layout& layout) {
  const long candidates = static_cast<long>(sites.layout.entries.cols()) - sites.markers;
  if (add < 1) throw InvalidArgument("--add", "must be >= 1, got " + std::to_string(add));
  if (sites.markers + add < 3) {
    throw InvalidArgument("--add", "the layout's " + std::to_string(sites.markers) +
                                       " markers and " + std::to_string(add) +
                                       " added are fewer than the 3 a pose needs");
  }
  if (add > candidates) {
    throw InvalidArgument("--add", std::to_string(add) + " exceeds the " +
                                       std::to_string(candidates) +
                                       " candidates (each is added at most once)");
  }
  place_json::Request r = request;
  r.markers = sites.markers + add;
  try {
    place_json::check_request(r);
    if (r.objective == "tracker") {
      place_json::internal::check_tracker_range(r, sites.layout.entries);
    }
  } catch (const InvalidArgument& e) {
    if (e.field() == "--markers") {
      throw InvalidArgument("--add", e.problem() + " (the layout's " +
                                         std::to_string(sites.markers) + " markers and --add " +
                                         std::to_string(add) + ")");
    }
    if (e.field() == "--sites") throw e.renamed("points", std::nullopt);
    throw;
  }
  // Coincident candidates and a distance difference the markers break, as the augmenter says
  // them (design::check_augmentation; its options are in range once check_request passed).
  design::AugmentOptions augment;
  augment.add = add;
  augment.candidates_only = true;
  augment.run_direct = false;
  augment.min_distance_difference = request.min_distance_difference;
  try {
    design::check_augmentation(layout, augment);
  } catch (const InvalidArgument& e) {
    if (e.field() == "min_distance_difference") {
      throw e.renamed("--min-distance-difference", std::nullopt);
    }
    throw;
  }
}

Outcome design_for_sensor(const place_json::Request& request, const Layout& layout,
                          const Sites& sites, int add,
                          const std::function<void(const std::string&)>& progress) {
  design::PlacementProblem problem;
  problem.sites = tracker::tre_visibility_problem(sites.layout);
  problem.keep = sites.keep;
  problem.markers = sites.markers + add;
  problem.min_distance_difference = request.min_distance_difference;
  const design::PlaceOptions options = place_json::place_options(request, sites.layout, progress);
  Outcome out;
  try {
    out.result = design::place_markers(problem, options);
  } catch (const InvalidArgument& e) {
    // The search's own refusals, named by the flags that cause them: a camera distance inside
    // the sites, and no K candidates that keep the distance difference (or apart).
    if (e.field() == "distance") {
      throw e.renamed(request.distances.empty() ? "--distance" : "--distances", std::nullopt);
    }
    if (e.field() == "min_separation") throw e.renamed("--min-distance-difference", std::nullopt);
    throw;
  }
  for (const int s : out.result.chosen) {
    if (s >= sites.markers) out.added.push_back(s - sites.markers);
  }
  const LayoutSensor sensor = sensor_of(request, options.camera, options.tracker);
  out.augmented = augmented_layout(layout, out.added);
  out.augmented.sensor = sensor;
  if (progress) progress("final evaluation");
  if (layout.entries.cols() >= 3) {
    Layout initial = layout;
    initial.sensor = sensor;
    out.initial = sensor_json::evaluate(initial, request.threads);
  }
  out.final = sensor_json::evaluate(out.augmented, request.threads);
  out.complete =
      out.result.status == design::PlacementResult::Status::kComplete && out.final.complete;
  return out;
}

std::string failure_message(const Outcome& outcome) {
  const design::PlacementResult& r = outcome.result;
  if (r.status == design::PlacementResult::Status::kIncomplete) {
    std::ostringstream percent;
    percent.precision(4);
    percent << 100.0 * r.value.coverage;
    return r.message + ": the best covers " + percent.str() + " % of the workspace";
  }
  if (outcome.final.crb) {
    return "the augmented layout is not trackable by the camera: " +
           camera::untrackable_reason(*outcome.final.crb, outcome.final.camera->distance);
  }
  return sensor_json::tre_objective(*outcome.final.tre) == std::numeric_limits<double>::infinity()
             ? "the augmented layout tracks a target from no direction of the workspace"
             : "the augmented layout's worst TRE is not certified at every target";
}

Json report(const Json& source, const place_json::Request& request, const Sites& sites,
            const Outcome& outcome) {
  const design::PlacementResult& r = outcome.result;
  const bool camera = request.objective == "camera";
  Json out;
  out["layout"] = source;
  out["objective"] = request.objective;
  out["status"] = design::to_string(r.status);
  out["complete"] = outcome.complete;
  out["markers"] = sites.markers;
  out["candidates"] = static_cast<long>(sites.layout.entries.cols()) - sites.markers;
  out["add"] = static_cast<int>(outcome.added.size());
  out["added"] = outcome.added;
  out["search"] = r.search;
  // The value the search ranked by (the camera's: its statistic over the lattice samples; for
  // `worst`, before the refinement that `vantage crb` and the final value below add).
  out[camera ? "search_value_deg" : "search_value"] = search_number(r.value.objective, camera);
  out["evaluations"] = r.evaluations;
  if (r.search == "exhaustive") {
    out["subsets"] = r.subsets;
  } else {
    out["swaps"] = r.swaps;
  }
  Json steps = Json::array();
  for (const design::PlacementStep& s : r.steps) {
    steps.push_back(
        {{"k", s.k},
         {"candidate", s.added >= sites.markers ? Json(s.added - sites.markers) : Json()},
         {"coverage", s.value.coverage},
         {camera ? "value_deg" : "value", search_number(s.value.objective, camera)}});
  }
  out["steps"] = steps;
  const design::RandomBaseline& b = r.random_baseline;
  out["random_baseline"] = {{"trials", b.trials},
                            {"complete", b.complete},
                            {"best", search_number(b.best_objective, camera)},
                            {"median", search_number(b.median_objective, camera)}};
  out["initial"] = outcome.initial ? sensor_json::to_json(*outcome.initial) : Json();
  out["sensor"] = sensor_json::to_json(outcome.final);
  out["written"] = Json();  // the CLI's --write file, when it wrote one
  return out;
}

}  // namespace vantage::design_sensor
