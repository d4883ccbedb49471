// vantage.analyze, vantage.design and vantage.weights: the library calls behind `vantage
// analyze`, `design` and `weights`, returning the fields of their --json output.

#include "layout_commands.h"

#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arrays.h"
#include "layouts.h"
#include "place_command.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/free_vectors.h"
#include "vantage/commands/design_json.h"
#include "vantage/commands/design_sensor.h"
#include "vantage/commands/limits.h"
#include "vantage/commands/sensor_json.h"
#include "vantage/design/augment.h"
#include "vantage/design/weights.h"
#include "vantage/report/layout_report.h"

namespace vantage::python {

namespace {

/// Runs a size check (vantage/commands/limits.h); its error names the file it read, if any, as
/// the error's source (ValueError.source), the bound as its field.
template <typename Check>
void check_size(const std::string& source, Check&& check) {
  try {
    check();
  } catch (const InvalidArgument& e) {
    throw source.empty() ? e : e.against(source);
  }
}

Json source_json(const std::string& source) {
  return source.empty() ? Json(nullptr) : Json(source);
}

/// (the report as the dict of `vantage analyze --json`, its brief_report()).
py::tuple analyze(const py::object& layout_arg, const py::object& vectors, const py::object& points,
                  const py::object& weights, int swaps, bool crosscheck,
                  const std::string& pair_weighting, bool dropout, bool allow_large,
                  const py::object& format, const py::object& tag_points,
                  const py::object& bundle) {
  if (swaps < 1) throw InvalidArgument("swaps", "must be >= 1");
  const std::optional<PairWeighting> weighting = parse_pair_weighting(pair_weighting);
  if (!weighting) throw InvalidArgument("pair_weighting", "expected geometric or arithmetic");
  std::string source;
  const Layout layout = layout_from_arguments(layout_arg, vectors, points, weights, py::none(),
                                              {format, tag_points, bundle, allow_large}, &source);
  check_size(source, [&] {
    commands::check_limit("data vectors", commands::data_vector_count(layout),
                          commands::kMaxAnalyzeVectors, "analyze", allow_large, kPythonWords);
    if (dropout) {
      commands::check_limit("data vectors with dropout=True", commands::data_vector_count(layout),
                            commands::kMaxDropoutVectors, "analyze", allow_large, kPythonWords);
    }
  });
  report::LayoutReportOptions options;
  options.dropout = dropout;
  options.pair_weighting = *weighting;
  options.analysis.swap_count = swaps;
  options.analysis.run_crosscheck = crosscheck;
  const report::LayoutReport report =
      without_gil([&] { return report::analyze_layout(layout, options); });
  const sdp::LayoutAnalysis& r = report.analysis;
  // Why the report is not usable, in the order LayoutReport::is_usable() asks.
  const bool certified = r.solver.status == sdp::WorstViewpoint::Status::kCertified;
  const auto& v = report.visibility;
  const std::string status =
      r.degenerate        ? "degenerate"
      : r.near_degenerate ? "near_degenerate"
      : !certified        ? sdp::to_string(r.solver.status)
      : !r.trusted()      ? "crosscheck_disagrees"
      : report.dropout && report.dropout->status != report::DropoutAnalysis::Status::kCertified
          ? "dropout_not_certified"
      : v && v->exact_viewpoint_disagrees() ? "exact_rays_disagree"
                                            : "visibility_not_certified";
  const std::string brief = report.brief_report();
  Json fields = Json::parse(report::to_json(report));
  if (layout.sensor) {
    fields["sensor"] =
        sensor_json::to_json(without_gil([&] { return sensor_json::evaluate(layout, 0); }));
  }
  return py::make_tuple(
      result_or_raise(!report.is_usable(), status, report.message(), fields, brief), brief);
}

/// design(objective='camera'|'tracker'): `vantage design --objective`'s run
/// (vantage/commands/design_sensor.h); the augmenter's own keywords are refused, not ignored.
py::object sensor_design(const Layout& layout, const std::string& source, int add, double margin,
                         bool direct, double min_distance_difference, place_json::Request request) {
  if (margin != design::AugmentOptions{}.margin || !direct) {
    throw InvalidArgument(margin != design::AugmentOptions{}.margin ? "margin" : "direct",
                          "is the augmenter's (objective='affine'); the " + request.objective +
                              " objective chooses among the candidates");
  }
  request.sites = source.empty() ? std::string("layout") : source;
  request.min_distance_difference = min_distance_difference;
  design_sensor::Sites sites;
  try {
    sites = design_sensor::sites_of(layout);
    design_sensor::check(request, sites, add, layout);
  } catch (const InvalidArgument& e) {
    if (e.field().rfind("--", 0) == 0) throw place_renamed(e);
    throw source.empty() ? e : e.against(source);
  }
  design_sensor::Outcome out;
  try {
    out = without_gil(
        [&] { return design_sensor::design_for_sensor(request, layout, sites, add, {}); });
  } catch (const InvalidArgument& e) {
    throw place_renamed(e);  // the search's refusals name the distance or the gap
  }
  const Json report = design_sensor::report(source_json(source), request, sites, out);
  if (!out.complete) {
    const bool covered = out.result.status == design::PlacementResult::Status::kComplete;
    NumericalFailure failure(covered
                                 ? (request.objective == "camera" ? "untrackable" : "not_certified")
                                 : design::to_string(out.result.status),
                             design_sensor::failure_message(out), report);
    failure.objects.emplace_back("augmented",
                                 std::make_shared<py::object>(py::cast(out.augmented)));
    throw failure;
  }
  py::object result = to_python(report);
  result["augmented"] = py::cast(out.augmented);
  return result;
}

py::object design_layout(const py::object& layout_arg, const py::object& vectors,
                         const py::object& points, const py::object& weights,
                         const py::object& candidates, int add, bool candidates_only, double margin,
                         bool direct, double min_distance_difference, bool allow_large,
                         const py::object& format, const py::object& tag_points,
                         const py::object& bundle, const std::string& objective,
                         const std::optional<double>& distance,
                         const std::optional<std::vector<double>>& distances,
                         const std::optional<double>& focal, const std::optional<double>& noise_px,
                         const std::string& statistic, const std::optional<int>& crb_samples,
                         const py::object& aim, const py::object& targets,
                         const std::optional<double>& fle_rms, const py::object& fle_sigma) {
  place_json::Request request;
  try {
    request = objective_request(objective, distance, distances, focal, noise_px, statistic,
                                crb_samples, aim, targets, fle_rms, fle_sigma);
    if (objective != "camera" && objective != "tracker") {
      // The camera's and the tracker's settings go with their objective (place's rule).
      place_json::Request affine = request;
      affine.sites = "layout";
      affine.markers = 1;
      place_json::check_request(affine);
    }
  } catch (const InvalidArgument& e) {
    throw place_renamed(e);
  }
  std::string source;
  const Layout layout = layout_from_arguments(layout_arg, vectors, points, weights, candidates,
                                              {format, tag_points, bundle, allow_large}, &source);
  if (add < 1) throw InvalidArgument("add", "must be >= 1, got " + std::to_string(add));
  if (objective == "camera" || objective == "tracker") {
    return sensor_design(layout, source, add, margin, direct, min_distance_difference, request);
  }
  check_size(source, [&] {
    const long final_count = layout.mode == LayoutMode::kPoints
                                 ? static_cast<long>(free_vector_count(layout.entries.cols() + add))
                                 : static_cast<long>(layout.entries.cols()) + add;
    commands::check_time_limit(
        "add=" + std::to_string(add) + " on " + std::to_string(final_count) + " data vectors",
        commands::estimated_design_seconds(layout, add, candidates_only,
                                           design::AugmentOptions{}.search_budget),
        commands::kMaxDesignSeconds, "design", allow_large, kPythonWords);
  });
  design::AugmentOptions options;
  options.add = add;
  options.candidates_only = candidates_only;
  options.margin = margin;
  options.run_direct = direct;
  options.min_distance_difference = min_distance_difference;
  try {
    design::check_augmentation(layout, options);
  } catch (const InvalidArgument& e) {
    // The library's "options.<field>" is this function's keyword <field>.
    const std::string prefix = "options.";
    if (e.field().rfind(prefix, 0) == 0) {
      throw e.renamed(e.field().substr(prefix.size()), std::nullopt);
    }
    throw source.empty() ? e : e.against(source);
  }
  if (const std::optional<std::string> warning = design_json::unused_visibility_warning(layout)) {
    if (PyErr_WarnEx(PyExc_RuntimeWarning, warning->c_str(), 1) < 0) throw py::error_already_set();
  }
  const design::AugmentResult r = without_gil([&] {
    try {
      return design::augment_layout(layout, options);
    } catch (const InvalidArgument& e) {
      throw source.empty() ? e : e.against(source);
    }
  });
  const bool ok = r.status == design::AugmentResult::Status::kOk;
  py::object result = result_or_raise(!ok, design::to_string(r.status), r.message,
                                      design_json::design(source_json(source), layout, direct, r));
  result["augmented"] = py::cast(design_json::layout_to_write(r));
  return result;
}

py::object layout_weights(const py::object& layout_arg, const py::object& vectors,
                          const py::object& points, bool allow_large, const py::object& format,
                          const py::object& tag_points, const py::object& bundle) {
  std::string source;
  const Layout layout = layout_from_arguments(layout_arg, vectors, points, py::none(), py::none(),
                                              {format, tag_points, bundle, allow_large}, &source);
  check_size(source, [&] {
    commands::check_limit(layout.entries_field(), layout.entries.cols(),
                          commands::kMaxWeightsEntries, "weights", allow_large, kPythonWords);
  });
  const design::Weights w = without_gil([&] { return design::layout_weights(layout); });
  const Json out = design_json::weights(source_json(source), layout, w);
  return result_or_raise(w.status == design::Weights::Status::kSolverFailed,
                         design::to_string(w.status), w.message, out);
}

}  // namespace

void bind_layout_commands(py::module_& module) {
  module.def("analyze", &analyze, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             py::arg("weights") = py::none(), py::arg("swaps") = 5, py::arg("crosscheck") = true,
             py::arg("pair_weighting") = "geometric", py::arg("dropout") = false,
             py::arg("allow_large") = false, py::arg("format") = py::none(),
             py::arg("tag_points") = py::none(), py::arg("bundle") = py::none(),
             "Worst viewpoint of a layout (as `vantage analyze --json`): a vantage.Layout, a "
             "layout file (format=, tag_points=, bundle=) or vectors=/points= (n x 3) with "
             "weights=. Raises NumericalError when the result is not certified.");
  module.def("design", &design_layout, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             py::arg("weights") = py::none(), py::arg("candidates") = py::none(),
             py::arg("add") = 1, py::arg("candidates_only") = false,
             py::arg("margin") = design::AugmentOptions{}.margin, py::arg("direct") = true,
             py::arg("min_distance_difference") = design::AugmentOptions{}.min_distance_difference,
             py::arg("allow_large") = false, py::arg("format") = py::none(),
             py::arg("tag_points") = py::none(), py::arg("bundle") = py::none(),
             py::arg("objective") = "affine", py::arg("distance") = py::none(),
             py::arg("distances") = py::none(), py::arg("focal") = py::none(),
             py::arg("noise_px") = py::none(), py::arg("statistic") = "worst",
             py::arg("crb_samples") = py::none(), py::arg("aim") = py::none(),
             py::arg("targets") = py::none(), py::arg("fle_rms") = py::none(),
             py::arg("fle_sigma") = py::none(),
             "Add `add` markers or directions where the worst viewpoint is weakest (as `vantage "
             "design --json`), or, with objective 'camera' or 'tracker', the `add` candidates "
             "that make its value best; the result's `augmented` is the new vantage.Layout.");
  module.def("weights", &layout_weights, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             py::arg("allow_large") = false, py::arg("format") = py::none(),
             py::arg("tag_points") = py::none(), py::arg("bundle") = py::none(),
             "Non-negative weights with sum_i w_i z_i = 0 (Prop. 3, Eq. 11), as `vantage weights "
             "--json`.");
}

}  // namespace vantage::python
