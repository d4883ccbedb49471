// vantage.ident (ident_command.h).

#include "ident_command.h"

#include <string>
#include <vector>

#include "layouts.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/ident_json.h"
#include "vantage/tracker/tool_match.h"

namespace vantage::python {

namespace {

// A 3-D registration needs three markers (as `vantage ident --min-visible`).
constexpr int kIdentMinVisible = 3;

// One tool of the library: a vantage.Layout, or a path read as `vantage ident` reads its TOOL
// arguments (format=, allow_large=); *source is the path, or "" for a Layout.
Layout ident_tool(const py::handle& item, long index, const ReadArguments& read,
                  std::string* source) {
  if (!py::isinstance<Layout>(item) && !py::isinstance<py::str>(item) &&
      !py::hasattr(item, "__fspath__")) {
    throw InvalidArgument("tools", index, "expected a vantage.Layout or a file path");
  }
  const Layout tool = layout_from_arguments(py::reinterpret_borrow<py::object>(item), py::none(),
                                            py::none(), py::none(), py::none(), read, source);
  if (tool.mode != LayoutMode::kPoints) {
    const InvalidArgument e("tools", index, "vectors: a tool needs marker positions (\"points\")");
    throw source->empty() ? e : e.against(*source);
  }
  return tool;
}

py::object ident(const py::object& tools_arg, int min_visible, const py::object& format,
                 bool allow_large) {
  if (min_visible < kIdentMinVisible) {
    throw InvalidArgument("min_visible", "must be >= 3 (a 3-D registration needs three markers)");
  }
  if (py::isinstance<py::str>(tools_arg) || py::isinstance<py::bytes>(tools_arg) ||
      py::hasattr(tools_arg, "__fspath__") || !py::hasattr(tools_arg, "__iter__")) {
    throw InvalidArgument("tools", "expected a list of vantage.Layout objects or file paths");
  }
  const ReadArguments read{format, py::none(), py::none(), allow_large};
  // The items first: the bound is checked before any tool is read.
  const py::list items(tools_arg);
  commands::check_limit("tools", static_cast<long>(items.size()), commands::kMaxIdentTools, "ident",
                        allow_large, kPythonWords);
  std::vector<Layout> tools;
  std::vector<std::string> files;
  for (const py::handle item : items) {
    const long index = static_cast<long>(tools.size());
    std::string source;
    tools.push_back(ident_tool(item, index, read, &source));
    files.push_back(source);
    const Layout& tool = tools.back();
    if (tool.entries.cols() < min_visible) {
      throw InvalidArgument("min_visible", std::to_string(min_visible) + " exceeds the " +
                                               std::to_string(tool.entries.cols()) +
                                               " markers of tools[" + std::to_string(index) + "]" +
                                               (source.empty() ? "" : " (" + source + ")"));
    }
  }
  if (tools.empty()) throw InvalidArgument("tools", "need at least one tool");
  std::vector<Eigen::Matrix3Xd> points;
  for (const Layout& tool : tools) points.push_back(tool.entries);
  tracker::ToolMatchOptions options;
  options.min_visible = min_visible;
  const tracker::ToolLibraryMatches matches =
      without_gil([&] { return tracker::match_tool_library(points, options); });
  Json out = ident_json::report_without_pairs(matches, tools, files);
  // A vantage.Layout has no file: null, as the other results' "layout" of arrays.
  for (std::size_t t = 0; t < files.size(); ++t) {
    if (files[t].empty()) out["tools"][t]["file"] = nullptr;
  }
  // One pair's JSON at a time (ident_json::report_without_pairs).
  py::object result = to_python(out);
  py::list pairs;
  for (const tracker::ToolPairMatch& p : matches.pairs) {
    pairs.append(to_python(ident_json::pair(p, tools)));
  }
  result["pairs"] = pairs;
  return result;
}

}  // namespace

void bind_ident_command(py::module_& module) {
  module.def("ident", &ident, py::arg("tools"), py::kw_only(),
             py::arg("min_visible") = kIdentMinVisible, py::arg("format") = py::none(),
             py::arg("allow_large") = false,
             "How close the tools of a library come by their inter-marker distances: every pair "
             "and each tool relabelled, mirror images included (as `vantage ident --json`; "
             "docs/math.md §24).");
}

}  // namespace vantage::python
