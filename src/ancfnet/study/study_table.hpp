#pragma once
/// @file The table of a study, DIR/study.csv: one row per case, in case order, with the varied
/// values, how the case ended and the metrics of its summary.json.

#include <filesystem>
#include <vector>

#include "ancfnet/study/case_result.hpp"
#include "ancfnet/study/study.hpp"

namespace ancfnet {

/// Writes `path` with the columns: case; one per parameter, named by its path; status (ok or
/// failed); reason (quoted); time and steps of the run; then every final probe value of the
/// cases' summary.json, named PROBE.FIELD[.SUBFIELD] as in probes.csv (without the probe's kind,
/// e.g. grab.enclosed_fraction, grab.tether.tension), a vector's components as NAME[i]
/// (true/false as 1/0) — the union over all cases, in the order they first appear going
/// through the cases in order. A value a case lacks (a probe of a run that never started, a
/// null) is an empty cell. Numbers are written with 10 significant digits, so that the same
/// cases give the same file whatever ran them. Throws InputError "cannot write PATH".
void WriteStudyTable(const std::filesystem::path& path, const Study& study,
                     const std::filesystem::path& study_dir,
                     const std::vector<CaseResult>& results);

}  // namespace ancfnet
