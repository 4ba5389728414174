#pragma once
/// @file Read-only numpy views of the library's arrays, without a copy.

#include <pybind11/numpy.h>

#include "ancfnet/common/types.hpp"

namespace ancfnet::python {

/// A read-only 1-D numpy array over the `size` doubles at `data`; `owner` becomes its base and
/// keeps the storage alive as long as the array.
inline pybind11::array_t<double> ReadOnlyView(const double* data, Index size,
                                              const pybind11::object& owner) {
  pybind11::array_t<double> view(static_cast<pybind11::ssize_t>(size), data, owner);
  view.attr("setflags")(pybind11::arg("write") = false);
  return view;
}

}  // namespace ancfnet::python
