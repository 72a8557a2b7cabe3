// python/src/numpy_arrays.h — checked views of numpy arrays and arrays made
// from C++ data, shared by the areas of the module.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <vector>

#include "predicates_dispatch.h"

namespace relgeo::python {

namespace py = pybind11;

/// Any array convertible to float64 (no copy when it already is, whatever its strides).
using Double_array = py::array_t<double, py::array::forcecast>;

/// Throws ValueError unless `a` has shape (n, columns); returns n. `what`
/// names the argument in the message.
inline std::size_t require_rows(const py::array& a, py::ssize_t columns, const std::string& what) {
  if (a.ndim() != 2 || a.shape(1) != columns) {
    std::string shape;
    for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
    throw py::value_error(what + " must have shape (n, " + std::to_string(columns) + "), not (" + shape +
                          (a.ndim() == 1 ? ",)" : ")"));
  }
  return static_cast<std::size_t>(a.shape(0));
}

/// The rows of a 2-D float64 array (strides in elements; 0 when broadcast).
inline Coordinate_rows coordinate_rows(const Double_array& a) {
  constexpr auto size = static_cast<py::ssize_t>(sizeof(double));
  return {a.data(), a.strides(0) / size, a.strides(1) / size};
}

/// A new 1-d array holding `values`.
template <class T, class U>
py::array_t<T> vector_array(const std::vector<U>& values) {
  py::array_t<T> out(static_cast<py::ssize_t>(values.size()));
  T* data = out.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) data[i] = static_cast<T>(values[i]);
  return out;
}

/// A new (rows, columns) array holding `values` (row-major, rows * columns of them).
template <class T, class U>
py::array_t<T> matrix_array(const std::vector<U>& values, std::size_t rows, std::size_t columns) {
  py::array_t<T> out({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  T* data = out.mutable_data();
  for (std::size_t i = 0; i < rows * columns; ++i) data[i] = static_cast<T>(values[i]);
  return out;
}

}  // namespace relgeo::python
