#pragma once
/// @file ProbeCsvWriter: one CSV row of probe values per output step.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// Writes probe values as CSV: a header `time,<ProbeColumns of each probe…>` and one row per call
/// to Append, with time in s and the probe values in SI units (m, m/s, J). Numbers are written in
/// their shortest form that reads back to the same double. Every row is flushed, so the rows
/// written before a crash survive.
class ProbeCsvWriter {
 public:
  /// Opens (truncates) `path` and writes the header. Throws InputError "cannot write PATH" when
  /// the file cannot be opened. With `resume_at`, continues the file an earlier run wrote: it is
  /// cut back to its first `resume_at` bytes (its size at a checkpoint, header included) and
  /// appended to; throws InputError when it is missing or shorter.
  ProbeCsvWriter(const std::filesystem::path& path, const std::vector<Probe>& probes,
                 std::optional<std::uintmax_t> resume_at = std::nullopt);

  ProbeCsvWriter(const ProbeCsvWriter&) = delete;
  ProbeCsvWriter& operator=(const ProbeCsvWriter&) = delete;
  ProbeCsvWriter(ProbeCsvWriter&&) = default;
  ProbeCsvWriter& operator=(ProbeCsvWriter&&) = default;

  /// Writes the row of `state` (time = state.t) evaluated with EvaluateProbe, `contacts` being
  /// the active contacts at `state` (read by contact probes only). Throws
  /// SolverError("non-finite value in probe column NAME", state.t) and writes nothing when a value
  /// is NaN or infinite; throws InputError when the file cannot be written. No allocation after
  /// the first row.
  void Append(const Model& model, const State& state, const EnergyAccount& energy,
              const std::vector<ContactPoint>& contacts);

  /// The column names, `time` first.
  const std::vector<std::string>& columns() const { return columns_; }
  const std::filesystem::path& path() const { return path_; }
  /// Bytes in the file so far.
  std::uintmax_t size() const { return size_; }

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  void WriteAndFlush(const std::string& text);

  std::filesystem::path path_;
  std::unique_ptr<std::FILE, FileCloser> file_;
  std::vector<Probe> probes_;
  std::vector<std::string> columns_;
  std::vector<double> values_;  // time, then the probe values of one row
  std::string row_;
  std::uintmax_t size_ = 0;
};

}  // namespace ancfnet
