#pragma once
/// @file `ancfnet identify`: natural frequencies and damping ratios of the modes in a free decay
/// recorded in a probes.csv file, by the matrix pencil method (IdentifyModes).

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ancfnet {

/// The command line of `ancfnet identify`.
struct IdentifyArguments {
  std::string probes_csv;
  std::vector<std::string> columns;  ///< e.g. {"tip.z", "tip.x"}: they share the poles
  int modes = 1;                     ///< K
  std::optional<int> extra_poles;    ///< default 2K: a simulated record holds more modes than K
  std::optional<double> from;        ///< s; skip the forced part of an impulse response
  std::optional<double> to;          ///< s
  std::optional<long> decimation;    ///< D; default automatic (ModalIdentificationOptions)
  bool remove_mean = false;
  std::string output_json;  ///< empty: no JSON file
};

/// Adds the `identify` subcommand to `app`, filling `arguments` when it is parsed.
CLI::App* AddIdentifyCommand(CLI::App& app, IdentifyArguments* arguments);

/// Reads the columns, identifies the modes, prints a table on `out` and writes the JSON file when
/// asked. Returns the exit code 0; bad input throws InputError (exit code 2).
int RunIdentifyCommand(const IdentifyArguments& arguments, std::FILE* out);

}  // namespace ancfnet
