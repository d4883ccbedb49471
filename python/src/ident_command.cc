// vantage.ident (ident_command.h).

#include "ident_command.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "layouts.h"
#include "results.h"
#include "vantage/analysis/common.h"
#include "vantage/commands/ident_json.h"
#include "vantage/commands/ident_tools.h"
#include "vantage/tracker/tool_match.h"

namespace vantage::python {

namespace {

// A 3-D registration needs three markers (as `vantage ident --min-visible`).
constexpr int kIdentMinVisible = 3;

// One tool of the library: a vantage.Layout (its own minimum from its visibility), or a path
// read once as `vantage ident` reads its TOOL arguments (format=, allow_large=); *source is the
// path, or "" for a Layout.
commands::IdentTool ident_tool(const py::handle& item, long index, const ReadArguments& read,
                               std::string* source) {
  commands::IdentTool tool;
  source->clear();
  if (py::isinstance<Layout>(item)) {
    tool.layout = item.cast<Layout>();
    tool.min_visible = commands::own_min_visible(tool.layout);
  } else {
    *source = py::str(item).cast<std::string>();
    const io::LayoutReadOptions options = read_options_from(read);
    try {
      tool = without_gil([&] { return commands::read_ident_tool(*source, options); });
    } catch (const io::FileTooLarge& e) {
      throw io::FileTooLarge(std::string(e.what()) +
                             (read.allow_large ? "" : " (allow_large=True raises it to 1 GiB)"));
    }
  }
  if (tool.layout.mode != LayoutMode::kPoints) {
    const InvalidArgument e("tools", index, "vectors: a tool needs marker positions (\"points\")");
    throw source->empty() ? e : e.against(*source);
  }
  return tool;
}

py::object ident(const py::object& tools_arg, const py::object& min_visible_arg,
                 double same_tolerance, const py::object& format, bool allow_large) {
  const bool given = !min_visible_arg.is_none();
  if (given &&
      (!py::isinstance<py::int_>(min_visible_arg) || py::isinstance<py::bool_>(min_visible_arg))) {
    throw InvalidArgument("min_visible", "expected an integer or None (each tool's own)");
  }
  const int min_visible = given ? min_visible_arg.cast<int>() : 0;
  if (given && min_visible < kIdentMinVisible) {
    throw InvalidArgument("min_visible", "must be >= 3 (a 3-D registration needs three markers)");
  }
  if (!(same_tolerance >= 0.0 && std::isfinite(same_tolerance))) {
    throw InvalidArgument("same_tolerance", "must be finite and >= 0");
  }
  if (py::isinstance<py::str>(tools_arg) || py::isinstance<py::bytes>(tools_arg) ||
      py::hasattr(tools_arg, "__fspath__") || !py::hasattr(tools_arg, "__iter__")) {
    throw InvalidArgument("tools", "expected a list of vantage.Layout objects or file paths");
  }
  const ReadArguments read{format, py::none(), py::none(), allow_large};
  // Folders become their tool files (as `vantage ident`); Layouts stay as they are.
  // origin[k]: the position in `tools` that item k came from (errors name it).
  py::list items;
  std::vector<long> origin;
  long position = 0;
  for (const py::handle item : py::list(tools_arg)) {
    const long index = position++;
    if (py::isinstance<Layout>(item)) {
      items.append(item);
      origin.push_back(index);
      continue;
    }
    if (!py::isinstance<py::str>(item) && !py::hasattr(item, "__fspath__")) {
      throw InvalidArgument("tools", index, "expected a vantage.Layout or a file path");
    }
    const py::object path = py::module_::import("os").attr("fspath")(item);
    if (!py::isinstance<py::str>(path)) {
      throw InvalidArgument("tools", index, "expected a str path (not bytes)");
    }
    std::vector<std::string> files;
    try {
      files = commands::tool_files({path.cast<std::string>()});
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("tools", index, e.what());
    }
    for (const std::string& file : files) {
      items.append(py::str(file));
      origin.push_back(index);
    }
  }
  // The items first: the bound is checked before any tool is read.
  commands::check_limit("tools", static_cast<long>(items.size()), commands::kMaxIdentTools, "ident",
                        allow_large, kPythonWords);
  std::vector<Layout> tools;
  std::vector<std::string> files;
  std::vector<int> k;
  for (const py::handle item : items) {
    const long index = origin[tools.size()];
    std::string source;
    commands::IdentTool read_tool = ident_tool(item, index, read, &source);
    tools.push_back(std::move(read_tool.layout));
    files.push_back(source);
    const Layout& tool = tools.back();
    k.push_back(given ? min_visible : read_tool.min_visible);
    if (given && tool.entries.cols() < min_visible) {
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
  options.same_tolerance = same_tolerance;
  const tracker::ToolLibraryMatches matches =
      without_gil([&] { return tracker::match_tool_library(points, options, k); });
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
  module.def("ident", &ident, py::arg("tools"), py::kw_only(), py::arg("min_visible") = py::none(),
             py::arg("same_tolerance") = tracker::ToolMatchOptions{}.same_tolerance,
             py::arg("format") = py::none(), py::arg("allow_large") = false,
             "How close the tools of a library (Layouts, files or folders of tool files) come by "
             "their inter-marker distances: every pair and each tool relabelled, mirror images "
             "included, each pair's verdict (same_tool, mirror, distinct) and the matrix (as "
             "`vantage ident --json`; docs/math.md §24). min_visible=None: each tool's own "
             "minimum markers.");
}

}  // namespace vantage::python
