#pragma once

// vantage.tre: the target registration error report of tracker::tre_report(), as the fields of
// `vantage tre --json`.

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers tre on `module`.
void bind_tre_command(pybind11::module_& module);

}  // namespace vantage::python
