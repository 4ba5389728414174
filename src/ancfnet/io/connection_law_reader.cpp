#include "ancfnet/io/connection_law_reader.hpp"

#include <vector>

namespace ancfnet {
namespace {

std::vector<ForceTablePoint> ReadTable(const YamlValue& value) {
  std::vector<ForceTablePoint> table;
  for (const YamlValue& row : value.AsList(/*non_empty=*/true)) {
    const std::vector<YamlValue> pair = row.AsList();
    if (pair.size() != 2) row.FailExpected("a row [elongation, force]");
    table.push_back({pair[0].AsNumber(), pair[1].AsNumber()});
  }
  return table;
}

}  // namespace

ConnectionLaw ReadConnectionLaw(const YamlValue& value) {
  const YamlMap map = value.AsMap();
  const std::size_t type =
      map.Get("type").AsChoice({"linear", "tension_only", "polynomial", "table"});
  static const std::vector<std::vector<std::string_view>> kKeys = {
      {"type", "stiffness", "damping", "damping_time"},
      {"type", "stiffness", "gap", "damping", "damping_time"},
      {"type", "k1", "k3", "damping", "damping_time"},
      {"type", "table", "damping", "damping_time"}};
  map.CheckKeys(kKeys[type]);
  if (map.Find("damping") && map.Find("damping_time"))
    map.Get("damping_time").Fail("give either damping (N s/m) or damping_time (s), not both");
  ConnectionLaw law;
  switch (type) {
    case 0: {
      const double k = map.Get("stiffness").AsPositive();
      law = value.Locate([&] { return MakeLinearLaw(k); });
      break;
    }
    case 1: {
      const double k = map.Get("stiffness").AsPositive();
      const double gap = map.Find("gap") ? map.Get("gap").AsNonNegative() : 0.0;
      law = value.Locate([&] { return MakeTensionOnlyLaw(k, gap); });
      break;
    }
    case 2: {
      const double k1 = map.Get("k1").AsPositive();
      const double k3 = map.Find("k3") ? map.Get("k3").AsNonNegative() : 0.0;
      law = value.Locate([&] { return MakePolynomialLaw(k1, k3); });
      break;
    }
    default: {
      const YamlValue table_value = map.Get("table");
      const std::vector<ForceTablePoint> table = ReadTable(table_value);
      law = table_value.Locate([&] { return MakePiecewiseLinearLaw(table); });
    }
  }
  if (auto v = map.Find("damping")) {
    const double b = v->AsNonNegative();
    v->Locate([&] { law = WithConstantDamping(law, b); });
  }
  if (auto v = map.Find("damping_time")) {
    const double beta = v->AsNonNegative();
    v->Locate([&] { law = WithStiffnessProportionalDamping(law, beta); });
  }
  return law;
}

}  // namespace ancfnet
