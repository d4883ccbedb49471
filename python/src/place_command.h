#pragma once

// vantage.place: K marker sites on a body (a mesh's surface, or given sites with normals), every
// workspace direction trackable and the certified worst case under visibility best
// (design::place_markers(), docs/math.md §21), as the fields of `vantage place --json`: the same
// checks, placement and JSON writer as the CLI (commands/include/vantage/commands/place_json.h).

#include <pybind11/pybind11.h>

namespace vantage::python {

/// Registers place on `module`.
void bind_place_command(pybind11::module_& module);

}  // namespace vantage::python
