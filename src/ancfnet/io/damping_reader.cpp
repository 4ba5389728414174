#include "ancfnet/io/damping_reader.hpp"

namespace ancfnet {
namespace {

// [a, b] of two numbers.
std::pair<double, double> ReadPairOfNumbers(const YamlValue& value) {
  const std::vector<YamlValue> items = value.AsList();
  if (items.size() != 2) value.FailExpected("a pair [frequency (Hz), damping ratio]");
  return {items[0].AsPositive(), items[1].AsNumberIn(0.0, 0.999999)};
}

void ReadRayleigh(const YamlValue& value, ModelBuilder* builder) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"alpha", "beta", "fit"});
  RayleighDamping rayleigh;
  if (auto fit = map.Find("fit")) {
    if (map.Find("alpha") || map.Find("beta")) fit->Fail("give either alpha and beta, or fit");
    const std::vector<YamlValue> rows = fit->AsList();
    if (rows.size() != 2) fit->FailExpected("two pairs [[f₁, ζ₁], [f₂, ζ₂]]");
    // (Frequency, damping ratio) pairs, not structured bindings: clang 14 (the fuzz build's
    // compiler) cannot capture those in a lambda.
    const std::pair<double, double> first = ReadPairOfNumbers(rows[0]);
    const std::pair<double, double> second = ReadPairOfNumbers(rows[1]);
    rayleigh = fit->Locate(
        [&] { return FitRayleighDamping(first.first, first.second, second.first, second.second); });
  } else {
    if (auto v = map.Find("alpha")) rayleigh.alpha = v->AsNonNegative();
    if (auto v = map.Find("beta")) rayleigh.beta = v->AsNonNegative();
  }
  value.Locate([&] { builder->SetRayleighDamping(rayleigh); });
}

void ReadModal(const YamlValue& value, ModelBuilder* builder) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"modes", "ratios", "table"});
  ModalDamping modal;
  modal.num_modes = map.Get("modes").AsInt(1, 10000);
  if (auto v = map.Find("ratios")) {
    if (map.Find("table")) v->Fail("give either ratios or table, not both");
    for (const YamlValue& ratio : v->AsList(true))
      modal.ratios.push_back(ratio.AsNumberIn(0.0, 0.999999));
  } else {
    for (const YamlValue& row : map.Get("table").AsList(true))
      modal.table.push_back(ReadPairOfNumbers(row));
  }
  value.Locate([&] { builder->SetModalDamping(modal); });
}

}  // namespace

void ReadDamping(const YamlValue& value, ModelBuilder* builder) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"rayleigh", "modal"});
  if (auto v = map.Find("rayleigh")) ReadRayleigh(*v, builder);
  if (auto v = map.Find("modal")) ReadModal(*v, builder);
}

}  // namespace ancfnet
