#pragma once
// A straight chain of ANCF beam elements (elements/ancf_beam.hpp) and a load-stepping Newton
// solver for its statics, for the beam verification cases until beams are wired into the Model.
// Node n has the coordinates q[12n, 12n + 12) = (r, r_x, r_y, r_z).

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <functional>
#include <stdexcept>
#include <vector>

#include "ancfnet/elements/ancf_beam.hpp"
#include "ancfnet/model/beam_section.hpp"

namespace ancfnet::test {

struct BeamChain {
  BeamElementParameters element;  // every element alike
  int elements = 0;
  VectorXd q;  // reference, then the solution
};

// `elements` equal elements along x from the origin, d₂ = e_y, d₃ = e_z.
inline BeamChain MakeStraightBeamChain(const BeamMaterial& material, const BeamSection& section,
                                       double length, int elements) {
  BeamChain chain{MakeBeamElementParameters(material, section, length / elements), elements,
                  VectorXd::Zero(kBeamNodeDofs * (elements + 1))};
  for (int n = 0; n <= elements; ++n) {
    auto node = chain.q.segment<kBeamNodeDofs>(kBeamNodeDofs * n);
    node.segment<3>(0) = Vector3d(length * n / elements, 0.0, 0.0);
    node.segment<3>(3) = Vector3d::UnitX();
    node.segment<3>(6) = Vector3d::UnitY();
    node.segment<3>(9) = Vector3d::UnitZ();
  }
  return chain;
}

// External load: adds λ·f(q) to `force` and λ·∂f/∂q to `jacobian` (dense, for the few loaded
// coordinates: triplets appended).
using BeamLoad = std::function<void(const VectorXd& q, double lambda, VectorXd& force,
                                    std::vector<Eigen::Triplet<double>>& jacobian)>;

// Solves F_int(q) = λ f(q) for λ = 1/steps, 2/steps, …, 1 by Newton's method with the
// coordinates listed in `fixed` held at their reference values. Throws if a step fails to
// converge to |Δq| ≤ 1e-10 |q| in 30 iterations.
inline void SolveBeamStatics(BeamChain& chain, const std::vector<int>& fixed, const BeamLoad& load,
                             int steps) {
  const Index n = chain.q.size();
  std::vector<bool> is_fixed(n, false);
  for (const int i : fixed) is_fixed[i] = true;
  for (int step = 1; step <= steps; ++step) {
    const double lambda = static_cast<double>(step) / steps;
    bool converged = false;
    for (int iteration = 0; iteration < 30 && !converged; ++iteration) {
      VectorXd residual = VectorXd::Zero(n);
      std::vector<Eigen::Triplet<double>> triplets;
      for (int el = 0; el < chain.elements; ++el) {
        const Index offset = kBeamNodeDofs * el;
        Vector24d f;
        Matrix24d k;
        CalcBeamInternalForce(chain.element, chain.q.segment<kBeamElementDofs>(offset),
                              Vector24d::Zero(), {.force = &f, .stiffness = &k});
        residual.segment<kBeamElementDofs>(offset) += f;
        for (int i = 0; i < kBeamElementDofs; ++i)
          for (int j = 0; j < kBeamElementDofs; ++j)
            triplets.emplace_back(offset + i, offset + j, k(i, j));
      }
      VectorXd external = VectorXd::Zero(n);
      std::vector<Eigen::Triplet<double>> load_jacobian;
      load(chain.q, lambda, external, load_jacobian);
      residual -= external;
      for (const auto& t : load_jacobian) triplets.emplace_back(t.row(), t.col(), -t.value());
      std::vector<Eigen::Triplet<double>> free_triplets;
      for (const auto& t : triplets)
        if (!is_fixed[t.row()] && !is_fixed[t.col()]) free_triplets.push_back(t);
      for (Index i = 0; i < n; ++i)
        if (is_fixed[i]) {
          free_triplets.emplace_back(i, i, 1.0);
          residual[i] = 0.0;
        }
      SparseMatrixd tangent(n, n);
      tangent.setFromTriplets(free_triplets.begin(), free_triplets.end());
      Eigen::SparseLU<SparseMatrixd> lu(tangent);
      if (lu.info() != Eigen::Success) throw std::runtime_error("singular beam tangent");
      const VectorXd dq = lu.solve(-residual);
      chain.q += dq;
      converged = dq.norm() <= 1e-10 * chain.q.norm();
    }
    if (!converged) throw std::runtime_error("beam statics: Newton did not converge");
  }
}

// Coordinates of node n's block (0: r, 1: r_x, 2: r_y, 3: r_z) component c.
inline int BeamDof(int node, int block, int component) {
  return kBeamNodeDofs * node + 3 * block + component;
}

// The clamp of node 0: position and both directors held; r_x stays free (shear).
inline std::vector<int> ClampFirstNode() {
  std::vector<int> fixed;
  for (const int block : {0, 2, 3})
    for (int c = 0; c < 3; ++c) fixed.push_back(BeamDof(0, block, c));
  return fixed;
}

}  // namespace ancfnet::test
