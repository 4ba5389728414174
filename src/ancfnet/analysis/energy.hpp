#pragma once
/// @file Energy accounting of a run.

namespace ancfnet {

/// Energies of the whole system (J). `work` is the work done by external loads other than
/// gravity (gravity has the potential `gravity`); `dissipated` is the energy taken by material
/// damping. For a consistent run, kinetic + strain + gravity + dissipated − work stays constant
/// (numerical dissipation of the integrator shows up as a drift of this balance).
struct EnergyAccount {
  double kinetic = 0.0;
  double strain = 0.0;
  double gravity = 0.0;
  double work = 0.0;
  double dissipated = 0.0;
  double Balance() const { return kinetic + strain + gravity + dissipated - work; }
};

}  // namespace ancfnet
