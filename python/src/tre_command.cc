// vantage.tre (tre_command.h).

#include "tre_command.h"

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <vector>

#include "arrays.h"
#include "layouts.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/analysis/scaling.h"
#include "vantage/commands/tre_json.h"
#include "vantage/tracker/tre_report.h"

namespace vantage::python {

std::vector<Eigen::Vector3d> tre_targets(const py::object& targets) {
  if (targets.is_none()) throw InvalidArgument("targets", "give at least one target [x, y, z]");
  std::vector<Eigen::Vector3d> out;
  if (py::module_::import("numpy").attr("ndim")(targets).cast<int>() == 1) {
    const Eigen::VectorXd r = vector_from_array(targets, "targets");
    if (r.size() != 3) throw InvalidArgument("targets", "expected [x, y, z] or an n x 3 array");
    out.emplace_back(r);
  } else {
    const Eigen::Matrix3Xd rows = rows_from_array<3>(targets, "targets");
    for (Eigen::Index i = 0; i < rows.cols(); ++i) out.emplace_back(rows.col(i));
  }
  if (out.empty()) throw InvalidArgument("targets", "give at least one target [x, y, z]");
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!out[i].allFinite())
      throw InvalidArgument("targets", static_cast<long>(i), "must be finite");
  }
  return out;
}

tracker::FleModel tre_fle(const std::optional<double>& fle_rms, const py::object& fle_sigma) {
  if (fle_rms.has_value() == !fle_sigma.is_none()) {
    throw InvalidArgument("fle_rms", "give exactly one of fle_rms and fle_sigma");
  }
  if (fle_rms) {
    if (!(std::isfinite(*fle_rms) && *fle_rms > 0.0)) {
      throw InvalidArgument("fle_rms", "must be a finite number > 0");
    }
    return tracker::FleModel::isotropic(*fle_rms);
  }
  const Eigen::VectorXd s = vector_from_array(fle_sigma, "fle_sigma");
  tracker::FleModel fle;
  if (s.size() == 2) {
    fle.sigma_perp = s(0);
    fle.sigma_axial = s(1);
  }
  if (s.size() != 2 || !fle.is_valid()) {
    throw InvalidArgument("fle_sigma",
                          "expected (sigma_perp, sigma_axial), finite, >= 0, not both 0");
  }
  return fle;
}

namespace {

py::object tre(const py::object& layout_arg, const py::object& points, const py::object& targets,
               const std::optional<double>& fle_rms, const py::object& fle_sigma,
               const py::object& direction, long monte_carlo, std::uint64_t seed, int threads,
               bool allow_large, const py::object& format, const py::object& tag_points,
               const py::object& bundle) {
  commands::check_limit("monte_carlo", monte_carlo, commands::kMaxTreTrials, "tre", allow_large,
                        kPythonWords);
  std::string source;
  const Layout layout =
      layout_from_arguments(layout_arg, py::none(), points, py::none(), py::none(),
                            {format, tag_points, bundle, allow_large}, &source);
  const std::vector<Eigen::Vector3d> target_list = tre_targets(targets);
  tracker::TreOptions options;
  options.fle = tre_fle(fle_rms, fle_sigma);
  if (!direction.is_none()) {
    const Eigen::VectorXd d = vector_from_array(direction, "direction");
    if (d.size() != 3 || unit_direction(Eigen::Vector3d(d)).isZero()) {
      throw InvalidArgument("direction", "expected [ax, ay, az], finite, not all 0");
    }
    options.direction = Eigen::Vector3d(d);
  }
  options.monte_carlo_trials = monte_carlo;
  options.seed = seed;
  options.threads = threads;
  const tracker::TreReport report = without_gil([&] {
    try {
      return tracker::tre_report(layout, target_list, options);
    } catch (const InvalidArgument& e) {
      // The library's fields as the keywords that set them.
      if (e.field() == "target") throw e.renamed("targets", std::nullopt);
      if (e.field() == "monte_carlo_trials") throw e.renamed("monte_carlo", std::nullopt);
      if (e.field() == "fle.sigma_perp" || e.field() == "fle.sigma_axial") {
        throw e.renamed(fle_rms ? "fle_rms" : "fle_sigma", std::nullopt);
      }
      throw source.empty() || e.field() != "points" ? e : e.against(source);
    }
  });
  // As the CLI exits 1: a target tracked from no direction raises NumericalError "untracked".
  const std::string untracked = tre_json::untracked_reason(report);
  return result_or_raise(!untracked.empty(), "untracked", untracked, tre_json::report(report));
}

}  // namespace

void bind_tre_command(py::module_& module) {
  module.def("tre", &tre, py::arg("layout") = py::none(), py::kw_only(),
             py::arg("points") = py::none(), py::arg("targets") = py::none(),
             py::arg("fle_rms") = py::none(), py::arg("fle_sigma") = py::none(),
             py::arg("direction") = py::none(), py::arg("monte_carlo") = 0, py::arg("seed") = 1,
             py::arg("threads") = 0, py::arg("allow_large") = false, py::arg("format") = py::none(),
             py::arg("tag_points") = py::none(), py::arg("bundle") = py::none(),
             "The target registration error of a tool on a 3-D tracker over every tracked line "
             "of sight (as `vantage tre --json`; docs/math.md §23).");
}

}  // namespace vantage::python
