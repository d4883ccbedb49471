#pragma once

// Layouts in the Python module: the vantage.Layout class, load_layout / save_layout / board /
// data_vectors / pbar_at_viewpoints, and the one place that turns the `layout | vectors= |
// points=` arguments of analyze, design and weights into a vantage::Layout.

#include <pybind11/pybind11.h>

#include <string>

#include "vantage/analysis/layout.h"
#include "vantage/io/layout_formats.h"

namespace vantage::python {

namespace py = pybind11;

/// How a layout file is read: the keyword arguments format=, tag_points=, bundle= (the CLI's
/// --format, --tag-points, --bundle; None for the default) and allow_large= (files up to 1 GiB
/// instead of 64 MiB, as --allow-large).
struct ReadArguments {
  py::object format = py::none();
  py::object tag_points = py::none();
  py::object bundle = py::none();
  bool allow_large = false;
};

/// format=, tag_points=, bundle=, allow_large= as the reader's options (the CLI's --format,
/// --tag-points, --bundle, --allow-large); InvalidArgument names the keyword.
io::LayoutReadOptions read_options_from(const ReadArguments& read);

/// The layout the caller means: `layout` (a vantage.Layout, or a path read in any supported
/// format as `read` says) or exactly one of `vectors` / `points` (n x 3) with optional `weights`
/// and `candidates`. Sets *source to the path (or "" for arrays). Throws InvalidArgument
/// (ValueError) with the reader's message on bad input.
Layout layout_from_arguments(const py::object& layout, const py::object& vectors,
                             const py::object& points, const py::object& weights,
                             const py::object& candidates, const ReadArguments& read,
                             std::string* source);

/// Registers vantage.Layout and the layout functions.
void bind_layouts(py::module_& module);

}  // namespace vantage::python
