#pragma once
/// @file Energy accounting of a run.

#include "ancfnet/common/binary_archive.hpp"

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

  /// Writes the five energies to a checkpoint.
  void Save(ArchiveWriter* out) const {
    for (double e : {kinetic, strain, gravity, work, dissipated}) out->Write(e);
  }
  /// Reads what Save wrote.
  void Load(ArchiveReader* in) {
    for (double* e : {&kinetic, &strain, &gravity, &work, &dissipated}) *e = in->Read<double>();
  }
};

}  // namespace ancfnet
