#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <string>

#include "ancfnet/io/contact_reader.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/model/builder_checks.hpp"
#include "ancfnet/model/material.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/net_builder.hpp"
#include "ancfnet/model/net_topology.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace ancfnet::python {
namespace {

Material MakeMaterial(double youngs_modulus, double density, double axial_damping_time,
                      double bending_damping_time) {
  RequirePositive(youngs_modulus, "youngs_modulus");
  RequirePositive(density, "density");
  RequireNonNegative(axial_damping_time, "axial_damping_time");
  RequireNonNegative(bending_damping_time, "bending_damping_time");
  return {.youngs_modulus = youngs_modulus,
          .density = density,
          .axial_damping_time = axial_damping_time,
          .bending_damping_time = bending_damping_time};
}

Section MakeCircle(double diameter) {
  RequirePositive(diameter, "diameter");
  return MakeCircleSection(diameter);
}

Section MakeRectangle(double width, double height) {
  RequirePositive(width, "width");
  RequirePositive(height, "height");
  return MakeRectangleSection(width, height);
}

// A cable as a scene file's `cables` item makes it: a rope's defaults when tension-only.
Index AddCable(ModelBuilder& builder, const std::string& name, const Vector3d& start,
               const Vector3d& end, int elements, const Material& material, const Section& section,
               bool tension_only, double breaking_force) {
  return builder.AddCable({.name = name,
                           .start = start,
                           .end = end,
                           .num_elements = elements,
                           .properties = tension_only ? MakeRopeProperties(material, section)
                                                      : MakeCableProperties(material, section),
                           .breaking_force = breaking_force});
}

Index AddRigidBody(ModelBuilder& builder, const std::string& name, double mass,
                   const Vector3d& inertia, const Vector3d& position, const Vector3d& velocity,
                   const Vector3d& angular_velocity) {
  return builder.AddRigidBody({.name = name,
                               .mass = mass,
                               .inertia = inertia.asDiagonal(),
                               .position = position,
                               .velocity = velocity,
                               .angular_velocity = angular_velocity});
}

// A square net as a scene file's `nets` item of type square makes it, ideal knots.
void AddSquareNet(ModelBuilder& builder, const std::string& name, double side, int meshes,
                  const Vector3d& center, const Material& material, const Section& section,
                  bool tension_only, int elements_per_thread, double knot_mass,
                  const Vector3d& velocity) {
  NetSpec spec;
  spec.name = name;
  spec.topology = MakeGridNet(
      {.side_u = side, .side_v = side, .meshes_u = meshes, .meshes_v = meshes, .center = center});
  spec.thread = MakeRopeProperties(material, section);
  spec.thread.tension_only = tension_only;
  spec.elements_per_thread = elements_per_thread;
  spec.knot_mass = knot_mass;
  spec.velocity = velocity;
  AddNet(builder, spec);
}

// A dict of scene-file keys as one line of JSON, which is YAML: what the scene file's readers
// read, so that defaults and messages are theirs.
std::string ToJson(const py::dict& keys) {
  return py::module_::import("json").attr("dumps")(keys).cast<std::string>();
}

// The scene of the builder's model with `settings` (a dict of the scene file's `analysis`,
// `output` and `probes`).
std::shared_ptr<Scene> BuildScene(const ModelBuilder& builder, const py::dict& settings,
                                  const std::string& source_name) {
  return std::make_shared<Scene>(
      ParseSceneSettings(builder.Build(), ToJson(settings), source_name));
}

}  // namespace

