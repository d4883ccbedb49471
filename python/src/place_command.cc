// vantage.place (place_command.h).

#include "place_command.h"

#include <pybind11/stl.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "arrays.h"
#include "layouts.h"
#include "results.h"
#include "tre_command.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/place_json.h"
#include "vantage/commands/visibility_options.h"
#include "vantage/io/layout_file.h"
#include "vantage/io/layout_formats.h"
#include "vantage/io/text_file.h"

namespace vantage::python {

namespace {

// A file path argument (str or os.PathLike), or "" for None.
std::string place_path(const py::object& value, const char* field) {
  return value.is_none() ? "" : path_from(value, field);
}

// exclude=: one path or a sequence of paths (--exclude, repeatable); None for none.
std::vector<std::string> place_paths(const py::object& value, const char* field) {
  if (value.is_none()) return {};
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
    return {place_path(value, field)};
  }
  if (!py::isinstance<py::sequence>(value)) {
    throw InvalidArgument(field, "expected a file path or a sequence of file paths");
  }
  std::vector<std::string> out;
  int index = 0;
  for (const py::handle item : value) {
    if (!py::isinstance<py::str>(item) && !py::hasattr(item, "__fspath__")) {
      throw InvalidArgument(field, index, "expected a file path");
    }
    out.push_back(place_path(py::reinterpret_borrow<py::object>(item), field));
    ++index;
  }
  return out;
}

// workspace=(ax, ay, az, deg) as --workspace's "AX,AY,AZ,DEG" (each number exactly).
std::string place_workspace(const py::object& workspace) {
  if (workspace.is_none()) return "";
  const Eigen::VectorXd w = vector_from_array(workspace, "workspace");
  if (w.size() != 4 || !w.allFinite()) {
    throw InvalidArgument("workspace", "expected (ax, ay, az, deg), four finite numbers");
  }
  std::string out;
  for (Eigen::Index i = 0; i < 4; ++i) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", w(i));
    out += (i > 0 ? "," : "") + std::string(buffer);
  }
  return out;
}

py::object place_run(const place_json::Request& request,
                     const commands::VisibilityOptions& visibility) {
  place_json::check_request(request);
  const place_json::Sites sites = place_json::candidate_sites(
      request,
      [&](const std::string& path) {
        std::string source;
        Layout layout = layout_from_arguments(py::str(path), py::none(), py::none(), py::none(),
                                              py::none(), ReadArguments{}, &source);
        visibility.apply(&layout);
        return layout;
      },
      [&](Layout* layout) { visibility.apply(layout); });
  std::optional<io::WriteLock> lock;
  if (!request.out.empty()) lock.emplace(request.out);
  const place_json::Outcome outcome =
      without_gil([&] { return place_json::place(request, sites, {}); });
  const bool write = (outcome.complete || request.allow_partial) && !request.out.empty();
  if (write) io::save_layout(request.out, outcome.placed.layout, request.overwrite);
  const Json report = place_json::report(request, sites, outcome, write);
  const std::string why = outcome.complete
                              ? std::string()
                              : place_json::failure_message(outcome.result, outcome.placed);
  if (!outcome.complete && !request.allow_partial) {
    NumericalFailure failure(outcome.result.status == design::PlacementResult::Status::kComplete
                                 ? "not_certified"
                                 : design::to_string(outcome.result.status),
                             why, report);
    failure.objects.emplace_back("layout",
                                 std::make_shared<py::object>(py::cast(outcome.placed.layout)));
    throw failure;
  }
  if (!outcome.complete) {
    const std::string warning = why + (write ? "; written as asked (allow_partial)" : "");
    if (PyErr_WarnEx(PyExc_RuntimeWarning, warning.c_str(), 1) < 0) throw py::error_already_set();
  }
  py::object result = to_python(report);
  result["layout"] = py::cast(outcome.placed.layout);
  return result;
}

