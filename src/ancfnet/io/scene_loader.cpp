#include "ancfnet/io/scene_loader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/fnv_hash.hpp"
#include "ancfnet/io/beam_reader.hpp"
#include "ancfnet/io/clearance_joint_reader.hpp"
#include "ancfnet/io/closest_name.hpp"
#include "ancfnet/io/connection_law_reader.hpp"
#include "ancfnet/io/contact_period_check.hpp"
#include "ancfnet/io/contact_reader.hpp"
#include "ancfnet/io/damping_reader.hpp"
#include "ancfnet/io/ideal_joint_reader.hpp"
#include "ancfnet/io/net_reader.hpp"
#include "ancfnet/io/rigid_body_reader.hpp"
#include "ancfnet/io/scene_library.hpp"
#include "ancfnet/io/scene_settings_reader.hpp"
#include "ancfnet/io/slender_cables.hpp"
#include "ancfnet/io/unique_names.hpp"
#include "ancfnet/io/yaml_document.hpp"
#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

// A bound far above any useful mesh that keeps a typo (elements: 2000000000) from exhausting the
// memory instead of being reported.
constexpr int kMaxElementsPerCable = 1'000'000;

Material ReadMaterial(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"youngs_modulus", "density", "axial_damping_time", "bending_damping_time",
                 "poisson_ratio", "shear_modulus"});
  ReadPoissonRatio(map);  // checked here; beams read it (io/beam_reader.hpp)
  Material material;
  material.youngs_modulus = map.Get("youngs_modulus").AsPositive();
  material.density = map.Get("density").AsPositive();
  if (auto v = map.Find("axial_damping_time")) material.axial_damping_time = v->AsNonNegative();
  if (auto v = map.Find("bending_damping_time")) material.bending_damping_time = v->AsNonNegative();
  return material;
}

Section ReadSection(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  const std::size_t shape = map.Get("shape").AsChoice({"circle", "rectangle", "general"});
  if (shape == 0) {
    map.CheckKeys({"shape", "diameter"});
    return MakeCircleSection(map.Get("diameter").AsPositive());
  }
  if (shape == 2) {
    // The beam keys are read by io/beam_reader.hpp.
    map.CheckKeys({"shape", "area", "second_moment", "radius", "second_moment_y",
                   "second_moment_z", "torsion_constant", "shear_correction"});
    Section section{.area = map.Get("area").AsPositive()};
    if (auto v = map.Find("second_moment")) section.second_moment = v->AsNonNegative();
    if (auto v = map.Find("radius")) section.radius = v->AsNonNegative();
    return section;
  }
  map.CheckKeys({"shape", "width", "height"});
  const double width = map.Get("width").AsPositive();
  return MakeRectangleSection(width, map.Get("height").AsPositive());
}

// A map NAME → definition, each read by `read`.
template <typename T, typename Read>
NamedList<T> ReadNamed(const YamlMap& scene, std::string_view key, Read read) {
  NamedList<T> list;
  const std::optional<YamlValue> value = scene.Find(key);
  if (!value) return list;
  const YamlMap map = value->AsMap();
  for (const YamlMap::Entry& entry : map.entries()) list.emplace_back(entry.key, read(entry.value));
  return list;
}

// POINT: "CABLE.start", "CABLE.end" (split at the last '.'), {cable: NAME, s: FRACTION}, or the
// name of a point mass in `point_masses`.
CablePointRef ReadPoint(const YamlValue& value, const std::vector<std::string>& point_masses = {}) {
  const std::string forms =
      std::string("a point CABLE.start, CABLE.end or {cable: NAME, s: FRACTION}") +
      (point_masses.empty() ? "" : ", or a point mass");
  if (value.IsMap()) {
    const YamlMap map = value.AsMap();
    map.CheckKeys({"cable", "s"});
    return {map.Get("cable").AsString(), map.Get("s").AsNumberIn(0.0, 1.0)};
  }
  if (!value.IsScalar()) value.FailExpected(forms);
  const std::string text = value.AsString();
  for (const std::string& name : point_masses)
    if (name == text) return {text, 0.0};
  const std::size_t dot = text.rfind('.');
  if (dot == std::string::npos || dot == 0) value.FailExpected(forms);
  const std::string end = text.substr(dot + 1);
  if (end != "start" && end != "end") value.FailExpected(forms);
  return {text.substr(0, dot), end == "start" ? 0.0 : 1.0};
}

