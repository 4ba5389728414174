#pragma once
/// @file One case of a study run as its own process: `ancfnet run` on the case's scene, exactly
/// as a user would run it, so that a case that crashes or hangs the solver takes no other case
/// with it. The case's folder DIR/cases/NNNN holds scene.yaml (the base scene with the case's
/// values), the run's outputs (summary.json, probes.csv, …) and its messages, stderr.txt.

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "ancfnet/study/case_result.hpp"
#include "ancfnet/study/study.hpp"

namespace ancfnet {

/// How a study starts its cases.
struct CaseLauncher {
  std::filesystem::path executable;  ///< the ancfnet command-line tool
  std::filesystem::path study_dir;   ///< DIR of `ancfnet study -o DIR`
};

/// Empties the case's folder (what an interrupted attempt left), writes its scene.yaml and
/// starts `EXECUTABLE run scene.yaml -o FOLDER -q --scene-dir BASE_SCENE_FOLDER` with stdout
/// discarded and stderr in stderr.txt, in a process group of its own, and stopped by SIGTERM if
/// the study dies. Returns the child's process id. Throws InputError when the folder cannot be
/// written or the process cannot be started (an executable that cannot be run ends the case
/// with exit code 127).
pid_t StartCase(const CaseLauncher& launcher, const Study& study, std::size_t index,
                const std::vector<double>& values);

/// The result of a case whose process ended with wait status `wait_status`: ok for exit code 0;
/// failed with the run's message (summary.json, else the last line of stderr.txt) for another
/// code, or with the signal that killed it. std::nullopt when the run was interrupted on
/// request (exit code 130 or 143, or ended by SIGINT or SIGTERM): the case is to be run again.
/// Else writes the result to the case's case.json (WriteCaseResult).
std::optional<CaseResult> FinishCase(const CaseLauncher& launcher, std::size_t index,
                                     const std::vector<double>& values, int wait_status);

/// StartCase, then waits for the process and returns FinishCase's result. A signal that
/// interrupts the wait (common/interrupt.hpp) is passed on to the case.
std::optional<CaseResult> RunCase(const CaseLauncher& launcher, const Study& study,
                                  std::size_t index, const std::vector<double>& values);

/// Waits for any started case to end; passes a pending interrupt on to `running` once. Returns
/// the process id and its wait status.
std::pair<pid_t, int> WaitForCase(const std::vector<pid_t>& running, bool* interrupt_passed_on);

}  // namespace ancfnet
