#include "ancfnet/analysis/energy_tracker.hpp"

#include "ancfnet/forces/body_forces.hpp"
#include "ancfnet/forces/clearance_joint_forces.hpp"
#include "ancfnet/forces/link_forces.hpp"
#include "ancfnet/forces/orbital_frame.hpp"
#include "ancfnet/forces/section_lock_forces.hpp"

namespace ancfnet {

double CalcKineticEnergy(const Model& model, const Workspace& ws, const VectorXd& v) {
  double energy = 0.0;
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const Vector12d ve = model.Gather(model.elements()[e], v);
    energy += 0.5 * ve.dot(ws.element_mass[e] * ve);
  }
  // The spin of beam sections (their translation is in element_mass of the centre line).
  for (std::size_t b = 0; b < model.beam_elements().size(); ++b) {
    const Vector24d vb = model.Gather(model.beam_elements()[b], v);
    energy += 0.5 * vb.dot(ws.beam_rotary_mass[b] * vb);
  }
  for (const PointMass& point : model.point_masses())
    energy += 0.5 * point.mass * v.segment<3>(point.dof).squaredNorm();
  return energy + CalcBodyKineticEnergy(model, v);
}

double CalcStrainEnergy(const Model& model, const Workspace& ws, const VectorXd& q) {
  double energy = 0.0;
  for (const CableElement& element : model.elements())
    if (element.beam < 0)
      energy += CalcCableStrainEnergy(element.parameters, model.Gather(element, q));
  for (const BeamElement& beam : model.beam_elements())
    energy += CalcBeamStrainEnergy(beam.parameters, model.Gather(beam, q));
  return energy + CalcLinkEnergy(model, ws, q) + CalcSectionLockEnergy(model, q) +
         CalcAttachmentEnergy(model, ws, q) + ws.contact_energy +
         CalcClearanceJointEnergy(model, q, ws.body_rotation);
}

EnergyTracker::EnergyTracker(const Model& model, const Workspace& ws, const State& state,
                             double load_factor, EnergyQuadrature quadrature)
    : t_(state.t),
      q_(state.q),
      applied_(ws.applied_force),
      drive_(ws.drive_force),
      load_factor_(load_factor),
      quadrature_(quadrature),
      v_(state.v),
      viscous_(ws.viscous_force) {
  for (const RigidBody& body : model.rigid_bodies())
    if (body.motion == BodyMotion::kFree)
      for (int k = 0; k < 3; ++k) rebased_.push_back(body.rotation_dof() + k);
  account_.strain = CalcStrainEnergy(model, ws, state.q);
  // Gravity and the tidal potential of an orbital frame; "0.0 −" gives +0, not −0, without them.
  account_.gravity =
      0.0 - load_factor * ws.gravity_force.dot(state.q) + CalcOrbitalPotential(model, ws, state.q);
}

void EnergyTracker::Advance(const Model& model, const Workspace& ws, const State& state,
                            double load_factor) {
  const VectorXd& q = state.q;
  // ∫ Q · dq ≈ (w_n Q_n + w_{n+1} Q_{n+1}) · (q_{n+1} − q_n): trapezoidal w = (½, ½); midpoint
  // w = (0, 1), `ws` then holding Q_{n+½}.
  const bool midpoint = quadrature_ == EnergyQuadrature::kMidpoint;
  const double w_then = midpoint ? 0.0 : 0.5;
  const double w_now = 1.0 - w_then;
  double work = 0.0;
  double dissipated = 0.0;
  const auto add = [&](Index i, double dq) {
    work +=
        (w_then * (applied_[i] + drive_[i]) + w_now * (ws.applied_force[i] + ws.drive_force[i])) *
        dq;
    dissipated += (w_then * viscous_[i] + w_now * ws.viscous_force[i]) * dq;
  };
  for (Index i = 0; i < q.size(); ++i) add(i, q[i] - q_[i]);
  // A free body's ψ is back at 0 after the rebase: its increment is h (ω_n + ω_{n+1})/2 (exact for
  // the midpoint rule, whose ψ_{n+1} = h ω_{n+½}).
  const double h = state.t - t_;
  for (Index i : rebased_) add(i, 0.5 * h * (v_[i] + state.v[i]) - (q[i] - q_[i]));
  // A growing gravity load (static load stepping) changes V = −λ Q_gᵀq also through λ; that part,
  // −∫ Q_gᵀq dλ, is work put in by raising the load, so the balance stays constant.
  const double gravity_then = ws.gravity_force.dot(q_);
  const double gravity_now = ws.gravity_force.dot(q);
  work -= 0.5 * (gravity_then + gravity_now) * (load_factor - load_factor_);
  account_.work += work;
  account_.dissipated += dissipated;
  account_.kinetic = CalcKineticEnergy(model, ws, state.v);
  account_.strain = CalcStrainEnergy(model, ws, q);
  account_.gravity =
      0.0 - load_factor * ws.gravity_force.dot(q) + CalcOrbitalPotential(model, ws, q);
  t_ = state.t;
  q_ = q;
  v_ = state.v;
  load_factor_ = load_factor;
  applied_ = ws.applied_force;
  drive_ = ws.drive_force;
  viscous_ = ws.viscous_force;
}

void EnergyTracker::Release(const Model& model, const Workspace& ws, double released) {
  account_.dissipated += released;
  account_.strain = CalcStrainEnergy(model, ws, q_);
  applied_ = ws.applied_force;
  drive_ = ws.drive_force;
  viscous_ = ws.viscous_force;
}

void EnergyTracker::SaveCheckpoint(ArchiveWriter* out) const {
  account_.Save(out);
  out->Write(t_);
  out->Write(load_factor_);
  for (const VectorXd* v : {&q_, &applied_, &drive_, &v_, &viscous_}) out->Write(*v);
}

void EnergyTracker::LoadCheckpoint(ArchiveReader* in) {
  account_.Load(in);
  t_ = in->Read<double>();
  load_factor_ = in->Read<double>();
  for (VectorXd* v : {&q_, &applied_, &drive_, &v_, &viscous_}) {
    const Index size = v->size();
    in->Read(v);
    if (v->size() != size) in->Fail("an energy account of the wrong length for this scene");
  }
}

}  // namespace ancfnet
