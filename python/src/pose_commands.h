#pragma once

// vantage.pose (one entry per estimator in a table) and vantage.orient.

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers pose, pose_methods and orient on `module`.
void bind_pose_commands(pybind11::module_& module);

}  // namespace vantage::python
