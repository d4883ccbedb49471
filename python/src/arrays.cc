#include "arrays.h"

#include <string>

#include "vantage/analysis/common.h"

namespace vantage::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The object as a C-contiguous float64 array, or InvalidArgument naming `name`.
Array as_double_array(const py::handle& object, const char* name) {
  const py::object numpy = py::module_::import("numpy");
  py::object array;
  try {
    array = numpy.attr("asarray")(object);
  } catch (const py::error_already_set&) {
    throw InvalidArgument(std::string(name) + ": expected an array of numbers");
  }
  const std::string kind = py::str(array.attr("dtype").attr("kind"));
  if (kind != "f" && kind != "i" && kind != "u") {
    throw InvalidArgument(std::string(name) + ": expected an array of numbers, got dtype " +
                          std::string(py::str(array.attr("dtype"))));
  }
  return Array::ensure(array);
}

std::string shape_text(const Array& array) {
  std::string out = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    out += (d ? ", " : "") + std::to_string(array.shape(d));
  }
  return out + (array.ndim() == 1 ? ",)" : ")");
}

}  // namespace

std::string path_from(const py::object& path, const char* keyword) {
  const py::object os = py::module_::import("os");
  try {
    // The file system's own bytes: a name that is not UTF-8 (a str with surrogate escapes, or
    // bytes) opens as it is; decoding it to a str first could not be cast.
    return os.attr("fsencode")(os.attr("fspath")(path)).cast<std::string>();
  } catch (const py::error_already_set&) {
    throw InvalidArgument(keyword, "expected a str or os.PathLike");
  } catch (const py::cast_error&) {
    throw InvalidArgument(keyword, "expected a str or os.PathLike");
  }
}

template <int Cols>
Eigen::Matrix<double, Cols, Eigen::Dynamic> rows_from_array(const py::handle& object,
                                                            const char* name) {
  const Array array = as_double_array(object, name);
  const std::string want = "an n x " + std::to_string(Cols) + " array (one row per entry)";
  if (array.ndim() == 2 && array.shape(1) == Cols) {
    Eigen::Matrix<double, Cols, Eigen::Dynamic> out(Cols, array.shape(0));
    const auto view = array.template unchecked<2>();
    for (py::ssize_t i = 0; i < array.shape(0); ++i) {
      for (int c = 0; c < Cols; ++c) out(c, i) = view(i, c);
    }
    return out;
  }
  if (array.ndim() == 2 && array.shape(0) == Cols) {
    throw InvalidArgument(std::string(name) + ": expected " + want + ", got shape " +
                          shape_text(array) + "; pass " + name + ".T");
  }
  throw InvalidArgument(std::string(name) + ": expected " + want + ", got shape " +
                        shape_text(array));
}

template Eigen::Matrix<double, 2, Eigen::Dynamic> rows_from_array<2>(const py::handle&,
                                                                     const char*);
template Eigen::Matrix<double, 3, Eigen::Dynamic> rows_from_array<3>(const py::handle&,
                                                                     const char*);

Eigen::VectorXd vector_from_array(const py::handle& object, const char* name) {
  const Array array = as_double_array(object, name);
  if (array.ndim() != 1) {
    throw InvalidArgument(std::string(name) + ": expected a 1-D array, got shape " +
                          shape_text(array));
  }
  Eigen::VectorXd out(array.shape(0));
  const auto view = array.unchecked<1>();
  for (py::ssize_t i = 0; i < array.shape(0); ++i) out(i) = view(i);
  return out;
}

Eigen::Vector2d pair_from_array(const py::handle& array, const char* name, const char* unit) {
  const Eigen::VectorXd c = vector_from_array(array, name);
  if (c.size() != 2 || !c.allFinite()) {
    throw InvalidArgument(std::string(name) + ": must be two finite numbers (" + unit + ")");
  }
  return {c(0), c(1)};
}

template <int Rows>
py::array_t<double> array_from_columns(const Eigen::Matrix<double, Rows, Eigen::Dynamic>& columns) {
  py::array_t<double> out({static_cast<py::ssize_t>(columns.cols()), py::ssize_t{Rows}});
  auto view = out.template mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < columns.cols(); ++i) {
    for (int c = 0; c < Rows; ++c) view(i, c) = columns(c, i);
  }
  return out;
}

template py::array_t<double> array_from_columns<2>(const Eigen::Matrix2Xd&);
template py::array_t<double> array_from_columns<3>(const Eigen::Matrix3Xd&);

py::array_t<double> array_from_vector(const Eigen::VectorXd& v) {
  py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
  auto view = out.mutable_unchecked<1>();
  for (Eigen::Index i = 0; i < v.size(); ++i) view(i) = v(i);
  return out;
}

}  // namespace vantage::python
