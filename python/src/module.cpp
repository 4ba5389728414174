// The Python module `ancfnet` over the C++ library (docs/python.md).
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(ancfnet, m) {
  m.doc() =
      "ANCF cables, beams and tether nets: the ancfnet C++ library from Python.\n\n"
      "Load a scene (load_scene, parse_scene) or build one (ModelBuilder), run it as `ancfnet run` "
      "does (run), or step it\n"
      "and read its state between output steps (Simulation); read probes.csv (read_probes).\n"
      "Invalid input raises InputError with the command-line tool's message.";
  ancfnet::python::BindErrors(m);
  ancfnet::python::BindScene(m);
  ancfnet::python::BindBuilder(m);
  ancfnet::python::BindRun(m);
  ancfnet::python::BindSimulation(m);
}
