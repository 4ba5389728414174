#pragma once
// `ancfnet assumed-modes --length L --ei EI --rho-a ρA --rate Ω --time T [--modes K] [--end t]
// [--step h] -o FILE.csv`: the linear floating-frame comparison model of a spin-up.

#include <CLI/CLI.hpp>
#include <string>

namespace ancfnet {

struct AssumedModesArguments {
  CLI::App* command = nullptr;
  double length = 10.0, bending_stiffness = 1.4e4, mass_per_length = 1.2;
  double rate = 6.0, ramp_time = 15.0, end_time = 20.0, time_step = 1e-3;
  int modes = 4;
  std::string output;
};

void AddAssumedModesCommand(CLI::App& app, AssumedModesArguments* arguments);

/// Writes time,tip_deflection rows (s, m) to the output file and prints one line; 0.
int RunAssumedModesCommand(const AssumedModesArguments& arguments);

}  // namespace ancfnet
