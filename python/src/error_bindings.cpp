#include <pybind11/pybind11.h>

#include "ancfnet/common/error.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace ancfnet::python {

void BindErrors(py::module_& m) {
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError).doc() =
      "Invalid user input: a scene file or string, an option or a call to the API. The message\n"
      "is the command-line tool's one line, \"SOURCE:LINE:COLUMN: what is wrong (key 'KEY')\"\n"
      "for a scene.";
  py::register_exception<SolverError>(m, "SolverError", PyExc_RuntimeError).doc() =
      "A solver failed for good (no convergence even at the smallest step, a singular matrix).";
}

}  // namespace ancfnet::python
