// Google Benchmark timings of the kernels the time loop spends its time in: the ANCF cable
// element (internal force, its Jacobians, the mass matrix), the system-level force and iteration
// matrix assembly of a whole cable, and the KLU factorisation and solve of that matrix.
//
// Every kernel runs on a bent, moving configuration (a quarter-circle helix turning about y and
// stretching), so the axial, bending and Kelvin–Voigt terms all do their full work. Figures and
// how to reproduce them: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/elements/ancf_cable.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/integrators/generalized_alpha.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/solvers/linear_solver.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {
namespace {

// Kelvin–Voigt retardation time (s) of the damped variants.
constexpr double kDampingTime = 1e-3;

// The S2 pendulum cable (docs/benchmarks.md): L = 1 m, d = 0.01 m, E = 2e9 Pa, ρ = 1000 kg/m³,
// pinned at the origin, optionally with Kelvin–Voigt damping. Built through the public API.
Model MakeBenchCable(int elements, double damping_time) {
  const Material material{.youngs_modulus = 2.0e9,
                          .density = 1000.0,
                          .axial_damping_time = damping_time,
                          .bending_damping_time = damping_time};
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({.name = "cable",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = elements,
                    .properties = MakeCableProperties(material, MakeCircleSection(0.01))});
  builder.AddPin({"cable", 0.0});
  return builder.Build();
}

// Coordinates q and velocities v (node by node: r, r') of a straight cable of reference length
// `length` divided into `elements` elements, laid onto a helix of radius R = 2 length / π and
// pitch 0.1 R per radian, so the cable turns by a quarter circle, is stretched by 0.5 %, is
// curved in 3D, and starts at the origin. It moves as a rigid rotation ω = 2 rad/s about y plus a
// stretching at 1 %/s, so that strain rate and curvature rate are not zero either.
struct CableConfiguration {
  VectorXd q;
  VectorXd v;
};

CableConfiguration MakeBentConfiguration(int elements, double length) {
  const double radius = 2.0 * length / std::numbers::pi;
  const double pitch = 0.1 * radius;
  const double dtheta_ds = 0.5 * std::numbers::pi / length;
  const Vector3d omega(0.0, 2.0, 0.0);
  const double stretch_rate = 0.01;
  CableConfiguration c{VectorXd(kCableNodeDofs * (elements + 1)),
                       VectorXd(kCableNodeDofs * (elements + 1))};
  for (int node = 0; node <= elements; ++node) {
    const double theta = dtheta_ds * length * node / elements;
    const Vector3d r(radius * std::sin(theta), pitch * theta, radius * (std::cos(theta) - 1.0));
    const Vector3d slope =
        dtheta_ds * Vector3d(radius * std::cos(theta), pitch, -radius * std::sin(theta));
    c.q.segment<3>(kCableNodeDofs * node) = r;
    c.q.segment<3>(kCableNodeDofs * node + 3) = slope;
    c.v.segment<3>(kCableNodeDofs * node) = omega.cross(r) + stretch_rate * r;
    c.v.segment<3>(kCableNodeDofs * node + 3) = omega.cross(slope) + stretch_rate * slope;
  }
  return c;
}

// ---------------------------------------------------------------------------------------------
// Element kernels: one quarter-circle element of the S2 cable (L = 1 m). Argument: damped (0/1).

struct ElementCase {
  CableElementParameters parameters;
  Vector12d e;
  Vector12d e_dot;
};

ElementCase MakeElementCase(bool damped) {
  const Model model = MakeBenchCable(1, damped ? kDampingTime : 0.0);
  const CableConfiguration c = MakeBentConfiguration(1, 1.0);
  return {model.elements()[0].parameters, c.q, c.v};
}

// Forces only, the outputs CalcInternalForces asks for (residual evaluations).
void BM_CableForce(benchmark::State& state) {
  const ElementCase c = MakeElementCase(state.range(0) != 0);
  Vector12d force, viscous_force;
  for (auto _ : state) {
    CalcCableInternalForce(c.parameters, c.e, c.e_dot,
                           {.force = &force, .viscous_force = &viscous_force});
    benchmark::DoNotOptimize(force.data());
    benchmark::DoNotOptimize(viscous_force.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CableForce)->ArgName("damped")->Arg(0)->Arg(1);

// Forces and Jacobians, the outputs AssembleIterationMatrix asks for in dynamics: stiffness
// ∂Q/∂e and damping ∂Q/∂ė (the latter is zero, but still requested, when undamped).
void BM_CableForceAndJacobian(benchmark::State& state) {
  const ElementCase c = MakeElementCase(state.range(0) != 0);
  Vector12d force, viscous_force;
  Matrix12d stiffness, damping;
  for (auto _ : state) {
    CalcCableInternalForce(c.parameters, c.e, c.e_dot,
                           {.force = &force,
                            .viscous_force = &viscous_force,
                            .stiffness = &stiffness,
                            .damping = &damping});
    benchmark::DoNotOptimize(force.data());
    benchmark::DoNotOptimize(stiffness.data());
    benchmark::DoNotOptimize(damping.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CableForceAndJacobian)->ArgName("damped")->Arg(0)->Arg(1);

void BM_CableMassMatrix(benchmark::State& state) {
  const ElementCase c = MakeElementCase(false);
  for (auto _ : state) {
    Matrix12d mass = CalcCableMassMatrix(c.parameters);
    benchmark::DoNotOptimize(mass.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_CableMassMatrix);

// ---------------------------------------------------------------------------------------------
// System kernels: the S2 pendulum cable (undamped, as in bench/scenes/pendulum_*.yaml), bent as
// above, with the generalised-α weights of ρ∞ = 0.8, h = 1e-3 s. Argument: number of elements.

class CableSystem : public benchmark::Fixture {
 public:
  void SetUp(const benchmark::State& state) override {
    const int elements = static_cast<int>(state.range(0));
    model_ = std::make_unique<Model>(MakeBenchCable(elements, 0.0));
    config_ = MakeBentConfiguration(elements, 1.0);
    ws_ = std::make_unique<Workspace>(*model_);
    dofs_ = std::make_unique<DofMap>(DofMap::FreeCoordinates(*model_));
    matrix_ = std::make_unique<SystemMatrix>(*model_, *dofs_);
    const auto c = GeneralizedAlphaCoefficients::FromSpectralRadius(0.8);
    const double h = 1e-3;
    const double ratio = (1.0 - c.alpha_f) / (1.0 - c.alpha_m);
    weights_ = {.mass = 1.0, .damping = h * c.gamma * ratio, .stiffness = h * h * c.beta * ratio};
  }
  void TearDown(const benchmark::State&) override {
    matrix_.reset();
    dofs_.reset();
    ws_.reset();
    model_.reset();
  }

 protected:
  void Assemble() {
    AssembleIterationMatrix(*model_, config_.q, config_.v, weights_, 1.0, *ws_, matrix_.get());
  }

  std::unique_ptr<Model> model_;
  CableConfiguration config_;
  std::unique_ptr<Workspace> ws_;
  std::unique_ptr<DofMap> dofs_;
  std::unique_ptr<SystemMatrix> matrix_;
  IterationWeights weights_;
};

void SetCounters(benchmark::State& state, const Model& model) {
  state.counters["elements"] = static_cast<double>(model.elements().size());
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(model.elements().size()));
}

BENCHMARK_DEFINE_F(CableSystem, CalcInternalForces)(benchmark::State& state) {
  for (auto _ : state) {
    CalcInternalForces(*model_, config_.q, config_.v, *ws_);
    benchmark::DoNotOptimize(ws_->internal_force.data());
    benchmark::ClobberMemory();
  }
  SetCounters(state, *model_);
}
BENCHMARK_REGISTER_F(CableSystem, CalcInternalForces)->ArgName("elements")->Arg(128);

BENCHMARK_DEFINE_F(CableSystem, AssembleIterationMatrix)(benchmark::State& state) {
  for (auto _ : state) {
    Assemble();
    benchmark::DoNotOptimize(matrix_->matrix().valuePtr());
    benchmark::ClobberMemory();
  }
  SetCounters(state, *model_);
}
BENCHMARK_REGISTER_F(CableSystem, AssembleIterationMatrix)->ArgName("elements")->Arg(128);

// Numeric KLU refactorisation of the iteration matrix (the pattern is analysed once, outside the
// timed loop, as in the solvers).
BENCHMARK_DEFINE_F(CableSystem, KluFactorize)(benchmark::State& state) {
  Assemble();
  SparseLinearSolver solver(LinearSolverType::kKlu);
  if (!solver.Factorize(matrix_->matrix())) state.SkipWithError("singular iteration matrix");
  for (auto _ : state) {
    const bool ok = solver.Factorize(matrix_->matrix());
    benchmark::DoNotOptimize(ok);
    benchmark::ClobberMemory();
  }
  state.counters["unknowns"] = static_cast<double>(dofs_->num_unknowns());
}
BENCHMARK_REGISTER_F(CableSystem, KluFactorize)->ArgName("elements")->Arg(128);

// Forward and back substitution with that factorisation (one Newton iteration's linear solve).
BENCHMARK_DEFINE_F(CableSystem, KluSolve)(benchmark::State& state) {
  Assemble();
  SparseLinearSolver solver(LinearSolverType::kKlu);
  if (!solver.Factorize(matrix_->matrix())) state.SkipWithError("singular iteration matrix");
  VectorXd rhs;
  dofs_->Restrict(ws_->internal_force, &rhs);
  VectorXd x(rhs.size());
  for (auto _ : state) {
    solver.Solve(rhs, &x);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  state.counters["unknowns"] = static_cast<double>(dofs_->num_unknowns());
}
BENCHMARK_REGISTER_F(CableSystem, KluSolve)->ArgName("elements")->Arg(128);

}  // namespace
}  // namespace ancfnet
