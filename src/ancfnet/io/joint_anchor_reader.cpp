#include "ancfnet/io/joint_anchor_reader.hpp"

namespace ancfnet {

JointAnchorSpec ReadJointAnchor(const YamlValue& value,
                                const std::function<CablePointRef(const YamlValue&)>& read_point) {
  JointAnchorSpec spec;
  if (value.IsScalar() && value.AsString() == "ground") return spec;  // the ground
  if (value.IsMap()) {
    const YamlMap map = value.AsMap();
    if (map.Find("ground")) {
      map.CheckKeys({"ground"});
      spec.position = map.Get("ground").AsVector3();
      return spec;
    }
    if (map.Find("body")) {
      map.CheckKeys({"body", "point"});
      spec.kind = JointAnchor::Kind::kBody;
      spec.name = map.Get("body").AsString();
      if (auto v = map.Find("point")) spec.position = v->AsVector3();
      return spec;
    }
  }
  const CablePointRef point = read_point(value);
  spec.kind = JointAnchor::Kind::kPoint;
  spec.name = point.cable;
  spec.s = point.s;
  return spec;
}

}  // namespace ancfnet
