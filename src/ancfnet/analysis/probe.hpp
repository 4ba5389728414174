#pragma once
/// @file Probes: named quantities recorded at every output step.

#include <string>
#include <vector>

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

enum class ProbeQuantity { kPosition, kVelocity, kEnergy };

/// A named probe. Position and velocity probes read a point (a cable material point or a point
/// mass); energy probes read the whole system (their point is unused).
struct Probe {
  std::string name;
  ProbeQuantity quantity = ProbeQuantity::kPosition;
  PointLocation point;
};

/// Column names of a probe: NAME.x/y/z, NAME.vx/vy/vz, or NAME.kinetic, NAME.strain,
/// NAME.gravity, NAME.work, NAME.dissipated.
std::vector<std::string> ProbeColumns(const Probe& probe);

/// Values of a probe in the order of ProbeColumns, appended to `values`.
void EvaluateProbe(const Probe& probe, const Model& model, const State& state,
                   const EnergyAccount& energy, std::vector<double>* values);

}  // namespace ancfnet
