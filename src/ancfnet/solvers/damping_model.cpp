#include "ancfnet/solvers/damping_model.hpp"

#include <fmt/format.h>

#include <numbers>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/elements/ancf_cable.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/solvers/modal.hpp"

namespace ancfnet {
namespace {

// ws.internal_force and ws.viscous_force += C_e v_e over the coordinates of a cable or beam
// element.
template <class Element, int N>
void AddElementDampingForce(const Model& model, const Element& element,
                            const Eigen::Matrix<double, N, N>& damping, const VectorXd& v,
                            Workspace& ws) {
  const Eigen::Matrix<double, N, 1> f = damping * model.Gather(element, v);
  for (int i = 0; i < N; ++i) {
    ws.internal_force[element.dofs[i]] += f[i];
    ws.viscous_force[element.dofs[i]] += f[i];
  }
}

}  // namespace

DampingModel::DampingModel(const Model& model) : model_(model) {
  const DampingSpec& spec = model.damping();
  const VectorXd& q0 = model.initial_positions();
  if (spec.rayleigh.alpha != 0.0 || spec.rayleigh.beta != 0.0) {
    alpha_ = spec.rayleigh.alpha;
    const Vector12d rest = Vector12d::Zero();
    for (const CableElement& element : model.elements()) {
      if (element.beam >= 0) {
        element_rayleigh_.push_back(Matrix12d::Zero());
        continue;
      }
      Matrix12d stiffness;
      CalcCableInternalForce(element.parameters, model.Gather(element, q0), rest,
                             {.stiffness = &stiffness});
      element_rayleigh_.push_back(alpha_ * CalcCableMassMatrix(element.parameters) +
                                  spec.rayleigh.beta * stiffness);
    }
    for (const BeamElement& beam : model.beam_elements()) {
      Matrix24d stiffness;
      CalcBeamInternalForce(beam.parameters, model.Gather(beam, q0), Vector24d::Zero(),
                            {.stiffness = &stiffness});
      beam_rayleigh_.push_back(alpha_ * CalcBeamMassMatrix(beam.parameters) +
                               spec.rayleigh.beta * stiffness);
    }
  }
  const ModalDamping& modal = spec.modal;
  if (modal.num_modes == 0) return;
  // The lowest modes, rigid ones included, then the first num_modes elastic ones of them.
  const int rigid_allowance = 6;
  const Index unknowns = DofMap::FreeCoordinates(model).num_unknowns();
  const int wanted =
      static_cast<int>(std::min<Index>(modal.num_modes + rigid_allowance, unknowns - 1));
  const UndampedModes modes = CalcUndampedModes(model, q0, {.num_modes = wanted});
  if (!modes.converged)
    throw SolverError("modal damping: the modes of the reference configuration: " + modes.message,
                      0.0);
  std::vector<Index> elastic;
  for (Eigen::Index i = 0; i < modes.omega_squared.size(); ++i)
    if (!modes.rigid[i] && static_cast<int>(elastic.size()) < modal.num_modes) elastic.push_back(i);
  if (static_cast<int>(elastic.size()) < modal.num_modes)
    throw InputError(fmt::format("modal damping of {} modes: the model has only {} elastic modes",
                                 modal.num_modes, elastic.size()));
  Workspace ws(model);
  SystemMatrix mass(model, DofMap::AllCoordinates(model));
  AssembleMassMatrix(model, ws, &mass);
  modal_basis_.resize(model.num_dofs(), modal.num_modes);
  modal_coefficients_.resize(modal.num_modes);
  for (int j = 0; j < modal.num_modes; ++j) {
    const double omega = std::sqrt(modes.omega_squared[elastic[j]]);
    modal_basis_.col(j) = mass.matrix() * modes.shapes.col(elastic[j]);
    modal_coefficients_[j] = 2.0 * modal.Ratio(j, omega / (2.0 * std::numbers::pi)) * omega;
  }
  modal_coordinates_.resize(modal.num_modes);
  modal_force_.resize(model.num_dofs());
}

void DampingModel::AddForces(const VectorXd& v, Workspace& ws) const {
  for (std::size_t e = 0; e < element_rayleigh_.size(); ++e)
    AddElementDampingForce(model_, model_.elements()[e], element_rayleigh_[e], v, ws);
  for (std::size_t b = 0; b < beam_rayleigh_.size(); ++b)
    AddElementDampingForce(model_, model_.beam_elements()[b], beam_rayleigh_[b], v, ws);
  if (alpha_ != 0.0) {
    for (const PointMass& point : model_.point_masses()) {
      const Vector3d f = alpha_ * point.mass * v.segment<3>(point.dof);
      ws.internal_force.segment<3>(point.dof) += f;
      ws.viscous_force.segment<3>(point.dof) += f;
    }
  }
  if (modal_basis_.cols() == 0) return;
  // C v = B (d ∘ (Bᵀ v)), O(n k).
  modal_coordinates_.noalias() = modal_basis_.transpose() * v;
  modal_coordinates_.array() *= modal_coefficients_.array();
  modal_force_.noalias() = modal_basis_ * modal_coordinates_;
  ws.internal_force += modal_force_;
  ws.viscous_force += modal_force_;
}

void DampingModel::AddRayleighJacobian(double weight, SystemMatrix* matrix) const {
  if (weight == 0.0) return;
  for (std::size_t e = 0; e < element_rayleigh_.size(); ++e)
    matrix->AddElementBlock(static_cast<Index>(e), element_rayleigh_[e], weight);
  for (std::size_t b = 0; b < beam_rayleigh_.size(); ++b)
    matrix->AddBeamElementBlock(static_cast<Index>(b), beam_rayleigh_[b], weight);
  if (alpha_ != 0.0) {
    const auto& points = model_.point_masses();
    for (std::size_t i = 0; i < points.size(); ++i)
      matrix->AddPointMassBlock(static_cast<Index>(i), Matrix3d::Identity(),
                                weight * alpha_ * points[i].mass);
  }
}

MatrixXd DampingModel::ProjectModal(const MatrixXd& shapes) const {
  if (modal_basis_.cols() == 0) return MatrixXd::Zero(shapes.cols(), shapes.cols());
  const MatrixXd projected = modal_basis_.transpose() * shapes;  // k × k_s
  return projected.transpose() * modal_coefficients_.asDiagonal() * projected;
}

}  // namespace ancfnet
