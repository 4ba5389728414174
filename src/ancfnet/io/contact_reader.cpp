#include "ancfnet/io/contact_reader.hpp"

#include <memory>
#include <numbers>
#include <utility>

#include "ancfnet/contact/mesh/triangle_mesh.hpp"
#include "ancfnet/io/unique_names.hpp"
#include "ancfnet/io/yaml_document.hpp"

namespace ancfnet {

NormalLaw ReadNormalLaw(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  // Without a type: Carvalho–Martins, whose achieved restitution stays closest to its input.
  constexpr std::size_t kCarvalhoMartins = 6;
  const std::size_t type =
      map.Find("type")
          ? map.Get("type").AsChoice({"linear", "hertz", "hunt_crossley", "lankarani_nikravesh",
                                      "flores", "gonthier", "carvalho_martins"})
          : kCarvalhoMartins;
  if (type == 0) {
    map.CheckKeys({"type", "stiffness", "damping"});
    const double damping = map.Find("damping") ? map.Get("damping").AsNonNegative() : 0.0;
    return value.Locate(
        [&] { return MakeLinearContactLaw(map.Get("stiffness").AsPositive(), damping); });
  }
  // Hertz's 3/2 for smooth bodies, 1 to about 2 for others; outside [1, 3] no contact law.
  const double exponent = map.Find("exponent") ? map.Get("exponent").AsNumberIn(1.0, 3.0) : 1.5;
  if (type == 1) {
    map.CheckKeys({"type", "stiffness", "exponent"});
    return value.Locate(
        [&] { return MakeHertzContactLaw(map.Get("stiffness").AsPositive(), exponent); });
  }
  map.CheckKeys({"type", "stiffness", "restitution", "exponent", "min_approach_speed"});
  constexpr NormalLawKind kKinds[] = {NormalLawKind::kHuntCrossley,
                                      NormalLawKind::kLankaraniNikravesh, NormalLawKind::kFlores,
                                      NormalLawKind::kGonthier, NormalLawKind::kCarvalhoMartins};
  const double speed =
      map.Find("min_approach_speed") ? map.Get("min_approach_speed").AsPositive() : 1e-3;
  const double stiffness = map.Get("stiffness").AsPositive();
  const double restitution = map.Get("restitution").AsNumberIn(1e-6, 1.0);
  return value.Locate([&] {
    return MakeDissipativeContactLaw(kKinds[type - 2], stiffness, restitution, exponent, speed);
  });
}

FrictionLaw ReadFriction(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  const std::size_t type = map.Get("type").AsChoice({"tanh", "ambrosio", "lugre"});
  const auto number_or = [&](const char* key, double fallback, bool positive) {
    if (!map.Find(key)) return fallback;
    return positive ? map.Get(key).AsPositive() : map.Get(key).AsNonNegative();
  };
  if (type == 1) {
    map.CheckKeys({"type", "coefficient", "ramp_start_speed", "ramp_end_speed"});
    const double coefficient = map.Get("coefficient").AsNonNegative();
    const double start = number_or("ramp_start_speed", 1e-4, false);
    const double end = number_or("ramp_end_speed", 1e-3, true);
    return value.Locate([&] { return MakeAmbrosioFriction(coefficient, start, end); });
  }
  if (type == 0) {
    map.CheckKeys({"type", "static", "kinetic", "regularization_speed", "stribeck_speed"});
  } else {
    map.CheckKeys({"type", "static", "kinetic", "stribeck_speed", "bristle_stiffness",
                   "bristle_damping", "viscous_damping"});
  }
  const double kinetic =
      type == 0 ? map.Get("kinetic").AsNonNegative() : map.Get("kinetic").AsPositive();
  const double statics = number_or("static", kinetic, false);
  const double stribeck = number_or("stribeck_speed", 1e-2, true);
  if (type == 0) {
    const double regularization = number_or("regularization_speed", 1e-3, true);
    return value.Locate(
        [&] { return MakeTanhFriction(statics, kinetic, regularization, stribeck); });
  }
  const double sigma0 = map.Get("bristle_stiffness").AsPositive();
  const double sigma1 = number_or("bristle_damping", 0.0, false);
  const double sigma2 = number_or("viscous_damping", 0.0, false);
  return value.Locate(
      [&] { return MakeLuGreFriction(statics, kinetic, stribeck, sigma0, sigma1, sigma2); });
}

namespace {

// A unit axis (default e_z when absent); a zero vector is refused.
Vector3d ReadAxis(const YamlMap& map) {
  if (!map.Find("axis")) return Vector3d::UnitZ();
  const Vector3d axis = map.Get("axis").AsVector3();
  if (!(axis.norm() > 0.0)) map.Get("axis").Fail("the axis must be a non-zero vector");
  return axis.normalized();
}

// rotation: {axis: [x, y, z], angle: degrees}, R = exp(θ [a]×).
Matrix3d ReadRotation(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"axis", "angle"});
  const double angle = map.Get("angle").AsNumber() * std::numbers::pi / 180.0;
  return Eigen::AngleAxisd(angle, ReadAxis(map)).toRotationMatrix();
}

