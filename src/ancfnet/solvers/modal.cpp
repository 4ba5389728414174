#include "ancfnet/solvers/modal.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/solvers/damping_model.hpp"
#include "ancfnet/solvers/linear_solver.hpp"
#include "ancfnet/solvers/system_forces.hpp"

namespace ancfnet {
namespace {

// Sparse, symmetrised matrices over the unknowns, and the ideal joints' constraints (none
// when the model has no ideal joints).
struct LinearSystem {
  SparseMatrixd stiffness, damping, mass;
  std::optional<JointConstraints> constraints;
};

// y = (K − σ M)⁻¹ x with one sparse factorisation per shift (KLU), for Spectra. With ideal
// joints y solves the bordered system [K − σM  Gᵀ; G  0] (y, μ) = (x, 0): y lies in the null
// space of G, and (K − σM)⁻¹ M becomes the shift-invert operator of the pencil (K, M)
// restricted to the motions the joints allow (Géradin & Cardona 2001). It is self-adjoint in
// the M inner product, so Lanczos applies; its m zero eigenvalues (ω² = ∞) are never among the
// largest.
class ShiftInvertOperator {
 public:
  using Scalar = double;
  ShiftInvertOperator(LinearSystem& system, const DofMap& dofs) : system_(system), dofs_(dofs) {}
  Eigen::Index rows() const { return system_.stiffness.rows(); }
  Eigen::Index cols() const { return system_.stiffness.cols(); }
  void set_shift(double sigma) {
    shifted_ = system_.stiffness - sigma * system_.mass;
    const SparseMatrixd* a = &shifted_;
    if (system_.constraints) {
      system_.constraints->AssembleBorderedMatrix(shifted_, dofs_, &bordered_);
      a = &bordered_;
    }
    if (!solver_.Factorize(*a))
      throw SolverError(
          fmt::format("K − σM is singular at σ = {:.6g}: choose another shift", sigma), 0.0);
    x_ = VectorXd::Zero(a->rows());
    y_.resize(a->rows());
  }
  void perform_op(const double* x_in, double* y_out) const {
    x_.head(rows()) = Eigen::Map<const VectorXd>(x_in, rows());
    solver_.Solve(x_, &y_);
    Eigen::Map<VectorXd>(y_out, rows()) = y_.head(rows());
  }

 private:
  LinearSystem& system_;
  const DofMap& dofs_;
  SparseMatrixd shifted_;
  SparseMatrixd bordered_;
  mutable SparseLinearSolver solver_;
  mutable VectorXd x_, y_;
};

struct Eigenpairs {
  bool converged = false;
  VectorXd values;   // ω², ascending
  MatrixXd vectors;  // over the unknowns, M-normalised
};

Eigenpairs SolveShiftInvert(LinearSystem& system, const DofMap& dofs, int num_modes, double sigma,
                            double tolerance, int subspace_factor = 1) {
  ShiftInvertOperator op(system, dofs);
  Spectra::SparseSymMatProd<double> m_op(system.mass);
  const Eigen::Index n = system.stiffness.rows();
  const Eigen::Index ncv =
      std::min<Eigen::Index>(n, subspace_factor * std::max(2 * num_modes + 1, 20));
  Spectra::SymGEigsShiftSolver<ShiftInvertOperator, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, m_op, num_modes, ncv, sigma);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, tolerance, Spectra::SortRule::SmallestAlge);
  Eigenpairs result;
  result.converged = solver.info() == Spectra::CompInfo::Successful;
  if (!result.converged) return result;
  result.values = solver.eigenvalues();
  result.vectors = solver.eigenvectors();
  return result;
}

