#pragma once

// Argument conversions of the Python module: paths, and numpy <-> Eigen. Point sets are n x 3
// arrays (one point or vector per row, like the lists of the JSON files); image points n x 2. Any
// numeric dtype is accepted and converted to float64 (float32 included); other shapes are rejected
// with a ValueError that names the argument and, for a 3 x n array, says to pass its transpose.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>

namespace vantage::python {

namespace py = pybind11;

/// A str or os.PathLike as a path string; InvalidArgument naming `keyword` otherwise.
std::string path_from(const py::object& path, const char* keyword);

/// An n x Cols array (Cols = 2 or 3) as the Cols x n matrix the C++ library takes.
template <int Cols>
Eigen::Matrix<double, Cols, Eigen::Dynamic> rows_from_array(const py::handle& array,
                                                            const char* name);

/// A 1-D array of numbers.
Eigen::VectorXd vector_from_array(const py::handle& array, const char* name);

/// Two finite numbers (a principal point, an offset); throws InvalidArgument naming `name`
/// with `unit` ("pixels") in the message otherwise.
Eigen::Vector2d pair_from_array(const py::handle& array, const char* name, const char* unit);

/// A Rows x n matrix (Rows = 2 or 3) as an n x Rows numpy array (one row per column).
template <int Rows>
py::array_t<double> array_from_columns(const Eigen::Matrix<double, Rows, Eigen::Dynamic>& columns);

/// A vector as a 1-D numpy array.
py::array_t<double> array_from_vector(const Eigen::VectorXd& v);

}  // namespace vantage::python
