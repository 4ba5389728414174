#include "ancfnet/io/rigid_body_reader.hpp"

#include <Eigen/Geometry>

namespace ancfnet {
namespace {

// [[a, b, c], [d, e, f], [g, h, i]], row by row.
Matrix3d ReadMatrix3(const YamlValue& value) {
  const std::vector<YamlValue> rows = value.AsList();
  if (rows.size() != 3) value.FailExpected("a 3 × 3 matrix [[..], [..], [..]]");
  Matrix3d m;
  for (int i = 0; i < 3; ++i) m.row(i) = rows[i].AsVector3().transpose();
  return m;
}

// inertia: [J1, J2, J3] (principal, in the body axes) or a full symmetric 3 × 3 matrix.
Matrix3d ReadInertia(const YamlValue& value) {
  const std::vector<YamlValue> items = value.AsList();
  if (!items.empty() && items[0].IsSequence()) return ReadMatrix3(value);
  return value.AsVector3().asDiagonal();
}

Matrix3d ReadOrientation(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"matrix", "axis", "angle", "quaternion"});
  if (auto v = map.Find("matrix")) {
    if (map.entries().size() != 1) value.Fail("give the orientation in one form only");
    return ReadMatrix3(*v);
  }
  if (auto v = map.Find("quaternion")) {
    if (map.entries().size() != 1) value.Fail("give the orientation in one form only");
    const std::vector<YamlValue> items = v->AsList();
    if (items.size() != 4) v->FailExpected("a quaternion [w, x, y, z]");
    Eigen::Quaterniond q(items[0].AsNumber(), items[1].AsNumber(), items[2].AsNumber(),
                         items[3].AsNumber());
    if (!(q.norm() > 0.0)) v->Fail("the quaternion must not be zero");
    return q.normalized().toRotationMatrix();
  }
  map.CheckKeys({"axis", "angle"});
  const YamlValue axis_value = map.Get("axis");
  const Vector3d axis = axis_value.AsVector3();
  if (!(axis.norm() > 0.0)) axis_value.Fail("the rotation axis must be a non-zero vector");
  return Eigen::AngleAxisd(map.Get("angle").AsNumber(), axis.normalized()).toRotationMatrix();
}

}  // namespace

void ReadRigidBody(const YamlValue& item, ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  map.CheckKeys({"name", "mass", "inertia", "position", "orientation", "velocity",
                 "angular_velocity", "angular_velocity_frame", "motion"});
  RigidBodySpec spec;
  spec.name = map.Get("name").AsString();
  spec.mass = map.Get("mass").AsPositive();
  const YamlValue inertia = map.Get("inertia");
  spec.inertia = ReadInertia(inertia);
  inertia.Locate([&] { ValidateInertia(spec.inertia, spec.name); });
  spec.position = map.Get("position").AsVector3();
  if (auto v = map.Find("orientation")) spec.orientation = ReadOrientation(*v);
  if (auto v = map.Find("velocity")) spec.velocity = v->AsVector3();
  if (auto v = map.Find("angular_velocity")) spec.angular_velocity = v->AsVector3();
  if (auto v = map.Find("angular_velocity_frame"))
    spec.angular_velocity_in_world = v->AsChoice({"body", "world"}) == 1;
  if (auto v = map.Find("motion"))
    spec.motion = v->AsEnum<BodyMotion>({{"free", BodyMotion::kFree},
                                         {"fixed", BodyMotion::kFixed},
                                         {"prescribed", BodyMotion::kPrescribed}});
  item.Locate([&] { builder->AddRigidBody(spec); });
}

void ReadBodyAttachment(const YamlValue& item,
                        const std::function<CablePointRef(const YamlValue&)>& read_point,
                        double time_step, ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  map.CheckKeys({"name", "body", "point", "body_point", "stiffness", "damping"});
  BodyAttachmentSpec spec;
  spec.name = map.Get("name").AsString();
  spec.body = map.Get("body").AsString();
  spec.point = read_point(map.Get("point"));
  if (auto v = map.Find("body_point")) spec.body_point = v->AsVector3();
  if (auto v = map.Find("stiffness")) spec.stiffness = v->AsPositive();
  if (auto v = map.Find("damping")) spec.damping = v->AsNonNegative();
  spec.time_step = time_step;
  item.Locate([&] { builder->AddBodyAttachment(spec); });
}

}  // namespace ancfnet