LinearSystem Linearise(const Model& model, const DofMap& dofs, const VectorXd& q,
                       const DampingModel* damping) {
  if (model.has_free_bodies())
    throw InputError(
        "modal analysis: the model has a free rigid body (its rotation coordinates are not "
        "linearised); make the bodies fixed (motion: fixed)");
  if (!model.contact().targets.empty() || model.contact().self_contact)
    throw InputError(
        "modal analysis: the scene has contact (targets or self_contact), which the linearisation "
        "does not include; remove the contact section to find the free modes");
  // K and C are the Jacobian of the forces every analysis takes (SystemForces) at rest in the
  // configuration q. Its own damping model is left out: the caller's (possibly none) is the one
  // whose modes are asked for.
  Workspace ws(model);
  SystemForces forces(model, ws, /*near_factor=*/1.0, /*with_damping=*/false);
  SystemMatrix matrix(model, dofs);
  const VectorXd rest = VectorXd::Zero(model.num_dofs());
  const std::vector<ContactPairHistory> no_contact;
  auto assemble = [&](const IterationWeights& weights) {
    forces.AssembleIterationMatrix(q, rest, no_contact, weights, 1.0, ws, &matrix);
  };
  LinearSystem system;
  assemble({.mass = 0.0, .damping = 0.0, .stiffness = 1.0});
  system.stiffness = 0.5 * (matrix.matrix() + SparseMatrixd(matrix.matrix().transpose()));
  assemble({.mass = 0.0, .damping = 1.0, .stiffness = 0.0});
  if (damping) damping->AddRayleighJacobian(1.0, &matrix);
  system.damping = matrix.matrix();
  AssembleMassMatrix(model, ws, &matrix);
  system.mass = matrix.matrix();
  if (model.num_constraint_equations() > 0) {
    // The joints' Hessian λ ∂²g/∂q² would add to K; it vanishes here: g is linear in the
    // coordinates of cable points and point masses, and every body is fixed or prescribed (free
    // bodies are refused above), so the nonlinear terms, all in body rotations, act on no
    // unknown. G alone restricts the modes.
    system.constraints.emplace(model);
    system.constraints->Evaluate(q, rest, MakeInitialState(model).body_rotation);
  }
  return system;
}

// ζ of each mode from the eigenvalues of the first-order form of ÿ + Φᵀ C Φ ẏ + Λ y = 0.
VectorXd CalcDampingRatios(const MatrixXd& c, const VectorXd& omega,
                           const std::vector<bool>& rigid) {
  const Eigen::Index k = omega.size();
  VectorXd zeta = VectorXd::Zero(k);
  if (c.norm() == 0.0) {
    for (Eigen::Index i = 0; i < k; ++i) zeta[i] = rigid[i] ? std::nan("") : 0.0;
    return zeta;
  }
  MatrixXd a = MatrixXd::Zero(2 * k, 2 * k);
  a.topRightCorner(k, k).setIdentity();
  a.bottomLeftCorner(k, k) = (-omega.array().square()).matrix().asDiagonal();
  a.bottomRightCorner(k, k) = -c;
  const Eigen::VectorXcd s = Eigen::EigenSolver<MatrixXd>(a, false).eigenvalues();
  std::vector<bool> used(s.size(), false);
  for (Eigen::Index i = 0; i < k; ++i) {
    if (rigid[i]) {
      zeta[i] = std::nan("");
      continue;
    }
    // The eigenvalue of positive imaginary part (or real, overdamped) nearest the undamped one.
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < s.size(); ++j) {
      if (used[j] || s[j].imag() < 0.0) continue;
      if (best < 0 || std::abs(std::abs(s[j]) - omega[i]) < std::abs(std::abs(s[best]) - omega[i]))
        best = j;
    }
    if (best < 0) continue;
    used[best] = true;
    zeta[i] = -s[best].real() / std::abs(s[best]);
  }
  return zeta;
}

