#include "ancfnet/io/probe_csv_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/closest_name.hpp"

namespace ancfnet {
namespace {

std::string_view Trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> SplitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(Trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::optional<double> ParseNumber(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::string MissingColumnMessage(const std::string& file, const std::string& name,
                                 const std::vector<std::string>& header) {
  std::vector<std::string_view> candidates(header.begin() + 1, header.end());
  std::string message = fmt::format("{}: no column '{}'", file, name);
  if (const std::optional<std::string> closest = ClosestName(name, candidates))
    message += fmt::format("; did you mean '{}'?", *closest);
  constexpr std::size_t kListed = 30;
  if (candidates.size() > kListed) {
    const std::size_t more = candidates.size() - kListed;
    candidates.resize(kListed);
    return message + fmt::format(" (columns: {}, and {} more)", fmt::join(candidates, ", "), more);
  }
  return message +
         fmt::format(" (columns: {})",
                     candidates.empty() ? "none" : fmt::format("{}", fmt::join(candidates, ", ")));
}

}  // namespace

ProbeSeries ReadProbeCsv(const std::filesystem::path& path, const std::vector<std::string>& columns,
                         const ProbeCsvWindow& window) {
  const std::string file = path.string();
  if (std::isnan(window.from) || std::isnan(window.to) || window.from > window.to)
    throw InputError(fmt::format("{}: the time window from {} s to {} s is empty", file,
                                 window.from, window.to));
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("cannot open {}", file));

  std::string line;
  if (!std::getline(in, line) || Trim(line).empty())
    throw InputError(fmt::format("{}: empty file, expected a header 'time,…'", file));
  std::vector<std::string> header;
  for (std::string_view field : SplitFields(line)) header.emplace_back(field);
  if (header.front() != "time")
    throw InputError(
        fmt::format("{}:1: the first column is '{}', expected 'time'", file, header.front()));

  ProbeSeries series;
  series.columns = columns;
  if (series.columns.empty()) series.columns.assign(header.begin() + 1, header.end());
  if (series.columns.empty()) throw InputError(fmt::format("{}: no column but time", file));
  std::vector<std::size_t> index;
  for (const std::string& name : series.columns) {
    const auto found = std::find(header.begin() + 1, header.end(), name);
    if (found == header.end()) throw InputError(MissingColumnMessage(file, name, header));
    index.push_back(static_cast<std::size_t>(found - header.begin()));
  }

  std::vector<double> time;
  std::vector<double> values;
  double first_time = 0.0;
  double last_time = 0.0;
  long rows = 0;
  for (long line_number = 2; std::getline(in, line); ++line_number) {
    if (Trim(line).empty()) continue;
    const std::vector<std::string_view> fields = SplitFields(line);
    if (fields.size() != header.size())
      throw InputError(fmt::format("{}:{}: {} fields, the header has {}", file, line_number,
                                   fields.size(), header.size()));
    const std::optional<double> t = ParseNumber(fields[0]);
    if (!t)
      throw InputError(
          fmt::format("{}:{}: time '{}' is not a finite number", file, line_number, fields[0]));
    if (rows > 0 && !(*t > last_time))
      throw InputError(fmt::format("{}:{}: time {} s does not increase (previous row {} s)", file,
                                   line_number, *t, last_time));
    if (rows == 0) first_time = *t;
    last_time = *t;
    ++rows;
    if (*t < window.from || *t > window.to) continue;
    time.push_back(*t);
    for (std::size_t j = 0; j < index.size(); ++j) {
      const std::optional<double> value = ParseNumber(fields[index[j]]);
      if (!value)
        throw InputError(fmt::format("{}:{}: '{}' in column '{}' is not a finite number", file,
                                     line_number, fields[index[j]], header[index[j]]));
      values.push_back(*value);
    }
  }
  if (in.bad()) throw InputError(fmt::format("cannot read {}", file));
  if (time.empty()) {
    if (rows == 0) throw InputError(fmt::format("{}: no data row", file));
    throw InputError(fmt::format("{}: no row with {} s ≤ time ≤ {} s (the file spans {} s to {} s)",
                                 file, window.from, window.to, first_time, last_time));
  }

  const auto n = static_cast<Index>(time.size());
  const auto c = static_cast<Index>(index.size());
  series.time = Eigen::Map<const VectorXd>(time.data(), n);
  series.values =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          values.data(), n, c);
  return series;
}

}  // namespace ancfnet
