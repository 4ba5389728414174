#pragma once
/// @file The outcome of one case of a study, kept in its folder DIR/cases/NNNN/case.json. The
/// file is written last, when the case has ended, and atomically (a rename), so that its
/// presence marks a complete case: a resumed study runs again only cases without it.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ancfnet {

struct CaseResult {
  std::size_t index = 0;
  std::vector<double> values;  ///< the parameters, in the study's order
  bool ok = false;             ///< the run completed (`ancfnet run` exited with 0)
  std::string reason;          ///< why it failed: the run's message, or how the process ended
};

/// DIR/cases/NNNN (at least four digits).
std::filesystem::path CaseFolder(const std::filesystem::path& study_dir, std::size_t index);

/// Writes `result` to its folder's case.json: {"case", "parameters": [...], "status":
/// "ok"|"failed", "reason"}, first to a temporary file, then renamed. Throws InputError "cannot
/// write PATH" on failure.
void WriteCaseResult(const std::filesystem::path& study_dir, const CaseResult& result);

/// The result of case `index` when its case.json exists; std::nullopt when it does not. Throws
/// InputError "PATH: …" when it exists but cannot be read or is not a case result, and when
/// its parameters are not `values` (the folder holds another study's case).
std::optional<CaseResult> ReadCaseResult(const std::filesystem::path& study_dir, std::size_t index,
                                         const std::vector<double>& values);

}  // namespace ancfnet
