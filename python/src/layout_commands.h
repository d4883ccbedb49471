#pragma once

// vantage.analyze, vantage.design, vantage.weights.

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers analyze, design and weights on `module`.
void bind_layout_commands(pybind11::module_& module);

}  // namespace vantage::python