// orbital_frame: {mean_motion: n} (rad/s) or {orbit_radius: a} (m, about the Earth: n = √(μ/a³)).
void ReadOrbitalFrame(const YamlValue& value, ModelBuilder* builder) {
  constexpr double kEarthGravitationalParameter = 3.986004418e14;  // μ (m³/s²), IERS 2010
  const YamlMap map = value.AsMap();
  map.CheckKeys({"mean_motion", "orbit_radius"});
  double mean_motion = 0.0;
  if (auto v = map.Find("mean_motion")) {
    if (map.Find("orbit_radius")) v->Fail("give either mean_motion or orbit_radius, not both");
    mean_motion = v->AsPositive();
  } else {
    const double radius = map.Get("orbit_radius").AsPositive();
    mean_motion = std::sqrt(kEarthGravitationalParameter / (radius * radius * radius));
  }
  value.Locate([&] { builder->SetOrbitalFrame(mean_motion); });
}

// point_masses: - {name, mass, position, velocity, fixed}
void ReadPointMass(const YamlValue& item, ModelBuilder* builder, std::vector<std::string>* names) {
  const YamlMap map = item.AsMap();
  map.CheckKeys({"name", "mass", "position", "velocity", "fixed"});
  const std::string name = map.Get("name").AsString();
  const double mass = map.Get("mass").AsPositive();
  const Vector3d position = map.Get("position").AsVector3();
  const Vector3d velocity =
      map.Find("velocity") ? map.Get("velocity").AsVector3() : Vector3d::Zero();
  item.Locate([&] { builder->AddPointMass(name, mass, position, velocity); });
  if (auto v = map.Find("fixed"); v && v->AsBool()) builder->FixPointMass(name);
  names->push_back(name);
}

// spring_dampers: - {name, from: POINT, to: POINT, law: LAW, natural_length, breaking_force}
void ReadSpringDamper(const YamlValue& item, const std::vector<std::string>& point_masses,
                      UniqueNames* names, ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  map.CheckKeys({"name", "from", "to", "law", "natural_length", "breaking_force"});
  const std::string name = names->Read(map.Get("name"));
  const CablePointRef from = ReadPoint(map.Get("from"), point_masses);
  const CablePointRef to = ReadPoint(map.Get("to"), point_masses);
  const ConnectionLaw law = ReadConnectionLaw(map.Get("law"));
  std::optional<double> natural_length;
  if (auto v = map.Find("natural_length")) natural_length = v->AsNonNegative();
  double breaking_force = std::numeric_limits<double>::infinity();
  if (auto v = map.Find("breaking_force")) breaking_force = v->AsPositive();
  item.Locate(
      [&] { builder->AddSpringDamper(name, from, to, law, natural_length, breaking_force); });
}

// initial_velocity: [vx, vy, vz], or {linear: v, angular: ω, center: c} for v + ω × (r − c).
void ReadInitialVelocity(const YamlValue& value, const std::string& cable, ModelBuilder* builder) {
  Vector3d linear = Vector3d::Zero(), angular = Vector3d::Zero(), center = Vector3d::Zero();
  if (value.IsSequence()) {
    linear = value.AsVector3();
  } else if (value.IsMap()) {
    const YamlMap map = value.AsMap();
    map.CheckKeys({"linear", "angular", "center"});
    if (auto v = map.Find("linear")) linear = v->AsVector3();
    if (auto v = map.Find("angular")) angular = v->AsVector3();
    if (auto v = map.Find("center")) center = v->AsVector3();
  } else {
    value.FailExpected("a velocity [vx, vy, vz] or a map {linear, angular, center}");
  }
  value.Locate([&] { builder->SetInitialVelocity(cable, linear, angular, center); });
}

