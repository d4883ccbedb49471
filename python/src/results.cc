#include "results.h"

#include "vantage/analysis/common.h"

namespace vantage::python {

py::object to_python(const Json& value) {
  switch (value.type()) {
    case Json::value_t::object: {
      py::dict out;
      for (const auto& item : value.items()) out[py::str(item.key())] = to_python(item.value());
      return std::move(out);
    }
    case Json::value_t::array: {
      py::list out;
      for (const Json& item : value) out.append(to_python(item));
      return std::move(out);
    }
    case Json::value_t::string:
      return py::str(value.get<std::string>());
    case Json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(value.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(value.get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(value.get<double>());
    default:
      return py::none();
  }
}

const commands::LimitWords kPythonWords{"vantage.", "()", "allow_large=True"};

py::object result_or_raise(bool failed, const std::string& status, const std::string& message,
                           const Json& result, const std::string& text) {
  if (failed) throw NumericalFailure(status, message.empty() ? status : message, result, text);
  return to_python(result);
}

void register_errors(py::module_& module) {
  static py::exception<NumericalFailure> error(module, "NumericalError", PyExc_RuntimeError);
  error.doc() =
      "A computation that finished but failed numerically (the CLI's exit status 1): not "
      "certified, solver failure, degenerate data. Attributes: status (the result's status "
      "string), message, result (the full typed result, as returned on success), text (the "
      "result's brief report when it has one, else empty).";
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const NumericalFailure& failure) {
      py::object instance = py::handle(error.ptr())(failure.what());
      instance.attr("status") = failure.status;
      instance.attr("message") = std::string(failure.what());
      py::object result = to_python(failure.result);
      for (const auto& [key, object] : failure.objects) result[py::str(key)] = *object;
      instance.attr("result") = result;
      instance.attr("text") = failure.text;
      PyErr_SetObject(error.ptr(), instance.ptr());
    } catch (const InvalidArgument& bad) {
      const auto or_none = [](const std::string& text) -> py::object {
        return text.empty() ? py::object(py::none()) : py::object(py::str(text));
      };
      py::object instance = py::handle(PyExc_ValueError)(bad.what());
      instance.attr("field") = or_none(bad.field());
      instance.attr("index") =
          bad.index() ? py::object(py::int_(*bad.index())) : py::object(py::none());
      instance.attr("problem") = or_none(bad.problem());
      instance.attr("source") = or_none(bad.source());
      PyErr_SetObject(PyExc_ValueError, instance.ptr());
    }
  });
}

}  // namespace vantage::python
