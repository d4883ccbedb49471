#pragma once

// How the Python module hands results back: every result is built as the same JSON object the
// CLI prints with --json (field names are the public contract), then converted to Python
// objects (dict, list, float, int, bool, str, None). vantage/_results.py makes the typed result
// (vantage.LayoutReport, vantage.PoseEstimate, ...) from that dict, which its to_dict() returns.
//
// A numerical failure (the CLI's exit status 1) raises vantage.NumericalError carrying
// `status`, `message` and the full `result`.

#include <pybind11/pybind11.h>

#include <memory>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "vantage/commands/limits.h"

namespace vantage::python {

namespace py = pybind11;
using Json = nlohmann::ordered_json;

/// The JSON value as plain Python objects.
py::object to_python(const Json& value);

/// Thrown by a binding when the computation finished but failed numerically; translated into
/// vantage.NumericalError.
class NumericalFailure : public std::runtime_error {
 public:
  NumericalFailure(std::string status, const std::string& message, Json result,
                   std::string text = "")
      : std::runtime_error(message),
        status(std::move(status)),
        result(std::move(result)),
        text(std::move(text)) {}

  std::string status;
  Json result;
  std::string text;  ///< the result's own brief text (LayoutReport::brief_report()), or ""
  /// Entries added to the result's dict beside the JSON's (e.g. place's "layout", a bound
  /// vantage.Layout): what a caller gets on success is on the error too.
  std::vector<std::pair<std::string, std::shared_ptr<py::object>>> objects;
};

/// Returns `result` as Python objects, or throws NumericalFailure(status, message, result, text)
/// when `failed`.
py::object result_or_raise(bool failed, const std::string& status, const std::string& message,
                           const Json& result, const std::string& text = "");

/// How the size limits (vantage/commands/limits.h) word Python's calls: "vantage.analyze()",
/// "allow_large=True lifts it".
extern const commands::LimitWords kPythonWords;

/// Defines vantage.NumericalError (a RuntimeError) in `module` and translates NumericalFailure;
/// translates InvalidArgument into ValueError with the attributes field, index, problem and
/// source (None when absent).
void register_errors(py::module_& module);

/// Runs `call` with the GIL released (for the long computations; `call` touches no Python
/// object).
template <typename Call>
auto without_gil(Call&& call) {
  py::gil_scoped_release release;
  return call();
}

}  // namespace vantage::python
