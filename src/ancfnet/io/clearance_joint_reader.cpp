#include "ancfnet/io/clearance_joint_reader.hpp"

#include "ancfnet/io/contact_reader.hpp"
#include "ancfnet/io/joint_anchor_reader.hpp"

namespace ancfnet {

void ReadClearanceJoint(const YamlValue& item,
                        const std::function<CablePointRef(const YamlValue&)>& read_point,
                        ModelBuilder* builder) {
  const YamlMap map = item.AsMap();
  ClearanceJointSpec spec;
  spec.name = map.Get("name").AsString();
  spec.type = map.Get("type").AsEnum<ClearanceJoint::Type>(
      {{"revolute_clearance", ClearanceJoint::Type::kRevolute},
       {"spherical_clearance", ClearanceJoint::Type::kSpherical}});
  const bool revolute = spec.type == ClearanceJoint::Type::kRevolute;
  if (revolute) {
    map.CheckKeys({"name", "type", "journal", "bearing", "clearance", "journal_radius", "axis",
                   "contact", "friction"});
  } else {
    map.CheckKeys({"name", "type", "journal", "bearing", "clearance", "journal_radius", "contact",
                   "friction"});
  }
  const YamlValue journal = map.Get("journal");
  const YamlValue bearing = map.Get("bearing");
  spec.journal = ReadJointAnchor(journal, read_point);
  spec.bearing = ReadJointAnchor(bearing, read_point);
  spec.clearance = map.Get("clearance").AsPositive();
  const YamlValue radius = map.Get("journal_radius");
  spec.journal_radius = radius.AsPositive();
  if (!(spec.journal_radius > spec.clearance))
    radius.Fail("the journal radius must be larger than the clearance");
  if (auto v = map.Find("axis")) {
    spec.axis = v->AsVector3();
    if (!(spec.axis.norm() > 0.0)) v->Fail("the joint axis must be a non-zero vector");
  }
  spec.normal = ReadNormalLaw(map.Get("contact"));
  if (auto v = map.Find("friction")) spec.friction = ReadFriction(*v);
  // The builder's remaining checks name the side ("journal: no rigid body named 'x'").
  if (spec.journal.kind == JointAnchor::Kind::kGround &&
      spec.bearing.kind == JointAnchor::Kind::kGround)
    bearing.Fail("journal and bearing are both the ground");
  try {
    builder->AddClearanceJoint(spec);
  } catch (const InputError& error) {
    const std::string message = error.what();
    (message.rfind("bearing", 0) == 0   ? bearing
     : message.rfind("journal", 0) == 0 ? journal
                                        : item)
        .Fail(message);
  }
}

}  // namespace ancfnet
