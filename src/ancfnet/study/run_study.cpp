#include "ancfnet/study/run_study.hpp"

#include <fmt/format.h>

#include <optional>
#include <vector>

#include "ancfnet/io/output_directory.hpp"
#include "ancfnet/study/case_process.hpp"
#include "ancfnet/study/local_case_pool.hpp"
#include "ancfnet/study/mpi_case_dispatch.hpp"
#include "ancfnet/study/study_progress.hpp"
#include "ancfnet/study/study_table.hpp"

namespace ancfnet {
namespace {

// The results of the complete cases (nullopt for the others).
std::vector<std::optional<CaseResult>> ReadResults(const std::filesystem::path& dir,
                                                   const CaseTable& cases) {
  std::vector<std::optional<CaseResult>> results;
  for (std::size_t index = 0; index < cases.size(); ++index)
    results.push_back(ReadCaseResult(dir, index, cases[index]));
  return results;
}

// Writes the table when every case has its result; returns the outcome.
StudyOutcome Conclude(const Study& study, const StudyOptions& options, const CaseTable& cases,
                      bool completed) {
  StudyOutcome outcome{.wrote_table = false, .interrupted = !completed, .cases = cases.size()};
  if (!completed) return outcome;
  std::vector<CaseResult> results;
  for (const std::optional<CaseResult>& result : ReadResults(options.output_dir, cases)) {
    results.push_back(*result);
    if (!result->ok) ++outcome.failed;
  }
  WriteStudyTable(options.output_dir / "study.csv", study, options.output_dir, results);
  outcome.wrote_table = true;
  return outcome;
}

}  // namespace

StudyOutcome RunStudy(const Study& study, const StudyOptions& options) {
  const CaseTable cases = study.MakeCases();
  const CaseLauncher launcher{options.executable, options.output_dir};
  std::optional<MpiCaseDispatch> mpi;
  if (StartedByMpirun()) mpi.emplace();
  if (mpi && mpi->rank() > 0) {
    mpi->Serve(launcher, study, cases);
    return {};
  }
  CreateOutputDirectory(options.output_dir);
  std::vector<std::size_t> pending;
  std::size_t failed_before = 0;
  const std::vector<std::optional<CaseResult>> before = ReadResults(options.output_dir, cases);
  for (std::size_t index = 0; index < cases.size(); ++index) {
    if (!before[index])
      pending.push_back(index);
    else if (!before[index]->ok)
      ++failed_before;
  }
  const std::size_t done_before = cases.size() - pending.size();
  const int workers = mpi && mpi->size() > 1 ? mpi->size() - 1 : options.workers;
  fmt::print(options.progress, "study: {} cases, {} done before, {} to run on {} {}\n",
             cases.size(), done_before, pending.size(), workers,
             mpi && mpi->size() > 1 ? "MPI ranks" : "worker processes");
  std::fflush(options.progress);
  StudyProgress progress(cases.size(), done_before, failed_before, options.progress);
  const bool completed = mpi && mpi->size() > 1
                             ? mpi->HandOut(launcher, cases, pending, &progress)
                             : RunCasesLocally(launcher, study, cases, pending, workers, &progress);
  return Conclude(study, options, cases, completed);
}

}  // namespace ancfnet
