#include "ancfnet/analysis/energy_tracker.hpp"

#include "ancfnet/assembly/link_forces.hpp"
#include "ancfnet/forces/orbital_frame.hpp"

namespace ancfnet {

double CalcKineticEnergy(const Model& model, const Workspace& ws, const VectorXd& v) {
  double energy = 0.0;
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const Vector12d ve = model.Gather(model.elements()[e], v);
    energy += 0.5 * ve.dot(ws.element_mass[e] * ve);
  }
  for (const PointMass& point : model.point_masses())
    energy += 0.5 * point.mass * v.segment<3>(point.dof).squaredNorm();
  return energy;
}

double CalcStrainEnergy(const Model& model, const Workspace& ws, const VectorXd& q) {
  double energy = 0.0;
  for (const CableElement& element : model.elements())
    energy += CalcCableStrainEnergy(element.parameters, model.Gather(element, q));
  return energy + CalcLinkEnergy(model, ws, q);
}

EnergyTracker::EnergyTracker(const Model& model, const Workspace& ws, const VectorXd& q,
                             double load_factor, ForceQuadrature quadrature)
    : q_(q),
      applied_(ws.applied_force),
      viscous_(ws.viscous_force),
      load_factor_(load_factor),
      quadrature_(quadrature) {
  account_.strain = CalcStrainEnergy(model, ws, q);
  // Gravity and the tidal potential of an orbital frame; "0.0 −" gives +0, not −0, without them.
  account_.gravity =
      0.0 - load_factor * ws.gravity_force.dot(q) + CalcOrbitalPotential(model, ws, q);
}

void EnergyTracker::Advance(const Model& model, const Workspace& ws, const VectorXd& q,
                            const VectorXd& v, double load_factor) {
  // ∫ Q · dq ≈ (w_n Q_n + w_{n+1} Q_{n+1}) · (q_{n+1} − q_n): trapezoidal w = (½, ½); midpoint
  // w = (0, 1), `ws` then holding Q_{n+½}.
  const double w_then = quadrature_ == ForceQuadrature::kTrapezoidal ? 0.5 : 0.0;
  const double w_now = 1.0 - w_then;
  double work = 0.0;
  double dissipated = 0.0;
  for (Index i = 0; i < q.size(); ++i) {
    const double dq = q[i] - q_[i];
    work += (w_then * applied_[i] + w_now * ws.applied_force[i]) * dq;
    dissipated += (w_then * viscous_[i] + w_now * ws.viscous_force[i]) * dq;
  }
  // A growing gravity load (static load stepping) changes V = −λ Q_gᵀq also through λ; that part,
  // −∫ Q_gᵀq dλ, is work put in by raising the load, so the balance stays constant.
  const double gravity_then = ws.gravity_force.dot(q_);
  const double gravity_now = ws.gravity_force.dot(q);
  work -= 0.5 * (gravity_then + gravity_now) * (load_factor - load_factor_);
  account_.work += work;
  account_.dissipated += dissipated;
  account_.kinetic = CalcKineticEnergy(model, ws, v);
  account_.strain = CalcStrainEnergy(model, ws, q);
  account_.gravity =
      0.0 - load_factor * ws.gravity_force.dot(q) + CalcOrbitalPotential(model, ws, q);
  q_ = q;
  load_factor_ = load_factor;
  applied_ = ws.applied_force;
  viscous_ = ws.viscous_force;
}

void EnergyTracker::Release(const Model& model, const Workspace& ws, double released) {
  account_.dissipated += released;
  account_.strain = CalcStrainEnergy(model, ws, q_);
  applied_ = ws.applied_force;
  viscous_ = ws.viscous_force;
}

}  // namespace ancfnet
