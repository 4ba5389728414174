#include "ancfnet/study/study.hpp"

#include <fmt/format.h>

#include <limits>
#include <system_error>
#include <utility>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/io/yaml_document.hpp"
#include "ancfnet/io/yaml_reader.hpp"

namespace ancfnet {
namespace {

// The scene value a parameter varies: it must exist in the base scene and be a number.
ScenePath ReadScenePath(const YamlValue& value, const Study& study) {
  const ScenePath path = value.Locate([&] { return ScenePath::Parse(value.AsString()); });
  const std::string scene_name = study.scene_file.filename().string();
  const YAML::Node node = value.Locate([&] { return path.Find(study.scene, scene_name); });
  double number = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, number))
    value.Fail(fmt::format("'{}' of the scene {} is not a number, so a study cannot vary it",
                           path.text(), scene_name));
  return path;
}

StudyParameter ReadParameter(const YamlValue& item, const Study& study) {
  const YamlMap map = item.AsMap();
  map.CheckKeys({"path", "values", "uniform", "normal"});
  StudyParameter parameter;
  parameter.path = ReadScenePath(map.Get("path"), study);
  const auto values = map.Find("values");
  const auto uniform = map.Find("uniform");
  const auto normal = map.Find("normal");
  if (study.sampling == StudySampling::kGrid) {
    if (uniform || normal)
      (uniform ? *uniform : *normal)
          .Fail(
              "a grid study lists each parameter's 'values' (distributions are for sampling: "
              "random or latin_hypercube)");
    for (const YamlValue& v : map.Get("values").AsList(/*non_empty=*/true))
      parameter.values.push_back(v.AsNumber());
    return parameter;
  }
  if (values)
    values->Fail(
        "a sampled study gives each parameter a distribution, 'uniform' or 'normal' "
        "('values' are for sampling: grid)");
  if (uniform && normal) normal->Fail("a parameter has one distribution: 'uniform' or 'normal'");
  if (!uniform && !normal)
    map.value().Fail(
        "missing the parameter's distribution: 'uniform: [LOW, HIGH]' or "
        "'normal: {mean: M, std: S}'");
  if (uniform) {
    const std::vector<YamlValue> bounds = uniform->AsList();
    if (bounds.size() != 2) uniform->FailExpected("a list [LOW, HIGH]");
    parameter.kind = StudyParameter::Kind::kUniform;
    parameter.low = bounds[0].AsNumber();
    parameter.high = bounds[1].AsNumber();
    if (!(parameter.low < parameter.high)) uniform->Fail("LOW must be below HIGH in [LOW, HIGH]");
    return parameter;
  }
  const YamlMap moments = normal->AsMap();
  moments.CheckKeys({"mean", "std"});
  parameter.kind = StudyParameter::Kind::kNormal;
  parameter.mean = moments.Get("mean").AsNumber();
  parameter.standard_deviation = moments.Get("std").AsPositive();
  return parameter;
}

std::size_t CountGridCases(const Study& study, const YamlValue& parameters) {
  std::size_t count = 1;
  for (const StudyParameter& parameter : study.parameters) {
    count *= parameter.values.size();
    if (count > kMaxStudyCases)
      parameters.Fail(fmt::format("the grid has more than {} cases", kMaxStudyCases));
  }
  return count;
}

StudyPlot ReadPlot(const YamlValue& value, const Study& study) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"x", "y", "metric"});
  std::vector<std::string_view> paths;
  for (const StudyParameter& parameter : study.parameters) paths.push_back(parameter.path.text());
  const auto parameter_path = [&](std::string_view key) {
    const YamlValue axis = map.Get(key);
    return std::string(paths[axis.AsChoice(paths)]);
  };
  StudyPlot plot{parameter_path("x"), parameter_path("y"), map.Get("metric").AsString()};
  if (plot.x == plot.y) map.Get("y").Fail("the plot's x and y are the same parameter");
  return plot;
}

}  // namespace

double StudyParameter::Quantile(double u) const {
  if (kind == Kind::kUniform) return low + (high - low) * u;
  return mean + standard_deviation * StandardNormalQuantile(u);
}