void ReadCable(const YamlValue& item, const Library& library, ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  map.CheckKeys({"name", "start", "end", "elements", "material", "section", "tension_only",
                 "rope_smoothing_strain", "bending", "axial_gauss_points", "bending_gauss_points",
                 "initial_velocity", "breaking_force", "element", "orientation", "continues"});
  CableSpec spec;
  spec.name = map.Get("name").AsString();
  spec.start = map.Get("start").AsVector3();
  spec.end = map.Get("end").AsVector3();
  const YamlValue elements = map.Get("elements");
  spec.num_elements = elements.AsInt(1);
  if (spec.num_elements > kMaxElementsPerCable)
    elements.Fail(fmt::format("too many elements: at most {} per cable, got {}",
                              kMaxElementsPerCable, spec.num_elements));
  const Material& material =
      Lookup(library.materials, map.Get("material"), "material", "known materials");
  const Section& section =
      Lookup(library.sections, map.Get("section"), "section", "known sections");
  CheckSlenderCable(section, (spec.end - spec.start).norm(), fmt::format("cable '{}'", spec.name),
                    map.Get("section"));
  CableProperties& properties = spec.properties;
  // A tension-only cable is a rope and takes the rope's defaults (smoothing, simple bending).
  const std::optional<YamlValue> tension_only = map.Find("tension_only");
  properties = tension_only && tension_only->AsBool() ? MakeRopeProperties(material, section)
                                                      : MakeCableProperties(material, section);
  if (auto v = map.Find("rope_smoothing_strain"))
    properties.rope_smoothing_strain = v->AsNumberIn(0.0, 0.1);
  if (auto v = map.Find("bending")) properties.bending_model = ReadBendingModel(*v);
  if (auto v = map.Find("axial_gauss_points")) properties.axial_gauss_points = v->AsInt(1, 8);
  if (auto v = map.Find("bending_gauss_points")) properties.bending_gauss_points = v->AsInt(1, 8);
  if (auto v = map.Find("breaking_force")) spec.breaking_force = v->AsPositive();
  spec.beam = ReadBeamCable(map, spec.end - spec.start, library);
  if (auto v = map.Find("continues")) spec.start_cable = v->AsString();
  item.Locate([&] { builder->AddCable(spec); });
  if (auto v = map.Find("initial_velocity")) ReadInitialVelocity(*v, spec.name, builder);
}

// angle: {type: constant_rate, rate: Ω} or {type: spin_up, rate: Ω, time: T} (rad/s, s).
AngleProfile ReadAngleProfile(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  AngleProfile angle;
  const bool spin_up = map.Get("type").AsChoice({"constant_rate", "spin_up"}) == 1;
  map.CheckKeys(spin_up ? std::vector<std::string_view>{"type", "rate", "time"}
                        : std::vector<std::string_view>{"type", "rate"});
  angle.rate = map.Get("rate").AsNumberIn(-1e6, 1e6);
  if (spin_up) {
    angle.kind = AngleProfile::Kind::kSpinUp;
    angle.ramp_time = map.Get("time").AsPositive();
  }
  return angle;
}

void ReadConstraint(const YamlValue& item, ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  const std::size_t type = map.Get("type").AsChoice({"clamp", "pin", "fix", "rotating_clamp"});
  if (type == 2) {
    map.CheckKeys({"type", "at", "coordinates"});
  } else if (type == 3) {
    map.CheckKeys({"type", "at", "axis", "center", "angle"});
  } else {
    map.CheckKeys({"type", "at"});
  }
  const YamlValue at = map.Get("at");
  const CablePointRef point = ReadPoint(at);
  if (type == 0) return at.Locate([&] { builder->AddClamp(point); });
  if (type == 3) {
    const Vector3d axis = map.Find("axis") ? map.Get("axis").AsVector3() : Vector3d::UnitZ();
    const Vector3d center = map.Find("center") ? map.Get("center").AsVector3() : Vector3d::Zero();
    const AngleProfile angle = ReadAngleProfile(map.Get("angle"));
    return item.Locate([&] { builder->AddRotatingClamp(point, axis, center, angle); });
  }
  if (type == 1) return at.Locate([&] { builder->AddPin(point); });
  CoordinateMask mask{};
  for (const YamlValue& coordinate : map.Get("coordinates").AsList(/*non_empty=*/true))
    mask[coordinate.AsChoice({"x", "y", "z", "dx", "dy", "dz"})] = true;
  at.Locate([&] { builder->FixCoordinates(point, mask); });
}

void ReadLoad(const YamlValue& item, ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  const std::size_t type = map.Get("type").AsChoice({"point_force", "point_moment", "distributed"});
  if (type == 0) {
    map.CheckKeys({"type", "at", "force"});
    const YamlValue at = map.Get("at");
    const CablePointRef point = ReadPoint(at);
    const Vector3d force = map.Get("force").AsVector3();
    at.Locate([&] { builder->AddPointForce(point, force); });
  } else if (type == 1) {
    map.CheckKeys({"type", "at", "moment"});
    const YamlValue at = map.Get("at");
    const CablePointRef point = ReadPoint(at);
    const Vector3d moment = map.Get("moment").AsVector3();
    at.Locate([&] { builder->AddPointMoment(point, moment); });
  } else {
    map.CheckKeys({"type", "cable", "force_per_length"});
    const YamlValue cable = map.Get("cable");
    const std::string name = cable.AsString();
    const Vector3d force_per_length = map.Get("force_per_length").AsVector3();
    cable.Locate([&] { builder->AddDistributedLoad(name, force_per_length); });
  }
}

