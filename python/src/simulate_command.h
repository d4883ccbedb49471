#pragma once

// vantage.simulate.

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers simulate on `module`.
void bind_simulate_command(pybind11::module_& module);

}  // namespace vantage::python
