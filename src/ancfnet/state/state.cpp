#include "ancfnet/state/state.hpp"

#include "ancfnet/model/contact_probes.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

State MakeInitialState(const Model& model) {
  State state;
  state.q = model.initial_positions();
  state.v = model.initial_velocities();
  state.a = VectorXd::Zero(model.num_dofs());
  state.link_broken.assign(model.links().size(), 0);
  state.contact_history.assign(static_cast<std::size_t>(CountContactPairs(model)), {});
  state.joint_history.assign(model.clearance_joints().size(), {});
  state.multipliers = VectorXd::Zero(model.num_constraint_equations());
  for (const RigidBody& body : model.rigid_bodies())
    state.body_rotation.push_back(body.initial_orientation);
  return state;
}

}  // namespace ancfnet