// Index of the item of `items` (each with a `name`) that `value` names; fails at `value`, with
// the closest name, when there is none.
template <class Items>
Index ReadNamedIndex(const YamlValue& value, const Items& items, std::string_view what,
                     std::string_view label) {
  const std::string name = value.AsString();
  std::vector<std::string_view> names;
  Index found = -1;
  for (std::size_t i = 0; i < items.size(); ++i) {
    names.push_back(items[i].name);
    if (items[i].name == name) found = static_cast<Index>(i);
  }
  if (found < 0)
    value.Fail(fmt::format("no {} named '{}'{}", what, name, SuggestName(name, names, label)));
  return found;
}

// A capture probe's net, its initial mouth area, and its target: a bounded contact target.
void ReadCaptureProbe(const YamlMap& map, const Model& model, Probe* probe) {
  const YamlValue net = map.Get("net");
  probe->net = ReadNamedIndex(net, model.nets(), "net", "nets");
  if (!model.contact().enabled())
    map.Get("quantity").Fail("a capture probe needs contact targets (a `contact:` section)");
  const YamlValue target = map.Get("target");
  probe->target = ReadNamedIndex(target, model.contact().targets, "contact target", "targets");
  if (model.contact().targets[probe->target].kind == ContactTarget::Kind::kPlane)
    target.Fail(
        "a capture probe needs a bounded target (sphere, box, cylinder, capsule, mesh), "
        "not a plane");
  probe->reference_area =
      CalcNetMouthArea(model, model.nets()[probe->net], model.initial_positions());
}

// Probes are read once the model is built: their points resolve to material points.
std::vector<Probe> ReadProbes(const YamlValue& list, const Model& model,
                              const std::vector<std::string>& point_masses) {
  std::vector<Probe> probes;
  UniqueNames names("probes");
  for (const YamlValue& item : list.AsList()) {
    const YamlMap map = item.AsMap();
    Probe probe;
    probe.quantity =
        map.Get("quantity")
            .AsEnum<ProbeQuantity>({{"position", ProbeQuantity::kPosition},
                                    {"velocity", ProbeQuantity::kVelocity},
                                    {"energy", ProbeQuantity::kEnergy},
                                    {"mouth_area", ProbeQuantity::kMouthArea},
                                    {"centroid", ProbeQuantity::kCentroid},
                                    {"centroid_velocity", ProbeQuantity::kCentroidVelocity},
                                    {"distance", ProbeQuantity::kDistance},
                                    {"max_tension", ProbeQuantity::kMaxTension},
                                    {"link_force", ProbeQuantity::kLinkForce},
                                    {"body_pose", ProbeQuantity::kBodyPose},
                                    {"body_velocity", ProbeQuantity::kBodyVelocity},
                                    {"contact", ProbeQuantity::kContact},
                                    {"clearance_joint", ProbeQuantity::kClearanceJoint},
                                    {"joint_reaction", ProbeQuantity::kJointReaction},
                                    {"capture", ProbeQuantity::kCapture}});
    const bool whole_system = probe.quantity == ProbeQuantity::kEnergy;
    const bool of_a_point =
        probe.quantity == ProbeQuantity::kPosition || probe.quantity == ProbeQuantity::kVelocity;
    if (auto at = map.Find("at"); at && whole_system)
      at->Fail("an energy probe reads the whole system and takes no point");
    const bool of_a_link = probe.quantity == ProbeQuantity::kLinkForce;
    const bool of_a_body = probe.quantity == ProbeQuantity::kBodyPose ||
                           probe.quantity == ProbeQuantity::kBodyVelocity;
    const bool of_contacts = probe.quantity == ProbeQuantity::kContact;
    const bool of_a_capture = probe.quantity == ProbeQuantity::kCapture;
    const bool of_a_joint = probe.quantity == ProbeQuantity::kClearanceJoint ||
                            probe.quantity == ProbeQuantity::kJointReaction;
    if (of_a_body)
      map.CheckKeys({"name", "quantity", "body"});
    else if (of_a_point)
      map.CheckKeys({"name", "quantity", "at"});
    else if (whole_system)
      map.CheckKeys({"name", "quantity"});
    else if (of_a_link)
      map.CheckKeys({"name", "quantity", "link"});
    else if (of_contacts)
      map.CheckKeys({"name", "quantity", "target"});
    else if (of_a_joint)
      map.CheckKeys({"name", "quantity", "joint"});
    else if (of_a_capture)
      map.CheckKeys({"name", "quantity", "net", "target"});
    else
      map.CheckKeys({"name", "quantity", "net"});
    probe.name = names.Read(map.Get("name"));
    if (of_a_point) {
      const YamlValue at = map.Get("at");
      const CablePointRef point = ReadPoint(at, point_masses);
      probe.point = at.Locate([&] { return model.LocatePoint(point.cable, point.s); });
    } else if (of_a_body) {
      probe.body = ReadNamedIndex(map.Get("body"), model.rigid_bodies(), "rigid body", "bodies");
    } else if (of_a_link) {
      probe.link =
          ReadNamedIndex(map.Get("link"), model.links(), "spring-damper", "spring-dampers");
    } else if (of_contacts) {
      if (!model.contact().enabled())
        map.Get("quantity").Fail("a contact probe needs contact targets (a `contact:` section)");
      if (auto target = map.Find("target"))
        probe.target =
            ReadNamedIndex(*target, model.contact().targets, "contact target", "targets");
    } else if (probe.quantity == ProbeQuantity::kClearanceJoint) {
      probe.joint =
          ReadNamedIndex(map.Get("joint"), model.clearance_joints(), "clearance joint", "joints");
    } else if (of_a_joint) {
      probe.joint = ReadNamedIndex(map.Get("joint"), model.ideal_joints(), "ideal joint", "joints");
    } else if (of_a_capture) {
      ReadCaptureProbe(map, model, &probe);
    } else if (!whole_system) {
      probe.net = ReadNamedIndex(map.Get("net"), model.nets(), "net", "nets");
      probe.reference = CalcNetCentroid(model, model.nets()[probe.net], model.initial_positions());
    }
    probes.push_back(std::move(probe));
  }
  return probes;
}

