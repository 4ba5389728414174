#include "ancfnet/analysis/probe.hpp"

namespace ancfnet {

std::vector<std::string> ProbeColumns(const Probe& probe) {
  const std::string& n = probe.name;
  switch (probe.quantity) {
    case ProbeQuantity::kPosition:
      return {n + ".x", n + ".y", n + ".z"};
    case ProbeQuantity::kVelocity:
      return {n + ".vx", n + ".vy", n + ".vz"};
    case ProbeQuantity::kEnergy:
      return {n + ".kinetic", n + ".strain", n + ".gravity", n + ".work", n + ".dissipated"};
  }
  return {};
}

void EvaluateProbe(const Probe& probe, const Model& /*model*/, const State& state,
                   const EnergyAccount& energy, std::vector<double>* values) {
  switch (probe.quantity) {
    case ProbeQuantity::kPosition:
    case ProbeQuantity::kVelocity: {
      const VectorXd& x = probe.quantity == ProbeQuantity::kPosition ? state.q : state.v;
      const Vector3d p = Model::Locate(probe.point, x);
      values->insert(values->end(), {p.x(), p.y(), p.z()});
      break;
    }
    case ProbeQuantity::kEnergy:
      values->insert(values->end(), {energy.kinetic, energy.strain, energy.gravity, energy.work,
                                     energy.dissipated});
      break;
  }
}

}  // namespace ancfnet
