#include "ancfnet/io/probe_csv_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

ProbeCsvWriter::ProbeCsvWriter(const std::filesystem::path& path, const std::vector<Probe>& probes,
                               std::optional<std::uintmax_t> resume_at)
    : path_(path), probes_(probes) {
  if (resume_at) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error)
      throw InputError(fmt::format(
          "cannot continue {}: it is missing (continue in the output directory of the run that "
          "wrote the checkpoint)",
          path.string()));
    if (size < *resume_at)
      throw InputError(fmt::format(
          "cannot continue {}: it has {} bytes, fewer than the {} it had at the checkpoint",
          path.string(), size, *resume_at));
    std::filesystem::resize_file(path, *resume_at, error);
    if (error) throw InputError(fmt::format("cannot write {}", path.string()));
    size_ = *resume_at;
  }
  file_.reset(std::fopen(path.c_str(), resume_at ? "a" : "w"));
  if (!file_) throw InputError(fmt::format("cannot write {}", path.string()));
  columns_.push_back("time");
  for (const Probe& probe : probes_) {
    for (std::string& column : ProbeColumns(probe)) columns_.push_back(std::move(column));
  }
  values_.reserve(columns_.size());
  if (!resume_at) WriteAndFlush(fmt::format("{}\n", fmt::join(columns_, ",")));
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
  size_ += text.size();
}

}  // namespace ancfnet