Scene ReadScene(const YamlValue& root, const std::filesystem::path& scene_directory,
                const LoadOptions& options) {
  if (root.node().IsNull())
    root.FailPlain("the scene is empty (expected a map with materials, sections and cables)");
  const YamlMap scene = root.AsMap();
  scene.CheckKeys({"gravity", "orbital_frame", "materials", "sections", "point_masses", "nets",
                   "cables", "bodies", "attachments", "joints", "spring_dampers", "constraints",
                   "loads", "damping", "contact", "probes", "analysis", "output"});
  ModelBuilder builder;
  if (auto v = scene.Find("gravity")) {
    const Vector3d gravity = v->AsVector3();
    v->Locate([&] { builder.SetGravity(gravity); });
  }
  if (auto v = scene.Find("orbital_frame")) ReadOrbitalFrame(*v, &builder);
  Library library;
  library.materials = ReadNamed<Material>(scene, "materials", ReadMaterial);
  library.sections = ReadNamed<Section>(scene, "sections", ReadSection);
  const auto as_written = [](const YamlValue& value) { return value; };
  library.material_values = ReadNamed<YamlValue>(scene, "materials", as_written);
  library.section_values = ReadNamed<YamlValue>(scene, "sections", as_written);
  std::vector<std::string> point_masses;
  if (auto v = scene.Find("point_masses"))
    for (const YamlValue& item : v->AsList()) ReadPointMass(item, &builder, &point_masses);
  if (auto v = scene.Find("nets"))
    for (const YamlValue& item : v->AsList()) ReadNet(item, library, &builder, &point_masses);
  // Cables are required unless the scene has point masses (or nets) or rigid bodies.
  const bool cables_required = point_masses.empty() && !scene.Find("bodies");
  if (auto v = scene.Find("cables"); v || cables_required)
    for (const YamlValue& item : scene.Get("cables").AsList(/*non_empty=*/cables_required))
      ReadCable(item, library, &builder);
  if (auto v = scene.Find("bodies"))
    for (const YamlValue& item : v->AsList()) ReadRigidBody(item, &builder);
  // The analysis settings first: a fixed attachment's penalty stiffness depends on the step.
  Scene result;
  if (auto v = scene.Find("analysis")) result.analysis = ReadAnalysisSettings(*v);
  if (auto v = scene.Find("attachments"))
    for (const YamlValue& item : v->AsList())
      ReadBodyAttachment(
          item, [&](const YamlValue& point) { return ReadPoint(point, point_masses); },
          result.analysis.dynamics.time_step, &builder);
  if (auto v = scene.Find("joints"))
    for (const YamlValue& item : v->AsList()) {
      const auto read_point = [&](const YamlValue& point) { return ReadPoint(point, point_masses); };
      const auto type = item.IsMap() ? item.AsMap().Find("type") : std::nullopt;
      // One list of the types for the message of a misspelt one.
      if (type)
        type->AsChoice({"spherical", "revolute", "weld", "line", "prismatic",
                        "revolute_clearance", "spherical_clearance"});
      if (type && IsIdealJointType(type->AsString()))
        ReadIdealJoint(item, read_point, &builder);
      else
        ReadClearanceJoint(item, read_point, &builder);
    }
  if (auto v = scene.Find("spring_dampers")) {
    UniqueNames names("spring-dampers");
    for (const YamlValue& item : v->AsList()) ReadSpringDamper(item, point_masses, &names, &builder);
  }
  if (auto v = scene.Find("constraints"))
    for (const YamlValue& item : v->AsList()) ReadConstraint(item, &builder);
  if (auto v = scene.Find("loads"))
    for (const YamlValue& item : v->AsList()) ReadLoad(item, &builder);
  if (auto v = scene.Find("damping")) ReadDamping(*v, &builder);
  if (auto v = scene.Find("contact")) ReadContact(*v, scene_directory, &builder);

  result.model = root.Locate([&] { return builder.Build(); });
  if (auto v = scene.Find("contact");
      v && result.analysis.type == AnalysisType::kDynamic && v->AsMap().Find("law"))
    if (auto k = v->AsMap().Get("law").AsMap().Find("stiffness"))
      CheckContactPeriod(result.model, result.analysis.dynamics.time_step, *k);
  if (auto v = scene.Find("analysis");
      v && options.max_unknown_steps > 0.0 && result.analysis.type == AnalysisType::kDynamic)
    CheckRunWork(result.analysis.dynamics, result.model.num_dofs(), options.max_unknown_steps, *v);
  if (auto v = scene.Find("probes")) result.probes = ReadProbes(*v, result.model, point_masses);
  if (auto v = scene.Find("output")) result.output = ReadOutputSettings(*v);
  result.source = root.source();
  return result;
}

}  // namespace

