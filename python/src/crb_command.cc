// vantage.crb (crb_command.h).

#include "crb_command.h"

#include <pybind11/stl.h>

#include <optional>

#include "arrays.h"
#include "layouts.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/camera/pose_crb.h"
#include "vantage/commands/crb_json.h"

namespace vantage::python {

namespace {

py::object crb(const py::object& layout_arg, const py::object& points, double distance,
               double focal, double noise_px, const py::object& principal_point,
               const py::object& direction, const py::object& sweep_distance, int samples,
               int threads, bool allow_large, const py::object& format,
               const py::object& tag_points, const py::object& bundle, const py::object& aim) {
  std::optional<camera::PoseCrbSweep> sweep;
  if (!sweep_distance.is_none()) {
    std::tuple<double, double, int> t;
    try {
      t = sweep_distance.cast<std::tuple<double, double, int>>();
    } catch (const py::cast_error&) {
      throw InvalidArgument("sweep_distance",
                            "expected (from, to, count): two distances and an int");
    }
    sweep = camera::PoseCrbSweep{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
    commands::check_limit("sweep_distance", sweep->count, commands::kMaxCrbSweepDistances, "crb",
                          allow_large, kPythonWords);
  }
  std::string source;
  const Layout layout =
      layout_from_arguments(layout_arg, py::none(), points, py::none(), py::none(),
                            {format, tag_points, bundle, allow_large}, &source);
  camera::PoseCrbOptions options;
  options.distance = distance;
  options.focal_length = focal;
  options.noise_px = noise_px;
  options.samples = samples;
  options.threads = threads;
  if (!principal_point.is_none()) {
    const Eigen::VectorXd pp = vector_from_array(principal_point, "principal_point");
    if (pp.size() != 2) throw InvalidArgument("principal_point", "expected [cx, cy]");
    options.principal_point = pp;
  }
  if (!aim.is_none()) {
    const Eigen::VectorXd o = vector_from_array(aim, "aim");
    if (o.size() != 3) throw InvalidArgument("aim", "expected [x, y, z]");
    options.aim = Eigen::Vector3d(o);
  }
  std::optional<Eigen::Vector3d> a;
  if (!direction.is_none()) {
    const Eigen::VectorXd d = vector_from_array(direction, "direction");
    if (d.size() != 3) throw InvalidArgument("direction", "expected [ax, ay, az]");
    a = Eigen::Vector3d(d);
  }
  const camera::PoseCrbReport report = without_gil([&] {
    try {
      return camera::pose_crb_report(layout, options, a, sweep);
    } catch (const InvalidArgument& e) {
      // The library's field is the option's: focal_length is the keyword focal.
      if (e.field() == "focal_length") throw e.renamed("focal", std::nullopt);
      throw source.empty() || e.field() != "vectors" ? e : e.against(source);
    }
  });
  // As the CLI exits 1: nothing trackable raises NumericalError with the status and the reason.
  const bool failed = report.map.status != camera::PoseCrbMap::Status::kOk;
  return result_or_raise(failed, camera::to_string(report.map.status),
                         failed ? camera::untrackable_reason(report.map, options.distance) : "",
                         crb_json::report(report));
}

}  // namespace

void bind_crb_command(py::module_& module) {
  module.def("crb", &crb, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("points") = py::none(), py::arg("distance"), py::arg("focal"),
             py::arg("noise_px"), py::arg("principal_point") = py::none(),
             py::arg("direction") = py::none(), py::arg("sweep_distance") = py::none(),
             py::arg("samples") = 10000, py::arg("threads") = 0, py::arg("allow_large") = false,
             py::arg("format") = py::none(), py::arg("tag_points") = py::none(),
             py::arg("bundle") = py::none(), py::arg("aim") = py::none(),
             "The pose Cramer-Rao bound of a pinhole camera over every viewpoint (as `vantage crb "
             "--json`; docs/math.md §22).");
}

}  // namespace vantage::python
