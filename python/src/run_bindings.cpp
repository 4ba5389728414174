#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "ancfnet/run/run_scene.hpp"
#include "bindings.hpp"
#include "results.hpp"

namespace py = pybind11;

namespace ancfnet::python {

void BindRun(py::module_& m) {
  m.def(
      "run",
      [](const Scene& scene, const std::filesystem::path& output_dir) {
        RunOptions options;
        options.output_dir = output_dir;
        options.show_progress = false;
        {
          py::gil_scoped_release release;
          RunScene(scene, options);
        }
        return ReadSummary(output_dir);
      },
      py::arg("scene"), py::arg("output_dir"),
      "Runs the analysis of `scene` as `ancfnet run` does and writes into `output_dir`:\n"
      "probes.csv (one row per output step), cables_NNNNNN.vtp frames with cables.pvd, contact\n"
      "frames with contacts.pvd when the scene has contact targets, and summary.json, which is\n"
      "returned as a dict. A solver failure does not raise: the outputs written so far are kept\n"
      "and the summary's \"status\" is \"failed\" with the time and the reason in \"message\".\n"
      "Raises InputError when the directory cannot be written. The Python interpreter is free\n"
      "for other threads while it runs.");
  m.def("read_probes", &ReadProbes, py::arg("path"),
        "Reads a probes.csv file (as run writes it): a dict from each column name (\"time\",\n"
        "\"tip.x\", ...) to a read-only 1-D numpy array of its values in SI units, one per output\n"
        "step. Raises InputError naming the file when it cannot be read or is malformed.");
}

}  // namespace ancfnet::python