CaseTable Study::MakeCases() const {
  if (sampling == StudySampling::kGrid) {
    std::vector<std::vector<double>> values;
    for (const StudyParameter& parameter : parameters) values.push_back(parameter.values);
    return MakeGridCases(values);
  }
  CaseTable cases = sampling == StudySampling::kRandom
                        ? DrawRandomUnitCases(sampled_cases, parameters.size(), seed)
                        : DrawLatinHypercubeUnitCases(sampled_cases, parameters.size(), seed);
  for (std::vector<double>& row : cases)
    for (std::size_t i = 0; i < row.size(); ++i) row[i] = parameters[i].Quantile(row[i]);
  return cases;
}

std::string Study::MakeCaseScene(const std::vector<double>& values) const {
  const YAML::Node copy = YAML::Clone(scene);
  const std::string scene_name = scene_file.filename().string();
  const auto set = [&](const ScenePath& path, double value) {
    YAML::Node node = path.Find(copy, scene_name);
    node = fmt::format("{}", value);  // the shortest text that reads back as `value`
  };
  for (const auto& [path, value] : fixed_values) set(path, value);
  for (std::size_t i = 0; i < parameters.size(); ++i) set(parameters[i].path, values[i]);
  YAML::Emitter out;
  out << copy;
  return std::string(out.c_str()) + "\n";
}

Study ParseStudy(const std::string& yaml_text, const std::string& source_name,
                 const std::filesystem::path& directory) {
  const YAML::Node root_node = ParseYamlDocument(yaml_text, source_name, "study");
  const YamlValue root = YamlValue::Root(root_node, source_name);
  if (root_node.IsNull()) root.FailPlain("the study is empty (expected scene and parameters)");
  try {
    const YamlMap map = root.AsMap();
    map.CheckKeys({"scene", "sampling", "cases", "seed", "set", "parameters", "plot"});
    Study study;
    const YamlValue scene = map.Get("scene");
    study.scene_file = directory / scene.AsString();
    if (std::error_code error; !std::filesystem::is_regular_file(study.scene_file, error))
      scene.Fail(fmt::format("cannot open the base scene {}", study.scene_file.string()));
    LoadScene(study.scene_file);
    study.scene = ParseYamlDocument(ReadInputFile(study.scene_file, "scene"),
                                    study.scene_file.string(), "scene");
    if (auto v = map.Find("sampling"))
      study.sampling =
          v->AsEnum<StudySampling>({{"grid", StudySampling::kGrid},
                                    {"random", StudySampling::kRandom},
                                    {"latin_hypercube", StudySampling::kLatinHypercube}});
    const bool sampled = study.sampling != StudySampling::kGrid;
    const auto cases = map.Find("cases");
    if (sampled && !cases) map.value().Fail("missing required key 'cases' (the number of samples)");
    if (!sampled && cases)
      cases->Fail("a grid study has one case per combination of the values: no 'cases'");
    if (cases) study.sampled_cases = cases->AsInt(1, static_cast<int>(kMaxStudyCases));
    if (auto v = map.Find("seed")) study.seed = static_cast<std::uint64_t>(v->AsInt(0));
    const YamlValue parameters = map.Get("parameters");
    for (const YamlValue& item : parameters.AsList(/*non_empty=*/true)) {
      study.parameters.push_back(ReadParameter(item, study));
      for (std::size_t i = 0; i + 1 < study.parameters.size(); ++i)
        if (study.parameters[i].path.text() == study.parameters.back().path.text())
          item.AsMap().Get("path").Fail("this scene value is already a parameter of the study");
    }
    if (!sampled) CountGridCases(study, parameters);
    if (auto v = map.Find("set")) {
      const YamlMap fixed = v->AsMap();
      for (const YamlMap::Entry& entry : fixed.entries()) {
        const YamlValue path = v->Child(YAML::Node(entry.key), entry.key, entry.key_mark);
        study.fixed_values.emplace_back(ReadScenePath(path, study), entry.value.AsNumber());
        for (const StudyParameter& parameter : study.parameters)
          if (parameter.path.text() == entry.key)
            entry.value.Fail("this scene value is a parameter of the study: it cannot be set");
      }
    }
    if (auto v = map.Find("plot")) study.plot = ReadPlot(*v, study);
    return study;
  } catch (const YAML::Exception& error) {  // a node access the reader did not foresee
    ThrowYamlError(source_name, error);
  }
}

Study LoadStudy(const std::filesystem::path& file) {
  return ParseStudy(ReadInputFile(file, "study"), file.string(), file.parent_path());
}

}  // namespace ancfnet
