#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ancfnet/io/scene_loader.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace ancfnet::python {
namespace {

// The columns of the scene's probes.csv: time, then ProbeColumns of each probe.
std::vector<std::string> ProbeCsvColumns(const Scene& scene) {
  std::vector<std::string> columns = {"time"};
  for (const Probe& probe : scene.probes) {
    const std::vector<std::string> probe_columns = ProbeColumns(probe);
    columns.insert(columns.end(), probe_columns.begin(), probe_columns.end());
  }
  return columns;
}

}  // namespace

void BindScene(py::module_& m) {
  py::class_<Scene, std::shared_ptr<Scene>>(
      m, "Scene",
      "A scene: the model plus what to run and what to record, loaded by load_scene or\n"
      "parse_scene (the YAML format of docs/scene-format.md). Read-only once loaded.")
      .def_property_readonly(
          "source", [](const Scene& s) { return s.source; },
          "The file the scene came from, or the source name given to parse_scene.")
      .def_property_readonly(
          "analysis",
          [](const Scene& s) {
            return s.analysis.type == AnalysisType::kStatic ? "static" : "dynamic";
          },
          "The analysis the scene asks for: \"static\" or \"dynamic\".")
      .def_property_readonly(
          "end_time", [](const Scene& s) { return s.analysis.dynamics.end_time; },
          "End time of a dynamic analysis (s).")
      .def_property_readonly(
          "time_step", [](const Scene& s) { return s.analysis.dynamics.time_step; },
          "Nominal time step h of a dynamic analysis (s).")
      .def_property_readonly(
          "output_interval", [](const Scene& s) { return s.output.interval; },
          "Interval between output rows and frames (s of simulated time); 0 writes every step.")
      .def_property_readonly(
          "probe_columns", &ProbeCsvColumns,
          "Column names of the run's probes.csv: \"time\", then NAME.x/y/z, NAME.vx/vy/vz,\n"
          "NAME.kinetic, ... of each probe in the order of the scene.")
      .def("__repr__", [](const Scene& s) { return "<ancfnet.Scene from " + s.source + ">"; });

  m.def(
      "load_scene",
      [](const std::filesystem::path& file) { return std::make_shared<Scene>(LoadScene(file)); },
      py::arg("file"),
      "Reads and parses the scene file `file` (as `ancfnet run FILE --force`: no limit on the\n"
      "estimated work). Relative paths in the scene are taken from the file's directory.\n"
      "Raises InputError \"FILE: cannot open scene file\" when it cannot be read, and as\n"
      "parse_scene otherwise.");
  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& source_name,
         const std::filesystem::path& scene_directory) {
        return std::make_shared<Scene>(ParseScene(text, source_name, scene_directory));
      },
      py::arg("text"), py::arg("source_name") = "<string>", py::arg("scene_directory") = "",
      "Parses a scene from YAML text; `source_name` names it in messages and in Scene.source.\n"
      "Relative paths in the scene (a mesh target's `file`) are taken from `scene_directory`\n"
      "(the working directory when empty). Raises InputError with the one-line message\n"
      "\"SOURCE:LINE:COLUMN: what is wrong (key 'KEY')\" on malformed YAML, an unknown or\n"
      "missing key, a value of the wrong type or out of range, an unknown name, or a model the\n"
      "model builder refuses.");
}

}  // namespace ancfnet::python
