// vantage.simulate: the Monte Carlo of `vantage simulate LAYOUT`, returning the fields of its
// --json output.

#include "simulate_command.h"

#include <pybind11/stl.h>

#include <optional>

#include "arrays.h"
#include "layouts.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/limits.h"
#include "vantage/simulate/layout_simulation.h"

namespace vantage::python {

namespace {

py::object simulate_layout(const py::object& layout_arg, const py::object& vectors,
                           const py::object& points, long trials, const std::string& camera,
                           double noise_px, std::optional<double> snr_db, const std::string& noise,
                           double range, double focal_px, const py::object& principal_point,
                           const py::object& lateral_offset, const std::string& viewpoint,
                           const std::vector<std::string>& methods, std::uint64_t seed, int threads,
                           bool per_trial, bool allow_large, const py::object& format,
                           const py::object& tag_points, const py::object& bundle) {
  std::string source;
  const Layout layout = layout_from_arguments(layout_arg, vectors, points, py::none(), py::none(),
                                              {format, tag_points, bundle, allow_large}, &source);
  if (trials < 1) throw InvalidArgument("trials", "must be >= 1");
  commands::check_limit("trials", trials, commands::kMaxTrials, "simulate", allow_large,
                        kPythonWords);
  if (per_trial) {
    commands::check_limit("trials with per_trial=True", trials, commands::kMaxPerTrialTrials,
                          "simulate", allow_large, kPythonWords);
  }
  simulate::LayoutSimulationOptions options;
  simulate::LayoutSceneOptions& scene = options.scene;
  if (camera != "affine" && camera != "pinhole") {
    throw InvalidArgument("camera: expected affine or pinhole, got '" + camera + "'");
  }
  scene.camera =
      camera == "pinhole" ? simulate::CameraModel::kPinhole : simulate::CameraModel::kAffine;
  scene.noise_px = noise_px;
  scene.snr_db = snr_db;
  scene.noise = simulate::parse_noise_kind(noise, "noise");
  scene.range = range;
  scene.focal_px = focal_px;
  scene.principal_point = pair_from_array(principal_point, "principal_point", "pixels");
  scene.lateral_offset = pair_from_array(lateral_offset, "lateral_offset", "object sizes");
  if (viewpoint != "random" && viewpoint != "worst") {
    throw InvalidArgument("viewpoint: expected random or worst, got '" + viewpoint + "'");
  }
  options.worst_viewpoint = viewpoint == "worst";
  options.monte_carlo.trials = trials;
  options.monte_carlo.seed = seed;
  options.monte_carlo.threads = threads;
  options.monte_carlo.keep_trials = per_trial;
  options.methods = methods;
  std::string why;
  if (!options.is_valid(&why)) {
    // "scene.noise_px: ..." -> "noise_px: ...": the keyword arguments carry the field names.
    throw InvalidArgument(why.substr(why.find('.') + 1));
  }
  const simulate::LayoutSimulation run =
      without_gil([&] { return simulate::simulate_layout(layout, options); });
  const bool failed = run.has_bound && !run.bound.passed;
  return result_or_raise(failed, "bound_check_failed", failed ? run.bound.message : "",
                         simulate::report_json(run, per_trial));
}

}  // namespace

void bind_simulate_command(py::module_& module) {
  const simulate::LayoutSceneOptions scene;
  module.def("simulate", &simulate_layout, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("vectors") = py::none(), py::arg("points") = py::none(),
             py::arg("trials") = simulate::MonteCarloOptions{}.trials, py::arg("camera") = "affine",
             py::arg("noise_px") = scene.noise_px, py::arg("snr_db") = py::none(),
             py::arg("noise") = "gaussian", py::arg("range") = scene.range,
             py::arg("focal_px") = scene.focal_px,
             py::arg("principal_point") = std::vector<double>{0.0, 0.0},
             py::arg("lateral_offset") = std::vector<double>{0.0, 0.0},
             py::arg("viewpoint") = "random", py::arg("methods") = std::vector<std::string>{},
             py::arg("seed") = simulate::MonteCarloOptions{}.seed, py::arg("threads") = 0,
             py::arg("per_trial") = false, py::arg("allow_large") = false,
             py::arg("format") = py::none(), py::arg("tag_points") = py::none(),
             py::arg("bundle") = py::none(),
             "Monte Carlo of every applicable estimator on seeded views of the layout, with the "
             "bound check of Eq. (26) / Eq. (30) on the affine camera (as `vantage simulate "
             "--json`). Raises NumericalError when the bound check fails.");
}

}  // namespace vantage::python
