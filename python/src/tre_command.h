#pragma once

// vantage.tre: the target registration error report of tracker::tre_report(), as the fields of
// `vantage tre --json`.

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "vantage/tracker/target_registration.h"

namespace vantage::python {

/// targets: one [x, y, z] or an n x 3 array of them, at least one, finite; InvalidArgument
/// naming "targets" otherwise (vantage.tre and vantage.place share it).
std::vector<Eigen::Vector3d> tre_targets(const pybind11::object& targets);

/// Exactly one of fle_rms (> 0) and fle_sigma (sigma_perp, sigma_axial); InvalidArgument naming
/// "fle_rms" or "fle_sigma" otherwise.
tracker::FleModel tre_fle(const std::optional<double>& fle_rms, const pybind11::object& fle_sigma);

/// Registers tre on `module`.
void bind_tre_command(pybind11::module_& module);

}  // namespace vantage::python
