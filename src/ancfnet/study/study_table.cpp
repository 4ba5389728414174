#include "ancfnet/study/study_table.hpp"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

using Json = nlohmann::ordered_json;  // keys in the order written: columns follow the probes
using Metrics = std::vector<std::pair<std::string, std::string>>;  // column, cell

std::string FormatNumber(double value) { return fmt::format("{:.10g}", value); }

// The leaves of `json` under the name `prefix`, in document order.
void Flatten(const Json& json, const std::string& prefix, Metrics* metrics) {
  if (json.is_object()) {
    for (const auto& [key, value] : json.items())
      Flatten(value, prefix.empty() ? key : prefix + "." + key, metrics);
  } else if (json.is_array()) {
    for (std::size_t i = 0; i < json.size(); ++i)
      Flatten(json[i], fmt::format("{}[{}]", prefix, i), metrics);
  } else if (json.is_boolean()) {
    metrics->emplace_back(prefix, json.get<bool>() ? "1" : "0");
  } else if (json.is_number()) {
    metrics->emplace_back(prefix, FormatNumber(json.get<double>()));
  } else if (json.is_null()) {
    metrics->emplace_back(prefix, "");
  }
}

// The metrics of a case's summary.json: the time and steps reached, the final probe values.
Metrics ReadMetrics(const std::filesystem::path& summary_file) {
  std::ifstream file(summary_file);
  const Json json = Json::parse(file, nullptr, /*allow_exceptions=*/false);
  Metrics metrics;
  if (!json.is_object()) return metrics;
  for (const char* key : {"time", "steps"})
    if (json.contains(key) && json[key].is_number())
      metrics.emplace_back(key, FormatNumber(json[key].get<double>()));
  // {"probes": {NAME: {KIND: VALUE}}}: the columns are NAME.FIELD, as in probes.csv.
  if (json.contains("probes") && json["probes"].is_object())
    for (const auto& [name, probe] : json["probes"].items())
      Flatten(probe.is_object() && probe.size() == 1 ? probe.front() : probe, name, &metrics);
  return metrics;
}

std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

}  // namespace

void WriteStudyTable(const std::filesystem::path& path, const Study& study,
                     const std::filesystem::path& study_dir,
                     const std::vector<CaseResult>& results) {
  std::vector<std::map<std::string, std::string>> cells;
  std::vector<std::string> columns;
  std::map<std::string, bool> known;
  for (const CaseResult& result : results) {
    cells.emplace_back();
    for (auto& [column, cell] : ReadMetrics(CaseFolder(study_dir, result.index) / "summary.json")) {
      if (!known[column]) columns.push_back(column);
      known[column] = true;
      cells.back()[column] = std::move(cell);
    }
  }
  std::ofstream file(path);
  file << "case";
  for (const StudyParameter& parameter : study.parameters) file << ',' << parameter.path.text();
  file << ",status,reason";
  for (const std::string& column : columns) file << ',' << column;
  file << '\n';
  for (std::size_t row = 0; row < results.size(); ++row) {
    const CaseResult& result = results[row];
    file << result.index;
    for (const double value : result.values) file << ',' << FormatNumber(value);
    file << ',' << (result.ok ? "ok" : "failed") << ',' << Quoted(result.reason);
    for (const std::string& column : columns) {
      const auto cell = cells[row].find(column);
      file << ',' << (cell == cells[row].end() ? std::string() : cell->second);
    }
    file << '\n';
  }
  file.close();
  if (!file) throw InputError(fmt::format("cannot write {}", path.string()));
}

}  // namespace ancfnet
