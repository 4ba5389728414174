#include "ancfnet/forces/clearance_joint_forces.hpp"

#include <cmath>

#include "ancfnet/forces/impact_speed.hpp"

namespace ancfnet {
namespace {

// Block g of a joint's group (the journal's blocks, then the bearing's): its anchor, its index
// there and whether it is the bearing's.
struct JointBlock {
  const AnchorMotion* anchor;
  int k;
  bool bearing;
};

JointBlock BlockOf(const ClearanceJointState& s, int g) {
  const int n = s.journal.num_blocks;
  return g < n ? JointBlock{&s.journal, g, false} : JointBlock{&s.bearing, g - n, true};
}

int NumBlocks(const ClearanceJointState& s) { return s.journal.num_blocks + s.bearing.num_blocks; }

// The force and moment that act on one side: (f, m_J) on the journal, (−f, m_B) on the bearing.
Vector3d SideForce(const Vector3d& f, bool bearing) { return bearing ? Vector3d(-f) : f; }

// ∂(f_side, m_side)/∂(q_l or v_l) of block l, from ∂(f, m_J, m_B)/∂z (z = c, ċ, ω of each side).
struct SideDerivative {
  Matrix3d force, moment;
};

SideDerivative Select(const Matrix9x3d& d, bool bearing) {
  if (bearing) return {-d.topRows<3>(), d.bottomRows<3>()};
  return {d.topRows<3>(), d.middleRows<3>(3)};
}

}  // namespace

ClearanceJointState CalcClearanceJointState(const Model& model, Index j, const VectorXd& q,
                                            const VectorXd& v,
                                            const std::vector<Matrix3d>& rotation,
                                            const ContactPairHistory& history, bool with_jacobian,
                                            double step) {
  const ClearanceJoint& joint = model.clearance_joints()[j];
  ClearanceJointState s;
  s.journal = CalcAnchorMotion(model, joint.journal, q, v, rotation);
  s.bearing = CalcAnchorMotion(model, joint.bearing, q, v, rotation);
  s.contact = CalcClearanceContact(joint, s.journal, s.bearing, std::abs(history.speed),
                                   history.bristle, step, with_jacobian);
  if (s.contact.touching) {
    const double v0 = std::max(history.speed, joint.normal.min_approach_speed);
    s.mode = std::abs(s.contact.rate) > 0.1 * v0 ? ClearanceMode::kImpact : ClearanceMode::kContact;
  }
  return s;
}

void AddClearanceJointForces(const Model& model, const VectorXd& q, const VectorXd& v,
                             Workspace& ws) {
  const auto& joints = model.clearance_joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const ClearanceJointState s =
        CalcClearanceJointState(model, static_cast<Index>(j), q, v, ws.body_rotation,
                                ws.joint_history[j], /*with_jacobian=*/false, ws.joint_step);
    const ClearanceContact& c = s.contact;
    if (!c.touching) continue;
    for (int g = 0; g < NumBlocks(s); ++g) {
      const auto [anchor, k, bearing] = BlockOf(s, g);
      const Index dof = anchor->dof[k];
      ws.internal_force.segment<3>(dof) -= anchor->GeneralizedForce(
          k, SideForce(c.force, bearing), bearing ? c.bearing_moment : c.journal_moment);
      ws.viscous_force.segment<3>(dof) -= anchor->GeneralizedForce(
          k, SideForce(c.dissipative_force, bearing),
          bearing ? c.dissipative_bearing_moment : c.dissipative_journal_moment);
    }
  }
}

double CalcClearanceJointEnergy(const Model& model, const VectorXd& q,
                                const std::vector<Matrix3d>& rotation) {
  double energy = 0.0;
  for (const ClearanceJoint& joint : model.clearance_joints()) {
    const Vector3d e = CalcEccentricity(joint, CalcAnchorCenter(model, joint.journal, q, rotation),
                                        CalcAnchorCenter(model, joint.bearing, q, rotation));
    energy += joint.normal.CalcElasticEnergy(e.norm() - joint.clearance);
  }
  return energy;
}

void AddClearanceJointJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                                const IterationWeights& weights, const Workspace& ws,
                                SystemMatrix* matrix) {
  const auto& joints = model.clearance_joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const ClearanceJointState s =
        CalcClearanceJointState(model, static_cast<Index>(j), q, v, ws.body_rotation,
                                ws.joint_history[j], /*with_jacobian=*/true, ws.joint_step);
    const ClearanceContact& c = s.contact;
    if (!c.touching) continue;
    const int blocks = NumBlocks(s);
    for (int h = 0; h < blocks; ++h) {
      // ∂(f, m_J, m_B)/∂q_h and /∂v_h through the centre, velocity and rotation of h's side.
      const auto [col, l, col_bearing] = BlockOf(s, h);
      const double sign = col_bearing ? -1.0 : 1.0;
      const Matrix9x3d& d_omega = col_bearing ? c.d_bearing_omega : c.d_journal_omega;
      Matrix9x3d d_q =
          sign * (c.d_center * col->a[l] + c.d_velocity * col->c[l]) + d_omega * col->d[l];
      // The bristle turns with a body bearing by θ_B = Σ B_l δq_l (B_ψ = R, B_x = 0).
      if (col_bearing) d_q += c.d_bearing_rotation * col->b[l];
      const Matrix9x3d d_v = sign * c.d_velocity * col->a[l] + d_omega * col->b[l];
      for (int g = 0; g < blocks; ++g) {
        const auto [row, k, row_bearing] = BlockOf(s, g);
        const SideDerivative dq = Select(d_q, row_bearing);
        const SideDerivative dv = Select(d_v, row_bearing);
        Matrix3d stiffness = row->a[k].transpose() * dq.force + row->b[k].transpose() * dq.moment;
        if (row == col)
          stiffness += row->GeometricStiffness(k, l, SideForce(c.force, row_bearing),
                                               row_bearing ? c.bearing_moment : c.journal_moment);
        const Matrix3d damping =
            row->a[k].transpose() * dv.force + row->b[k].transpose() * dv.moment;
        matrix->AddClearanceJointBlock(static_cast<Index>(j), g, h,
                                       weights.stiffness * stiffness + weights.damping * damping,
                                       -1.0);
      }
    }
  }
}

void UpdateClearanceJointHistory(const Model& model, const VectorXd& q, const VectorXd& v,
                                 const std::vector<Matrix3d>& rotation, double step,
                                 std::vector<ContactPairHistory>* history) {
  const auto& joints = model.clearance_joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    ContactPairHistory& stored = (*history)[j];
    const ClearanceJointState s =
        CalcClearanceJointState(model, static_cast<Index>(j), q, v, rotation, stored, false, step);
    // The bristle at the end of the step, from the history at its start (zero while apart).
    stored.bristle = s.contact.bristle;
    // δ̇ = n·u also in free flight, with n along the eccentricity.
    const Vector3d& e = s.contact.eccentricity;
    const double closing =
        e.norm() > 0.0 ? std::max(e.normalized().dot(s.journal.velocity - s.bearing.velocity), 0.0)
                       : 0.0;
    UpdateImpactSpeed(s.contact.touching, closing, joints[j].normal.min_approach_speed, &stored);
  }
}

}  // namespace ancfnet
