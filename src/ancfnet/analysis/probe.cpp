#include "ancfnet/analysis/probe.hpp"

#include "ancfnet/analysis/net_metrics.hpp"

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
    case ProbeQuantity::kMouthArea:
      return {n + ".area"};
    case ProbeQuantity::kCentroid:
      return {n + ".x", n + ".y", n + ".z"};
    case ProbeQuantity::kDistance:
      return {n + ".distance"};
  }
  return {};
}

Vector3d CalcNetCentroid(const Model& model, const Net& net, const VectorXd& q) {
  std::vector<Vector3d> knots;
  for (Index knot : net.knots) knots.push_back(q.segment<3>(model.point_masses()[knot].dof));
  return CalcCentroid(knots);
}

void EvaluateProbe(const Probe& probe, const Model& model, const State& state,
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
    case ProbeQuantity::kMouthArea: {
      const Net& net = model.nets()[probe.net];
      std::vector<Vector3d> polygon;
      for (Index knot : net.perimeter) polygon.push_back(state.q.segment<3>(model.point_masses()[knot].dof));
      values->push_back(CalcMouthArea(polygon, net.axis));
      break;
    }
    case ProbeQuantity::kCentroid: {
      const Vector3d c = CalcNetCentroid(model, model.nets()[probe.net], state.q);
      values->insert(values->end(), {c.x(), c.y(), c.z()});
      break;
    }
    case ProbeQuantity::kDistance: {
      const Net& net = model.nets()[probe.net];
      values->push_back(
          CalcDistanceTravelled(probe.reference, CalcNetCentroid(model, net, state.q), net.axis));
      break;
    }
  }
}

}  // namespace ancfnet
