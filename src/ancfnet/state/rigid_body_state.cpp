#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {

BodyPose CalcBodyPose(const Model& model, const State& state, Index b) {
  return CalcBodyPose(model.rigid_bodies()[b], state.q, state.body_rotation[b]);
}

void RebaseBodyRotations(const Model& model, State* state) {
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].motion != BodyMotion::kFree) continue;
    auto psi = state->q.segment<3>(bodies[b].rotation_dof());
    // Through a unit quaternion, so that round-off does not accumulate in RᵀR = I.
    state->body_rotation[b] = Eigen::Quaterniond(state->body_rotation[b] * ExpRotation(psi))
                                  .normalized()
                                  .toRotationMatrix();
    psi.setZero();
  }
}

}  // namespace ancfnet