UndampedModes SolveUndamped(const Model& model, const DofMap& dofs, LinearSystem& system,
                            const ModalSettings& settings) {
  const Index n = dofs.num_unknowns();
  // The joints take one degree of freedom per constraint equation.
  const Index m = system.constraints ? system.constraints->size() : 0;
  if (settings.num_modes < 1 || settings.num_modes >= n - m)
    throw InputError(fmt::format("modes: asked for {} of a model with {} unknowns{} (1 … {})",
                                 settings.num_modes, n,
                                 m > 0 ? fmt::format(" and {} joint constraints", m) : "",
                                 n - m - 1));
  const double scale = system.stiffness.diagonal().cwiseAbs().maxCoeff() /
                       system.mass.diagonal().cwiseAbs().maxCoeff();
  double sigma = settings.shift;
  if (sigma == 0.0) {
    // A first pass with a shift far below any elastic eigenvalue of the model finds the lowest
    // one; the real solve then shifts to just below it, where Lanczos converges fast.
    const Eigenpairs probe =
        SolveShiftInvert(system, dofs, 1, -1e-12 * scale, settings.tolerance);
    const double lowest = probe.converged ? std::max(probe.values[0], 0.0) : 0.0;
    sigma = lowest > 1e-10 * scale ? -0.5 * lowest : -1e-6 * scale;
  }
  // Clustered eigenvalues (a slack rope's or net's near-mechanisms, far below |σ|) are poorly
  // separated by the transformation: retry with a larger Krylov subspace, then with the shift
  // moved towards them.
  Eigenpairs pairs;
  for (const auto& [factor, move] : {std::pair{1, 1.0}, {3, 1.0}, {3, 1e-4}, {3, 1e-8}}) {
    if (settings.shift != 0.0 && move != 1.0) break;  // the user's shift stays
    pairs = SolveShiftInvert(system, dofs, settings.num_modes, sigma * move, settings.tolerance,
                             factor);
    if (pairs.converged) break;
  }
  UndampedModes modes;
  if (!pairs.converged) {
    modes.message = fmt::format("the eigensolver did not converge for {} modes at σ = {:.6g}",
                                settings.num_modes, sigma);
    return modes;
  }
  modes.converged = true;
  modes.omega_squared = pairs.values;
  // Rigid modes: ω² at the round-off of K, far below any elastic one.
  modes.rigid.assign(pairs.values.size(), false);
  for (Eigen::Index i = 0; i < pairs.values.size(); ++i)
    modes.rigid[i] = std::abs(pairs.values[i]) <= 1e-9 * scale;
  modes.shapes = MatrixXd::Zero(model.num_dofs(), pairs.values.size());
  for (Index u = 0; u < n; ++u) modes.shapes.row(dofs.coordinates()[u]) = pairs.vectors.row(u);
  return modes;
}

}  // namespace

UndampedModes CalcUndampedModes(const Model& model, const VectorXd& q,
                                const ModalSettings& settings) {
  const DofMap dofs = DofMap::FreeCoordinates(model);
  LinearSystem system = Linearise(model, dofs, q, nullptr);
  return SolveUndamped(model, dofs, system, settings);
}

ModalResult CalcModes(const Model& model, const VectorXd& q, const ModalSettings& settings) {
  const DofMap dofs = DofMap::FreeCoordinates(model);
  const DampingModel damping(model);
  LinearSystem system = Linearise(model, dofs, q, &damping);
  const UndampedModes undamped = SolveUndamped(model, dofs, system, settings);
  ModalResult result;
  result.message = undamped.message;
  if (!undamped.converged) return result;
  result.converged = true;
  result.rigid = undamped.rigid;
  result.omega = undamped.omega_squared.cwiseMax(0.0).cwiseSqrt();
  for (Eigen::Index i = 0; i < result.omega.size(); ++i)
    if (result.rigid[i]) result.omega[i] = 0.0;
  result.frequency_hz = result.omega / (2.0 * std::numbers::pi);
  result.shapes = undamped.shapes;
  // Φᵀ C Φ over the unknowns, plus the dense modal damping matrix.
  MatrixXd free_shapes(dofs.num_unknowns(), result.shapes.cols());
  for (Index u = 0; u < dofs.num_unknowns(); ++u)
    free_shapes.row(u) = result.shapes.row(dofs.coordinates()[u]);
  const MatrixXd projected = free_shapes.transpose() * (system.damping * free_shapes) +
                             damping.ProjectModal(result.shapes);
  result.damping_ratio = CalcDampingRatios(projected, result.omega, result.rigid);
  return result;
}

}  // namespace ancfnet
