#pragma once

// vantage.ident: how close the tools of a library come by their inter-marker distances
// (vantage::tracker::match_tool_library(), docs/math.md §24), as the fields of `vantage ident
// --json`.

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers ident on `module`.
void bind_ident_command(pybind11::module_& module);

}  // namespace vantage::python
