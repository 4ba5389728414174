#pragma once
/// @file The output directory of a run.

#include <filesystem>

namespace ancfnet {

/// Creates `dir` (and its parents) when missing; throws InputError "cannot create output
/// directory 'DIR': REASON" when it cannot.
void CreateOutputDirectory(const std::filesystem::path& dir);

}  // namespace ancfnet
