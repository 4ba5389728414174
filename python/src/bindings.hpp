#pragma once
/// @file The parts of the Python module `ancfnet`, each adding its classes and functions to the
/// module (module.cpp calls them in order).

#include <pybind11/pybind11.h>

namespace ancfnet::python {

/// ancfnet.InputError (a ValueError) and ancfnet.SolverError (a RuntimeError).
void BindErrors(pybind11::module_& m);
/// ancfnet.Scene, load_scene, parse_scene.
void BindScene(pybind11::module_& m);
/// ancfnet.Material, Section and ModelBuilder: a scene built in code.
void BindBuilder(pybind11::module_& m);
/// ancfnet.run and read_probes.
void BindRun(pybind11::module_& m);
/// ancfnet.Simulation: a run stepped from Python.
void BindSimulation(pybind11::module_& m);

}  // namespace ancfnet::python