py::object place(const py::object& body, const py::object& sites, int markers,
                 const std::optional<int>& candidates, const std::optional<double>& cone_deg,
                 const std::optional<int>& min_visible, const py::object& workspace,
                 const std::optional<double>& min_separation, const py::object& keep,
                 bool robust_dropout, double min_distance_difference,
                 const std::optional<std::uint64_t>& seed, const std::optional<int>& threads,
                 const std::optional<int>& random_trials,
                 const std::optional<long>& exhaustive_limit, const py::object& out, bool overwrite,
                 const std::string& objective, const std::optional<double>& distance,
                 const std::optional<std::vector<double>>& distances,
                 const std::optional<double>& focal, const std::optional<double>& noise_px,
                 const std::string& statistic, const std::optional<int>& crb_samples,
                 const py::object& aim, const py::object& targets,
                 const std::optional<double>& fle_rms, const py::object& fle_sigma,
                 const std::optional<double>& min_coverage, bool allow_partial,
                 double marker_diameter, const py::object& exclude, const py::object& region,
                 int perturbations) {
  try {
    place_json::Request request =
        objective_request(objective, distance, distances, focal, noise_px, statistic, crb_samples,
                          aim, targets, fle_rms, fle_sigma);
    request.body = place_path(body, "body");
    request.sites = place_path(sites, "sites");
    request.candidates_given = candidates.has_value();
    request.candidates = candidates.value_or(request.candidates);
    request.markers = markers;
    request.out = place_path(out, "out");
    request.min_separation = min_separation.value_or(request.min_separation);
    request.keep = place_path(keep, "keep");
    request.robust_dropout = robust_dropout;
    request.min_distance_difference = min_distance_difference;
    request.seed = seed.value_or(request.seed);
    request.threads = threads.value_or(request.threads);
    request.random_trials = random_trials.value_or(request.random_trials);
    request.perturbations = perturbations;
    request.exhaustive_limit = exhaustive_limit.value_or(request.exhaustive_limit);
    request.overwrite = overwrite;
    request.min_coverage = min_coverage.value_or(request.min_coverage);
    request.allow_partial = allow_partial;
    request.marker_diameter = marker_diameter;
    request.exclude = place_paths(exclude, "exclude");
    request.region = place_path(region, "region");
    commands::VisibilityOptions visibility;
    visibility.cone_deg = cone_deg;
    visibility.min_visible = min_visible;
    visibility.workspace = place_workspace(workspace);
    return place_run(request, visibility);
  } catch (const InvalidArgument& e) {
    throw place_renamed(e);
  }
}

}  // namespace

InvalidArgument place_renamed(const InvalidArgument& e) {
  const std::string& field = e.field();
  if (field == "BODY" || field == "BODY/--sites") return e.renamed("body", e.index());
  if (field == "--target") return e.renamed("targets", e.index());
  if (field.rfind("--", 0) != 0) return e;
  std::string keyword = field.substr(2);
  for (char& c : keyword) {
    if (c == '-') c = '_';
  }
  return e.renamed(keyword, e.index());
}

place_json::Request objective_request(
    const std::string& objective, const std::optional<double>& distance,
    const std::optional<std::vector<double>>& distances, const std::optional<double>& focal,
    const std::optional<double>& noise_px, const std::string& statistic,
    const std::optional<int>& crb_samples, const py::object& aim, const py::object& targets,
    const std::optional<double>& fle_rms, const py::object& fle_sigma) {
  place_json::Request request;
  request.objective = objective;
  request.distance = distance.value_or(request.distance);
  if (distances && distances->empty()) {
    throw InvalidArgument("--distances", "give at least one distance (or none: distance=)");
  }
  request.distances = distances.value_or(request.distances);
  request.focal = focal.value_or(request.focal);
  request.noise_px = noise_px.value_or(request.noise_px);
  request.statistic = statistic;
  request.crb_samples = crb_samples.value_or(request.crb_samples);
  if (!aim.is_none()) {
    const Eigen::VectorXd a = vector_from_array(aim, "aim");
    if (a.size() != 3) throw InvalidArgument("aim", "expected (x, y, z)");
    request.aim = Eigen::Vector3d(a);
  }
  if (!targets.is_none()) request.targets = tre_targets(targets);
  if (fle_rms || !fle_sigma.is_none()) request.fle = tre_fle(fle_rms, fle_sigma);
  return request;
}

void bind_place_command(py::module_& module) {
  module.def(
      "place", &place, py::arg("body") = py::none(), py::kw_only(), py::arg("sites") = py::none(),
      py::arg("markers"), py::arg("candidates") = py::none(), py::arg("cone_deg") = py::none(),
      py::arg("min_visible") = py::none(), py::arg("workspace") = py::none(),
      py::arg("min_separation") = py::none(), py::arg("keep") = py::none(),
      py::arg("robust_dropout") = false, py::arg("min_distance_difference") = 0.0,
      py::arg("seed") = py::none(), py::arg("threads") = py::none(),
      py::arg("random_trials") = py::none(), py::arg("exhaustive_limit") = py::none(),
      py::arg("out") = py::none(), py::arg("overwrite") = false, py::arg("objective") = "affine",
      py::arg("distance") = py::none(), py::arg("distances") = py::none(),
      py::arg("focal") = py::none(), py::arg("noise_px") = py::none(),
      py::arg("statistic") = "worst", py::arg("crb_samples") = py::none(),
      py::arg("aim") = py::none(), py::arg("targets") = py::none(), py::arg("fle_rms") = py::none(),
      py::arg("fle_sigma") = py::none(), py::arg("min_coverage") = py::none(),
      py::arg("allow_partial") = false, py::arg("marker_diameter") = 0.0,
      py::arg("exclude") = py::none(), py::arg("region") = py::none(), py::arg("perturbations") = 0,
      "K marker sites on a body mesh or among given sites: every workspace direction "
      "trackable, then the best certified worst case under visibility (as `vantage place "
      "--json`; docs/math.md §21).");
}

}  // namespace vantage::python
