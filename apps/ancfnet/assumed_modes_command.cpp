#include "assumed_modes_command.hpp"

#include <fmt/format.h>

#include <fstream>

#include "ancfnet/analysis/assumed_modes.hpp"
#include "ancfnet/common/error.hpp"

namespace ancfnet {

void AddAssumedModesCommand(CLI::App& app, AssumedModesArguments* a) {
  a->command = app.add_subcommand(
      "assumed-modes",
      "Spin-up of a hub-clamped beam with the linear floating-frame assumed-modes model");
  CLI::App* c = a->command;
  c->add_option("--length", a->length, "Beam length L (m)")->check(CLI::PositiveNumber);
  c->add_option("--ei", a->bending_stiffness, "Bending stiffness EI (N m²)")
      ->check(CLI::PositiveNumber);
  c->add_option("--rho-a", a->mass_per_length, "Mass per length ρA (kg/m)")
      ->check(CLI::PositiveNumber);
  c->add_option("--rate", a->rate, "Final hub rate Ω (rad/s)");
  c->add_option("--time", a->ramp_time, "Spin-up time T (s)")->check(CLI::PositiveNumber);
  c->add_option("--end", a->end_time, "End time (s)")->check(CLI::PositiveNumber);
  c->add_option("--step", a->time_step, "Runge–Kutta step (s)")->check(CLI::PositiveNumber);
  c->add_option("--modes", a->modes, "Clamped–free modes, 1 … 6")->check(CLI::Range(1, 6));
  c->add_option("-o,--output", a->output, "CSV file: time, tip_deflection")->required();
}

int RunAssumedModesCommand(const AssumedModesArguments& a) {
  const AngleProfile hub{
      .kind = AngleProfile::Kind::kSpinUp, .rate = a.rate, .ramp_time = a.ramp_time};
  const AssumedModesResponse r = SimulateAssumedModes({.length = a.length,
                                                       .bending_stiffness = a.bending_stiffness,
                                                       .mass_per_length = a.mass_per_length,
                                                       .num_modes = a.modes},
                                                      hub, a.end_time, a.time_step, 1e3 * a.length);
  std::ofstream file(a.output);
  file << "time,tip_deflection\n";
  for (std::size_t i = 0; i < r.time.size(); ++i)
    file << fmt::format("{},{}\n", r.time[i], r.tip_deflection[i]);
  if (!file) throw InputError(fmt::format("cannot write {}", a.output));
  if (r.time.back() < a.end_time - 0.5 * a.time_step)
    fmt::print("assumed modes (ω₁ = {:.4g} rad/s): diverged, |v(L)| > {} m at t = {:.4g} s\n",
               r.omega[0], 1e3 * a.length, r.time.back());
  else
    fmt::print("assumed modes (ω₁ = {:.4g} rad/s): {} samples in {}\n", r.omega[0], r.time.size(),
               a.output);
  return 0;
}

}  // namespace ancfnet
