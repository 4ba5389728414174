#include "ancfnet/io/ideal_joint_reader.hpp"

#include <string_view>
#include <utility>
#include <vector>

#include "ancfnet/io/joint_anchor_reader.hpp"

namespace ancfnet {
namespace {

const std::vector<std::pair<std::string_view, IdealJoint::Type>> kTypes = {
    {"spherical", IdealJoint::Type::kSpherical},
    {"revolute", IdealJoint::Type::kRevolute},
    {"weld", IdealJoint::Type::kWeld},
    {"line", IdealJoint::Type::kLine},
    {"prismatic", IdealJoint::Type::kPrismatic}};

}  // namespace

bool IsIdealJointType(const std::string& type) {
  for (const auto& [name, value] : kTypes)
    if (name == type) return true;
  return false;
}

void ReadIdealJoint(const YamlValue& item,
                    const std::function<CablePointRef(const YamlValue&)>& read_point,
                    ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  IdealJointSpec spec;
  const YamlValue name = map.Get("name");
  spec.name = name.AsString();
  spec.type = map.Get("type").AsEnum<IdealJoint::Type>(kTypes);
  const bool has_axis = spec.type != IdealJoint::Type::kSpherical &&
                        spec.type != IdealJoint::Type::kWeld;
  if (has_axis)
    map.CheckKeys({"name", "type", "between", "point", "axis"});
  else
    map.CheckKeys({"name", "type", "between", "point"});
  const YamlValue between = map.Get("between");
  const std::vector<YamlValue> sides = between.AsList();
  if (sides.size() != 2)
    between.FailExpected("a list of the joint's two sides, [ANCHOR, ANCHOR]");
  spec.first = ReadJointAnchor(sides[0], read_point);
  spec.second = ReadJointAnchor(sides[1], read_point);
  if (spec.first.kind == JointAnchor::Kind::kGround &&
      spec.second.kind == JointAnchor::Kind::kGround)
    between.Fail("both sides of the joint are the ground");
  if (auto v = map.Find("point")) spec.point = v->AsVector3();
  if (auto v = map.Find("axis")) {
    spec.axis = v->AsVector3();
    if (!(spec.axis.norm() > 0.0)) v->Fail("the joint axis must be a non-zero vector");
  }
  // The builder's remaining checks name the side ("first: no rigid body named 'x'") or the
  // name ("two joints are named 'x'").
  try {
    builder->AddIdealJoint(spec);
  } catch (const InputError& error) {
    const std::string message = error.what();
    (message.rfind("first", 0) == 0       ? sides[0]
     : message.rfind("second", 0) == 0    ? sides[1]
     : message.rfind("two joints", 0) == 0 ? name
                                           : item)
        .Fail(message);
  }
}

}  // namespace ancfnet
