#pragma once
/// @file Runs a study (`ancfnet study`): its cases not yet complete in the output folder, on
/// this machine or across the ranks of an MPI job, then its table.

#include <cstddef>
#include <cstdio>
#include <filesystem>

#include "ancfnet/study/study.hpp"

namespace ancfnet {

struct StudyOptions {
  std::filesystem::path output_dir;  ///< DIR: DIR/cases/NNNN/ and DIR/study.csv
  std::filesystem::path executable;  ///< the ancfnet command-line tool, which runs each case
  int workers = 1;                   ///< cases run at a time on this machine (≥ 1)
  std::FILE* progress = stderr;      ///< where the progress lines go
};

struct StudyOutcome {
  /// This process wrote the table (false on the ranks > 0 of an MPI job).
  bool wrote_table = false;
  bool interrupted = false;  ///< stopped on request before every case ran: no table
  std::size_t cases = 0;
  std::size_t failed = 0;
};

/// Runs every case of `study` whose folder has no result yet (case_result.hpp), on
/// options.workers processes, or, when started by mpirun with more than one rank, handed out by
/// rank 0 to the other ranks; prints the progress; then writes DIR/study.csv (study_table.hpp).
/// A case that fails is recorded with its reason and the others go on. An interrupt
/// (common/interrupt.hpp) lets the running cases stop cleanly and starts no others; running the
/// study again continues it. Throws InputError when DIR cannot be written or holds another
/// study's cases, and when started by mpirun without MPI built in.
StudyOutcome RunStudy(const Study& study, const StudyOptions& options);

}  // namespace ancfnet
