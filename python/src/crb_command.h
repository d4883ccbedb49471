#pragma once

// vantage.crb: the pose CRB report of camera::pose_crb_report(), as the fields of `vantage crb
// --json`.

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers crb on `module`.
void bind_crb_command(pybind11::module_& module);

}  // namespace vantage::python