// The mesh file (relative to the scene's directory), scaled, rotated and moved into the world.
std::shared_ptr<const MeshBvh> ReadMesh(const YamlMap& map,
                                        const std::filesystem::path& scene_directory) {
  const YamlValue file = map.Get("file");
  const std::filesystem::path path = scene_directory / file.AsString();
  const double scale = map.Find("scale") ? map.Get("scale").AsPositive() : 1.0;
  const Vector3d position =
      map.Find("position") ? map.Get("position").AsVector3() : Vector3d::Zero();
  const Matrix3d rotation =
      map.Find("rotation") ? ReadRotation(map.Get("rotation")) : Matrix3d::Identity();
  TriangleMesh mesh = file.Locate([&] { return LoadTriangleMesh(path); });
  TransformTriangleMesh(scale, rotation, position, &mesh);
  return std::make_shared<const MeshBvh>(std::move(mesh));
}

ContactTarget ReadTarget(const YamlValue& value, const std::filesystem::path& scene_directory,
                         UniqueNames* names) {
  const YamlMap map = value.AsMap();
  ContactTarget t;
  const std::size_t type =
      map.Get("type").AsChoice({"plane", "sphere", "box", "cylinder", "capsule", "mesh"});
  // An unnamed target is called "target" (so only one may be unnamed).
  t.name = map.Find("name") ? names->Read(map.Get("name")) : names->Claim(value, "target");
  // Carried by a rigid body: the geometry is in the body's frame.
  if (auto body = map.Find("body")) t.body_name = body->AsString();
  switch (type) {
    case 0:
      map.CheckKeys({"name", "type", "body", "point", "normal"});
      t.kind = ContactTarget::Kind::kPlane;
      t.point = map.Get("point").AsVector3();
      t.normal = map.Get("normal").AsVector3();
      if (!(t.normal.norm() > 0.0)) map.Get("normal").Fail("the normal must be a non-zero vector");
      t.normal.normalize();
      break;
    case 1:
      map.CheckKeys({"name", "type", "body", "center", "radius"});
      t.kind = ContactTarget::Kind::kSphere;
      t.point = map.Get("center").AsVector3();
      t.radius = map.Get("radius").AsPositive();
      break;
    case 2:
      map.CheckKeys({"name", "type", "body", "center", "half_extents"});
      t.kind = ContactTarget::Kind::kBox;
      t.point = map.Get("center").AsVector3();
      t.half_extents = map.Get("half_extents").AsVector3();
      if (!(t.half_extents.minCoeff() > 0.0))
        map.Get("half_extents").Fail("half extents must be > 0");
      break;
    case 3:
    case 4: {
      // A cylinder and a capsule share their keys; a capsule's axis may have zero length.
      map.CheckKeys({"name", "type", "body", "center", "axis", "radius", "half_length"});
      const bool capsule = type == 4;
      t.kind = capsule ? ContactTarget::Kind::kCapsule : ContactTarget::Kind::kCylinder;
      t.point = map.Get("center").AsVector3();
      t.normal = ReadAxis(map);
      t.radius = map.Get("radius").AsPositive();
      const YamlValue half_length = map.Get("half_length");
      t.half_length = capsule ? half_length.AsNonNegative() : half_length.AsPositive();
      break;
    }
    default:
      map.CheckKeys({"name", "type", "body", "file", "scale", "position", "rotation"});
      t.kind = ContactTarget::Kind::kMesh;
      t.mesh = ReadMesh(map, scene_directory);
      break;
  }
  return t;
}

}  // namespace

void ReadContact(const YamlValue& value, const std::filesystem::path& scene_directory,
                 ModelBuilder* builder) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"law", "friction", "cable_radius", "point_mass_radius", "points_per_element",
                 "targets", "target_geometry", "self_contact", "self_contact_geometry",
                 "capsules_per_element", "penetration_increment"});
  ContactSpec spec;
  spec.normal = ReadNormalLaw(map.Get("law"));
  if (auto v = map.Find("friction")) spec.friction = ReadFriction(*v);
  if (auto v = map.Find("cable_radius")) spec.cable_radius = v->AsPositive();
  if (auto v = map.Find("point_mass_radius")) spec.point_mass_radius = v->AsNonNegative();
  if (auto v = map.Find("points_per_element")) spec.points_per_element = v->AsInt(1, 1000);
  if (auto v = map.Find("penetration_increment")) spec.penetration_increment = v->AsNonNegative();
  if (auto v = map.Find("self_contact")) spec.self_contact = v->AsBool();
  if (auto v = map.Find("self_contact_geometry"))
    spec.self_geometry = v->AsChoice({"capsules", "spheres"}) == 0
                             ? ContactSpec::SelfGeometry::kCapsules
                             : ContactSpec::SelfGeometry::kSpheres;
  if (auto v = map.Find("target_geometry"))
    spec.target_geometry = v->AsChoice({"spheres", "capsules"}) == 0
                               ? ContactSpec::TargetGeometry::kSpheres
                               : ContactSpec::TargetGeometry::kCapsules;
  if (auto v = map.Find("capsules_per_element")) spec.capsules_per_element = v->AsInt(1, 1000);
  // Targets may be left out when only the threads touch each other.
  UniqueNames target_names("contact targets");
  if (!spec.self_contact || map.Find("targets"))
    for (const YamlValue& target : map.Get("targets").AsList(true))
      spec.targets.push_back(ReadTarget(target, scene_directory, &target_names));
  value.Locate([&] { builder->SetContact(spec); });
}

void ReadContactText(const std::string& yaml_text, const std::string& source_name,
                     const std::filesystem::path& directory, ModelBuilder* builder) {
  const YAML::Node root = ParseYamlDocument(yaml_text, source_name, "contact");
  try {
    ReadContact(YamlValue::Root(root, source_name), directory, builder);
  } catch (const YAML::Exception& error) {  // a node access the reader did not foresee
    ThrowYamlError(source_name, error);
  }
}

}  // namespace ancfnet
