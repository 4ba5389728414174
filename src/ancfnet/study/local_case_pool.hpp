#pragma once
/// @file The cases of a study run on this machine by a pool of child processes.

#include <cstddef>
#include <vector>

#include "ancfnet/study/case_process.hpp"
#include "ancfnet/study/study_progress.hpp"

namespace ancfnet {

/// Runs the cases `pending` (indices into `cases`), at most `workers` at a time, each as soon as
/// one before it ends, and records each result in `progress`. A pending interrupt
/// (common/interrupt.hpp) starts no more cases and is passed on to the running ones. Returns
/// false when interrupted before every case ran.
bool RunCasesLocally(const CaseLauncher& launcher, const Study& study, const CaseTable& cases,
                     const std::vector<std::size_t>& pending, int workers, StudyProgress* progress);

}  // namespace ancfnet
