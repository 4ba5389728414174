// Google Benchmark timings of the ANCF beam element (elements/ancf_beam.hpp), beside the cable's
// kernels in element_kernels_bench.cpp: internal force only, force + tangent stiffness, and the
// mass matrix of one element of the Timoshenko cantilever's section (0.5 × 0.1 m steel),
// L = 0.25 m, in a configuration that is stretched, sheared, bent in both planes and twisted, so
// that every strain does its full work. Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>

#include "ancfnet/elements/ancf_beam.hpp"
#include "ancfnet/model/beam_section.hpp"

namespace ancfnet {
namespace {

struct BeamElementCase {
  BeamElementParameters parameters;
  Vector24d e;
  Vector24d e_dot;
};

// Node B turned by 0.3 rad about (0.2, 0.5, 1) relative to node A, its axis moved off the chord
// and stretched by 1 %, its section sheared by 0.02 rad. Damped: Kelvin–Voigt times of 1e-4 s
// (the cable kernels' kDampingTime) and every coordinate moving, so every strain rate is non-zero.
BeamElementCase MakeBeamElementCase(bool damped) {
  const double tau = damped ? 1e-4 : 0.0;
  const BeamMaterial steel{.youngs_modulus = 2.07e11,
                           .poisson_ratio = 0.3,
                           .density = 7800.0,
                           .axial_damping_time = tau,
                           .bending_damping_time = tau};
  BeamElementCase c{MakeBeamElementParameters(steel, MakeRectangleBeamSection(0.5, 0.1, 0.3), 0.25),
                    Vector24d::Zero(), Vector24d::Zero()};
  for (int i = 0; i < kBeamElementDofs; ++i) c.e_dot[i] = 0.01 * std::sin(1.3 * i + 0.2);
  const Matrix3d turn =
      Eigen::AngleAxisd(0.3, Vector3d(0.2, 0.5, 1.0).normalized()).toRotationMatrix();
  const Matrix3d shear = Eigen::AngleAxisd(0.02, Vector3d::UnitZ()).toRotationMatrix();
  c.e << Vector3d::Zero(), 1.01 * Vector3d::UnitX(), shear * Vector3d::UnitY(), Vector3d::UnitZ(),
      Vector3d(0.245, 0.04, 0.01), 1.01 * turn.col(0), turn * shear * Vector3d::UnitY(),
      turn.col(2);
  return c;
}

// Forces only, the outputs CalcInternalForces asks for (residual evaluations). Argument: damped.
void BM_BeamForce(benchmark::State& state) {
  const BeamElementCase c = MakeBeamElementCase(state.range(0) != 0);
  Vector24d force, viscous_force;
  for (auto _ : state) {
    CalcBeamInternalForce(c.parameters, c.e, c.e_dot,
                          {.force = &force, .viscous_force = &viscous_force});
    benchmark::DoNotOptimize(force.data());
    benchmark::DoNotOptimize(viscous_force.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_BeamForce)->ArgName("damped")->Arg(0)->Arg(1);

// Forces and Jacobians, the outputs AssembleIterationMatrix asks for in dynamics: stiffness
// ∂Q/∂e and damping ∂Q/∂ė (zero, but still requested, when undamped).
void BM_BeamForceAndJacobian(benchmark::State& state) {
  const BeamElementCase c = MakeBeamElementCase(state.range(0) != 0);
  Vector24d force, viscous_force;
  Matrix24d stiffness, damping;
  for (auto _ : state) {
    CalcBeamInternalForce(c.parameters, c.e, c.e_dot,
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
BENCHMARK(BM_BeamForceAndJacobian)->ArgName("damped")->Arg(0)->Arg(1);

void BM_BeamMassMatrix(benchmark::State& state) {
  const BeamElementCase c = MakeBeamElementCase(false);
  for (auto _ : state) {
    Matrix24d mass = CalcBeamMassMatrix(c.parameters);
    benchmark::DoNotOptimize(mass.data());
  }
}
BENCHMARK(BM_BeamMassMatrix);

}  // namespace
}  // namespace ancfnet