Scene ParseScene(const std::string& yaml_text, const std::string& source_name,
                 const std::filesystem::path& scene_directory, const LoadOptions& options) {
  const YAML::Node root = ParseYamlDocument(yaml_text, source_name, "scene");
  try {
    Scene scene = ReadScene(YamlValue::Root(root, source_name), scene_directory, options);
    scene.text_hash = Fnv1aHash(yaml_text.data(), yaml_text.size());
    return scene;
  } catch (const YAML::Exception& error) {  // a node access the reader did not foresee
    ThrowYamlError(source_name, error);
  }
}

Scene ParseSceneSettings(Model model, const std::string& yaml_text,
                         const std::string& source_name) {
  const YAML::Node root = ParseYamlDocument(yaml_text, source_name, "settings");
  try {
    Scene scene;
    scene.model = std::move(model);
    scene.source = source_name;
    if (root.IsNull()) return scene;
    const YamlMap map = YamlValue::Root(root, source_name).AsMap();
    map.CheckKeys({"analysis", "output", "probes"});
    if (auto v = map.Find("analysis")) scene.analysis = ReadAnalysisSettings(*v);
    std::vector<std::string> point_masses;
    for (const PointMass& mass : scene.model.point_masses()) point_masses.push_back(mass.name);
    if (auto v = map.Find("probes")) scene.probes = ReadProbes(*v, scene.model, point_masses);
    if (auto v = map.Find("output")) scene.output = ReadOutputSettings(*v);
    return scene;
  } catch (const YAML::Exception& error) {
    ThrowYamlError(source_name, error);
  }
}

Scene LoadScene(const std::filesystem::path& file, const LoadOptions& options) {
  return ParseScene(ReadInputFile(file, "scene"), file.string(), file.parent_path(), options);
}

}  // namespace ancfnet
