#include "ancfnet/forces/link_forces.hpp"

#include "ancfnet/forces/spring_damper.hpp"

namespace ancfnet {
namespace {

// σ_b w_b of block b of a link, blocks numbered first point's then second point's.
double SignedWeight(const SpringDamperLink& link, int b) {
  const int n1 = link.first.num_blocks;
  return b < n1 ? -link.first.weight[b] : link.second.weight[b - n1];
}

Index BlockDof(const SpringDamperLink& link, int b) {
  const int n1 = link.first.num_blocks;
  return b < n1 ? link.first.dof[b] : link.second.dof[b - n1];
}

int NumBlocks(const SpringDamperLink& link) {
  return link.first.num_blocks + link.second.num_blocks;
}

// Relative position d = r₂ − r₁ (or velocity, given velocities).
Vector3d Relative(const SpringDamperLink& link, const VectorXd& x) {
  return Model::Locate(link.second, x) - Model::Locate(link.first, x);
}

}  // namespace

void AddLinkForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws) {
  const auto& links = model.links();
  for (std::size_t l = 0; l < links.size(); ++l) {
    if (ws.link_broken[l]) continue;
    const SpringDamperLink& link = links[l];
    const Vector3d d = Relative(link, q);
    const Vector3d d_dot = Relative(link, v);
    const Vector3d force = CalcSpringDamper(link.law, link.natural_length, d, d_dot).force_on_2;
    const Vector3d elastic =
        CalcSpringDamper(link.law, link.natural_length, d, Vector3d::Zero()).force_on_2;
    for (int b = 0; b < NumBlocks(link); ++b) {
      const double w = SignedWeight(link, b);
      ws.internal_force.segment<3>(BlockDof(link, b)) -= w * force;
      ws.viscous_force.segment<3>(BlockDof(link, b)) -= w * (force - elastic);
    }
  }
}

void AddLinkJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                      const IterationWeights& weights, const Workspace& ws, SystemMatrix* matrix) {
  const auto& links = model.links();
  for (std::size_t l = 0; l < links.size(); ++l) {
    if (ws.link_broken[l]) continue;
    const SpringDamperLink& link = links[l];
    const auto out =
        CalcSpringDamper(link.law, link.natural_length, Relative(link, q), Relative(link, v));
    const Matrix3d jacobian = weights.stiffness * out.stiffness + weights.damping * out.damping;
    for (int i = 0; i < NumBlocks(link); ++i)
      for (int j = 0; j < NumBlocks(link); ++j)
        matrix->AddLinkBlock(static_cast<Index>(l), i, j, jacobian,
                             -SignedWeight(link, i) * SignedWeight(link, j));
  }
}

double CalcLinkEnergy(const SpringDamperLink& link, const VectorXd& q) {
  return CalcSpringDamper(link.law, link.natural_length, Relative(link, q), Vector3d::Zero())
      .energy;
}

double CalcLinkEnergy(const Model& model, const Workspace& ws, const VectorXd& q) {
  double energy = 0.0;
  for (std::size_t l = 0; l < model.links().size(); ++l)
    if (!ws.link_broken[l]) energy += CalcLinkEnergy(model.links()[l], q);
  return energy;
}

SpringDamperResult CalcLinkState(const SpringDamperLink& link, const VectorXd& q,
                                 const VectorXd& v) {
  return CalcSpringDamper(link.law, link.natural_length, Relative(link, q), Relative(link, v));
}

}  // namespace ancfnet
