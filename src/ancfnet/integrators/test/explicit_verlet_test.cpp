// Stability limit of the explicit Verlet integrator: the estimate 2/ω_max from element
// frequencies must be safe (at or below the true limit of the assembled system) without being
// far too conservative, and the integrator must be stable just below the true limit and
// unstable just above it (central-difference limit ω_max h = 2).

#include "ancfnet/integrators/explicit_verlet.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cstdio>

#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

// Steel cantilever, 8 elements, no loads; with `beam` of ANCF beam elements (ν = 0.3).
Model MakeUnloadedCantilever(bool beam = false) {
  ModelBuilder builder;
  CableSpec cable{.name = "beam",
                  .start = Vector3d::Zero(),
                  .end = Vector3d(1.0, 0.0, 0.0),
                  .num_elements = 8,
                  .properties = MakeCableProperties({.youngs_modulus = 2.0e11, .density = 7800.0},
                                                    MakeRectangleSection(0.01, 0.01))};
  if (beam)
    cable.beam = BeamCableSpec{
        .material = {.youngs_modulus = 2.0e11, .poisson_ratio = 0.3, .density = 7800.0},
        .section = MakeRectangleBeamSection(0.01, 0.01, 0.3),
        .orientation = Vector3d::UnitY()};
  builder.AddCable(cable);
  builder.AddClamp({"beam", 0.0});
  return builder.Build();
}

// 2/ω_max of the assembled, constrained system linearised at q.
double GlobalCriticalStep(const Model& model, const VectorXd& q) {
  const DofMap dofs = DofMap::FreeCoordinates(model);
  Workspace ws(model);
  SystemMatrix stiffness(model, dofs);
  SystemMatrix mass(model, dofs);
  AssembleIterationMatrix(model, q, VectorXd::Zero(q.size()), {.stiffness = 1.0}, 1.0, ws,
                          &stiffness);
  AssembleMassMatrix(model, ws, &mass);
  const MatrixXd k = MatrixXd(stiffness.matrix());
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> eigen(
      0.5 * (k + k.transpose()), MatrixXd(mass.matrix()), Eigen::EigenvaluesOnly);
  return 2.0 / std::sqrt(eigen.eigenvalues().maxCoeff());
}

// Largest speed reached in `steps` Verlet steps of size h from a tiny velocity perturbation.
double MaxSpeedAfterSteps(const Model& model, double h, int steps) {
  ExplicitVerletIntegrator integrator(model);
  State state = MakeInitialState(model);
  const DofMap dofs = DofMap::FreeCoordinates(model);
  for (Index i = 0; i < dofs.num_unknowns(); ++i)
    state.v[dofs.coordinates()[i]] = 1e-6 * std::sin(1.0 + 7.0 * i);
  EXPECT_TRUE(integrator.Initialize(&state));
  double max_speed = 0.0;
  for (int i = 0; i < steps; ++i) {
    if (!integrator.Step(h, &state).accepted) return std::numeric_limits<double>::infinity();
    max_speed = std::max(max_speed, state.v.cwiseAbs().maxCoeff());
  }
  return max_speed;
}

// The element-frequency estimate lies in [0.5, 1] × the exact limit.
void ExpectSafeEstimate(const Model& model) {
  const State state = MakeInitialState(model);
  const double estimate = ExplicitVerletIntegrator(model).EstimateCriticalStep(state.q);
  const double exact = GlobalCriticalStep(model, state.q);
  std::printf("critical step: estimate %.4e s, exact %.4e s (ratio %.3f)\n", estimate, exact,
              estimate / exact);
  EXPECT_LE(estimate, exact * (1.0 + 1e-9));
  EXPECT_GE(estimate, 0.5 * exact);
}

void ExpectStableJustBelowTheLimit(const Model& model) {
  const double exact = GlobalCriticalStep(model, MakeInitialState(model).q);
  EXPECT_LT(MaxSpeedAfterSteps(model, 0.98 * exact, 3000), 1e-4);
  EXPECT_GT(MaxSpeedAfterSteps(model, 1.02 * exact, 3000), 1.0);
}

TEST(ExplicitVerletTest, CriticalStepEstimateIsSafeAndNotFarTooConservative) {
  ExpectSafeEstimate(MakeUnloadedCantilever());
}

TEST(ExplicitVerletTest, StableJustBelowTheLimitAndUnstableJustAbove) {
  ExpectStableJustBelowTheLimit(MakeUnloadedCantilever());
}

// Beam elements: their highest frequencies, those of the cross-section's own deformation against
// the rotary inertia, are in the estimate (issue 13).
TEST(ExplicitVerletTest, BeamCriticalStepEstimateIsSafeAndNotFarTooConservative) {
  ExpectSafeEstimate(MakeUnloadedCantilever(/*beam=*/true));
}

TEST(ExplicitVerletTest, BeamStableJustBelowTheLimitAndUnstableJustAbove) {
  ExpectStableJustBelowTheLimit(MakeUnloadedCantilever(/*beam=*/true));
}

// A step above the limit (2.5 × the estimate, which is at least half the true limit) diverges
// after many accepted steps whose states grow wild; the message quotes the estimate made at the
// start (once 1e-104 s, made at the last wild state) and says that h is above it; a step below
// the limit that still diverges is not blamed on h.
TEST(ExplicitVerletTest, ADivergedStepQuotesTheEstimateOfTheStart) {
  const Model model = MakeUnloadedCantilever();
  const double estimate =
      ExplicitVerletIntegrator(model).EstimateCriticalStep(MakeInitialState(model).q);
  ExplicitVerletIntegrator integrator(model);
  State state = MakeInitialState(model);
  state.v.setConstant(1e-6);
  ASSERT_TRUE(integrator.Initialize(&state));
  StepOutcome outcome;
  for (int i = 0; i < 100000 && (outcome = integrator.Step(2.5 * estimate, &state)).accepted; ++i) {
  }
  ASSERT_FALSE(outcome.accepted);
  EXPECT_EQ(outcome.failure,
            fmt::format("non-finite state: h = {:.3g} s is above the stability limit of the "
                        "elements, about {:.3g} s (2/ω_max at t = 0 s)",
                        2.5 * estimate, estimate));
  // A state so wild that its forces overflow diverges at any step: not blamed on h.
  state.q *= 1e200;
  const StepOutcome small = integrator.Step(0.5 * estimate, &state);
  ASSERT_FALSE(small.accepted);
  EXPECT_NE(small.failure.find("below the stability limit"), std::string::npos) << small.failure;
}

}  // namespace
}  // namespace ancfnet
