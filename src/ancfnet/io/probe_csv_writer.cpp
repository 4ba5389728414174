#include "ancfnet/io/probe_csv_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

ProbeCsvWriter::ProbeCsvWriter(const std::filesystem::path& path, const std::vector<Probe>& probes)
    : path_(path), file_(std::fopen(path.c_str(), "w")), probes_(probes) {
  if (!file_) throw InputError(fmt::format("cannot write {}", path.string()));
  columns_.push_back("time");
  for (const Probe& probe : probes_) {
    for (std::string& column : ProbeColumns(probe)) columns_.push_back(std::move(column));
  }
  values_.reserve(columns_.size());
  WriteAndFlush(fmt::format("{}\n", fmt::join(columns_, ",")));
}

void ProbeCsvWriter::Append(const Model& model, const State& state, const EnergyAccount& energy,
                            const std::vector<ContactPoint>& contacts) {
  values_.clear();
  values_.push_back(state.t);
  for (const Probe& probe : probes_) EvaluateProbe(probe, model, state, energy, contacts, &values_);
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (!std::isfinite(values_[i]))
      throw SolverError(fmt::format("non-finite value in probe column {}", columns_[i]), state.t);
  }
  row_.clear();
  for (std::size_t i = 0; i < values_.size(); ++i)
    fmt::format_to(std::back_inserter(row_), "{}{}", i == 0 ? "" : ",", values_[i]);
  row_ += '\n';
  WriteAndFlush(row_);
}

void ProbeCsvWriter::WriteAndFlush(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size() ||
      std::fflush(file_.get()) != 0)
    throw InputError(fmt::format("cannot write {}", path_.string()));
}

}  // namespace ancfnet
