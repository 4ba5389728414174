#pragma once
/// @file The outputs of a run as Python objects: summary.json as a dict, probes.csv as numpy
/// arrays.

#include <pybind11/pybind11.h>

#include <filesystem>

namespace ancfnet::python {

/// The run's `output_dir/summary.json` (WriteSummaryJson's keys) parsed into a dict.
/// Raises InputError when it cannot be read.
pybind11::dict ReadSummary(const std::filesystem::path& output_dir);

/// Every column of the probe CSV file `path` (ReadProbeCsv), "time" first, as read-only 1-D
/// numpy arrays that share one buffer (no copy per column).
pybind11::dict ReadProbes(const std::filesystem::path& path);

}  // namespace ancfnet::python
