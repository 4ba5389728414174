#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <utility>

#include "array_view.hpp"
#include "bindings.hpp"
#include "results.hpp"
#include "stepped_run.hpp"

namespace py = pybind11;

namespace ancfnet::python {
namespace {

// A read-only view of the vector `member` of the state of the SteppedRun `self`.
py::array_t<double> StateView(const py::object& self, VectorXd State::*member) {
  const VectorXd& vector = self.cast<const SteppedRun&>().state().*member;
  return ReadOnlyView(vector.data(), vector.size(), self);
}

}  // namespace

void BindSimulation(py::module_& m) {
  py::class_<SteppedRun>(
      m, "Simulation",
      "A run of a scene stepped from Python: the very run of ancfnet.run (same steps, same\n"
      "outputs in `output_dir`, bit for bit), stopped at each output step (t = 0 and every\n"
      "output time of the scene) so that the state can be read in between. q and v are\n"
      "read-only numpy views of the state, without a copy: they keep showing the latest output\n"
      "step after each advance.")
      .def(py::init([](std::shared_ptr<Scene> scene, std::filesystem::path output_dir) {
             return std::make_unique<SteppedRun>(std::move(scene), std::move(output_dir));
           }),
           py::arg("scene"), py::arg("output_dir"))
      .def(
          "advance",
          [](SteppedRun& run) {
            py::gil_scoped_release release;
            return run.Advance();
          },
          "Runs to the next output step (the first call stops at the initial state) and\n"
          "returns True, or returns False once the run has ended (summary is then set).\n"
          "Raises InputError when the output directory cannot be written.")
      .def(
          "run_to_end",
          [](SteppedRun& run) {
            {
              py::gil_scoped_release release;
              while (run.Advance()) {
              }
            }
            return ReadSummary(run.output_dir());
          },
          "Runs the remaining steps and returns summary.json as a dict (see ancfnet.run).")
      .def_property_readonly(
          "t", [](const SteppedRun& run) { return run.state().t; },
          "Time of the current output step (s; the load factor of a static analysis).")
      .def_property_readonly(
          "q", [](const py::object& self) { return StateView(self, &State::q); },
          "Generalised coordinates of every coordinate of the model, fixed ones included\n"
          "(positions in m, slopes dimensionless), as a read-only view.")
      .def_property_readonly(
          "v", [](const py::object& self) { return StateView(self, &State::v); },
          "Generalised velocities v = dq/dt (m/s, 1/s), as a read-only view.")
      .def_property_readonly("finished", &SteppedRun::finished, "True once the run has ended.")
      .def_property_readonly(
          "summary",
          [](SteppedRun& run) -> py::object {
            if (!run.summary()) return py::none();
            return ReadSummary(run.output_dir());
          },
          "summary.json as a dict once the run has ended, None before.");
}

}  // namespace ancfnet::python
