#include "ancfnet/study/case_result.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

std::filesystem::path ResultFile(const std::filesystem::path& study_dir, std::size_t index) {
  return CaseFolder(study_dir, index) / "case.json";
}

}  // namespace

std::filesystem::path CaseFolder(const std::filesystem::path& study_dir, std::size_t index) {
  return study_dir / "cases" / fmt::format("{:04d}", index);
}

void WriteCaseResult(const std::filesystem::path& study_dir, const CaseResult& result) {
  const nlohmann::ordered_json json = {{"case", result.index},
                                       {"parameters", result.values},
                                       {"status", result.ok ? "ok" : "failed"},
                                       {"reason", result.reason}};
  const std::filesystem::path path = ResultFile(study_dir, result.index);
  std::filesystem::path temporary = path;
  temporary += ".part";
  {
    std::ofstream file(temporary);
    file << json.dump(2) << '\n';
    file.close();
    if (!file) throw InputError(fmt::format("cannot write {}", temporary.string()));
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw InputError(fmt::format("cannot write {}: {}", path.string(), error.message()));
}

std::optional<CaseResult> ReadCaseResult(const std::filesystem::path& study_dir, std::size_t index,
                                         const std::vector<double>& values) {
  const std::filesystem::path path = ResultFile(study_dir, index);
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  std::ifstream file(path);
  const nlohmann::json json = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  CaseResult result;
  result.index = index;
  const bool readable = json.is_object() && json.value("case", nlohmann::json()) == index &&
                        json.contains("parameters") && json["parameters"].is_array() &&
                        json.value("status", "") != "" && json.contains("reason") &&
                        json["reason"].is_string();
  if (!readable)
    throw InputError(
        fmt::format("{}: not the result of case {} of a study (remove the folder "
                    "to run the case again)",
                    path.string(), index));
  for (const nlohmann::json& value : json["parameters"])
    result.values.push_back(value.is_number() ? value.get<double>() : 0.0);
  if (result.values != values)
    throw InputError(
        fmt::format("{}: case {} of another study (other parameter values); give "
                    "the study another output folder",
                    path.string(), index));
  result.ok = json["status"] == "ok";
  result.reason = json["reason"].get<std::string>();
  return result;
}

}  // namespace ancfnet