void BindBuilder(py::module_& m) {
  py::class_<Material>(m, "Material",
                       "Linear elastic material with optional Kelvin–Voigt damping, SI units: as\n"
                       "a scene file's `materials` item.")
      .def(py::init(&MakeMaterial), py::arg("youngs_modulus"), py::arg("density"),
           py::arg("axial_damping_time") = 0.0, py::arg("bending_damping_time") = 0.0,
           "E (Pa, > 0), ρ (kg/m³, > 0), the retardation times τ of σ = E (ε + τ ε̇) of the\n"
           "axial strain and of the curvature (s, ≥ 0). Raises InputError otherwise.")
      .def_readonly("youngs_modulus", &Material::youngs_modulus, "E (Pa)")
      .def_readonly("density", &Material::density, "ρ (kg/m³)");

  py::class_<Section>(m, "Section",
                      "Cross-section of a cable: area A, second moment I, drawing radius.")
      .def_static("circle", &MakeCircle, py::arg("diameter"),
                  "Solid circle of diameter d > 0 (m): A = π d²/4, I = π d⁴/64.")
      .def_static("rectangle", &MakeRectangle, py::arg("width"), py::arg("height"),
                  "Solid rectangle w × h (m, > 0): A = w h, I = w h³/12.")
      .def_readonly("area", &Section::area, "A (m²)")
      .def_readonly("second_moment", &Section::second_moment, "I (m⁴)");

  const Vector3d zero = Vector3d::Zero();
  py::class_<ModelBuilder>(
      m, "ModelBuilder",
      "Builds a model step by step with the C++ ModelBuilder, the API the scene loader uses: a\n"
      "model built here and the same model written as a scene file run alike, bit for bit.\n"
      "Every method checks its arguments and raises InputError with a one-line message naming\n"
      "the offending value. Vectors are 3 numbers (m, m/s, N, ...); points on a cable are a\n"
      "cable name and a fraction s ∈ [0, 1] of its reference length.")
      .def(py::init<>())
      .def("set_gravity", &ModelBuilder::SetGravity, py::arg("gravity"),
           "Gravitational acceleration (m/s²) acting on every cable, point mass and free body.")
      .def("add_cable", &AddCable, py::arg("name"), py::arg("start"), py::arg("end"),
           py::arg("elements"), py::arg("material"), py::arg("section"),
           py::arg("tension_only") = false,
           py::arg("breaking_force") = std::numeric_limits<double>::infinity(),
           "Adds a straight cable of `elements` ANCF elements (≥ 1) from `start` to `end` (m),\n"
           "unstrained, as a scene file's `cables` item; a tension-only cable is a rope (smooth\n"
           "rope law, simple bending). It fails at `breaking_force` (N, > 0; inf: never).\n"
           "Names are unique. Returns its index.")
      .def("add_point_mass", &ModelBuilder::AddPointMass, py::arg("name"), py::arg("mass"),
           py::arg("position"), py::arg("velocity") = zero,
           "Adds a point mass m ≥ 0 (kg) at `position` (m) moving at `velocity` (m/s); returns\n"
           "its index.")
      .def("fix_point_mass", &ModelBuilder::FixPointMass, py::arg("name"),
           "Fixes the position of a point mass.")
      .def("add_square_net", &AddSquareNet, py::arg("name"), py::arg("side"), py::arg("meshes"),
           py::arg("center"), py::arg("material"), py::arg("section"),
           py::arg("tension_only") = true, py::arg("elements_per_thread") = 1,
           py::arg("knot_mass") = 0.0, py::arg("velocity") = zero,
           "Adds a flat square net (model/net_builder.hpp, AddNet) as a scene file's `nets` item\n"
           "of type square: `side` (m, > 0) split into `meshes` × `meshes` meshes (≥ 1) in the\n"
           "x-y plane about `center`, its launch axis +z; ideal knots of `knot_mass` (kg, ≥ 0)\n"
           "named NAME.k<i> (row by row), rope threads NAME.t<j> (tension_only=False: elastic\n"
           "in compression too) of `elements_per_thread` elements (≥ 1), all moving at\n"
           "`velocity` (m/s).")
      .def(
          "add_rigid_body", &AddRigidBody, py::arg("name"), py::arg("mass"), py::arg("inertia"),
          py::arg("position"), py::arg("velocity") = zero, py::arg("angular_velocity") = zero,
          "Adds a free rigid body of mass m > 0 (kg) with principal moments of inertia\n"
          "[J1, J2, J3] (kg m², the triangle inequality holding) along the world axes, its centre\n"
          "of mass at `position` (m), moving at `velocity` (m/s) and turning at\n"
          "`angular_velocity` (rad/s, body axes); returns its index.")
      .def(
          "add_clamp",
          [](ModelBuilder& b, const std::string& cable, double s) {
            b.AddClamp({cable, s});
          },
          py::arg("cable"), py::arg("s"),
          "Fixes position and slope of the cable node at fraction s (which must be a node).")
      .def(
          "add_pin",
          [](ModelBuilder& b, const std::string& cable, double s) {
            b.AddPin({cable, s});
          },
          py::arg("cable"), py::arg("s"),
          "Fixes the position of the cable node at fraction s; the slope stays free.")
      .def(
          "add_point_force",
          [](ModelBuilder& b, const std::string& cable, double s, const Vector3d& force) {
            b.AddPointForce({cable, s}, force);
          },
          py::arg("cable"), py::arg("s"), py::arg("force"),
          "A force fixed in space (N) at the material point s of a cable (or at the point mass\n"
          "named `cable`, s ignored).")
      .def("add_distributed_load", &ModelBuilder::AddDistributedLoad, py::arg("cable"),
           py::arg("force_per_length"), "A load per unit reference length (N/m) on a cable.")
      .def("set_initial_velocity", &ModelBuilder::SetInitialVelocity, py::arg("cable"),
           py::arg("velocity"), py::arg("angular_velocity") = zero, py::arg("center") = zero,
           "Initial velocity of every point of a cable: v (m/s) + ω × (r − center), ω in rad/s.")
      .def(
          "set_contact",
          [](ModelBuilder& b, const py::dict& contact, const std::string& directory,
             const std::string& source_name) {
            ReadContactText(ToJson(contact), source_name, directory, &b);
          },
          py::arg("contact"), py::arg("directory") = ".", py::arg("source_name") = "<contact>",
          "The model's contact from `contact`, a dict of the scene file's `contact` section\n"
          "(docs/scene-format.md): law, friction, targets (planes, spheres, boxes, cylinders,\n"
          "capsules, meshes; a target on a body names a body added before), self_contact, ....\n"
          "A mesh's relative file is taken from `directory`. Raises InputError with the scene\n"
          "file's message (\"SOURCE_NAME:LINE:COLUMN: ... (key 'KEY')\").")
      .def(
          "build_scene", &BuildScene, py::arg("settings") = py::dict(),
          py::arg("source_name") = "<ModelBuilder>",
          "The finished model as a Scene to run (ancfnet.run, ancfnet.Simulation), with\n"
          "`settings` a dict of the scene file's keys \"analysis\", \"output\" and \"probes\"\n"
          "(docs/scene-format.md), e.g. {\"analysis\": {\"type\": \"dynamic\", \"time_step\":\n"
          "1e-3, \"end_time\": 1.0}, \"probes\": [{\"name\": \"tip\", \"quantity\": \"position\",\n"
          "\"at\": \"beam.end\"}]}; without \"analysis\", a static analysis. The builder stays\n"
          "usable. Raises InputError for a model without cables, masses or bodies, and with the\n"
          "scene file's message (\"SOURCE_NAME:LINE:COLUMN: ... (key 'KEY')\", the dict written\n"
          "as one line of JSON) for bad settings.");
}

}  // namespace ancfnet::python
