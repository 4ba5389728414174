// Large deflection of a cantilever under a tip load P with P L² / EI = k, against the elliptic-
// integral solution tabulated by Mattiasson (1981), and a tip moment M = 2π EI / L that rolls the
// cantilever into a full circle (exact solution of the elastica under a pure end moment).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ancfnet/solvers/static_solver.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

using verification::CantileverBendingStiffness;
using verification::MakeCantilever;

struct TipDisplacement {
  double u = 0.0;  ///< shortening along x, divided by L
  double w = 0.0;  ///< deflection along −z, divided by L
};

TipDisplacement SolveTipLoad(double k, int elements, int axial_points = 3, int bending_points = 4) {
  ModelBuilder builder = MakeCantilever(elements, axial_points, bending_points);
  builder.AddPointForce({"beam", 1.0}, Vector3d(0.0, 0.0, -k * CantileverBendingStiffness()));
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  StaticSettings settings;
  settings.load_steps = 10;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-12;
  const SolveResult result = SolveStatic(model, settings, [](const State&, const EnergyAccount&) {},
                                         &state);
  EXPECT_TRUE(result.completed) << result.message;
  const Vector3d tip = model.Interpolate(model.LocateCablePoint(0, 1.0), state.q);
  return {1.0 - tip.x(), -tip.z()};
}

struct MattiassonCase {
  double k;
  double u;
  double w;
};
// Mattiasson (1981), Table 1: tip displacements of the elastica under a transverse end load.
constexpr MattiassonCase kMattiasson[] = {
    {1.0, 0.05643, 0.30172}, {2.0, 0.16064, 0.49346}, {5.0, 0.38763, 0.71379},
    {10.0, 0.55500, 0.81061}};

TEST(Elastica, TipLoadMatchesMattiassonWith16Elements) {
  for (const MattiassonCase& c : kMattiasson) {
    const TipDisplacement tip = SolveTipLoad(c.k, 16);
    EXPECT_NEAR(tip.u, c.u, 3e-3 * c.u) << "k = " << c.k;
    EXPECT_NEAR(tip.w, c.w, 3e-3 * c.w) << "k = " << c.k;
  }
}

// Discretisation error against a 64-element solution of the same (slightly extensible) model;
// the comparison with Mattiasson's inextensible values levels off near 1e-4 because EA is finite.
TEST(Elastica, ErrorFallsWithRefinement) {
  const TipDisplacement reference = SolveTipLoad(10.0, 64);
  double previous = 0.0;
  for (int elements : {4, 8, 16, 32}) {
    const TipDisplacement tip = SolveTipLoad(10.0, elements);
    const double error = std::hypot(tip.u - reference.u, tip.w - reference.w);
    std::printf("k = 10, %2d elements: u/L = %.6f, w/L = %.6f, error %.2e\n", elements, tip.u,
                tip.w, error);
    if (previous > 0.0) {
      EXPECT_GT(previous / error, 4.0) << elements << " elements";
    }
    previous = error;
  }
}

TEST(Elastica, QuadratureChoiceDoesNotLock) {
  // Reduced axial integration (3 points) must be at least as accurate as exact integration (5).
  const MattiassonCase& c = kMattiasson[3];
  const TipDisplacement reduced = SolveTipLoad(c.k, 8, 3, 4);
  const TipDisplacement exact = SolveTipLoad(c.k, 8, 5, 5);
  const double error_reduced = std::hypot(reduced.u - c.u, reduced.w - c.w);
  const double error_exact = std::hypot(exact.u - c.u, exact.w - c.w);
  std::printf("8 elements: error with 3/4 Gauss points %.3e, with 5/5 %.3e\n", error_reduced,
              error_exact);
  EXPECT_LE(error_reduced, 1.05 * error_exact);
}

TEST(Elastica, TipMomentRollsCantileverIntoCircle) {
  ModelBuilder builder = MakeCantilever(32);
  const double moment = 2.0 * std::numbers::pi * CantileverBendingStiffness();
  builder.AddPointMoment({"beam", 1.0}, Vector3d(0.0, -moment, 0.0));
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  StaticSettings settings;
  settings.load_steps = 20;
  const SolveResult result = SolveStatic(model, settings, [](const State&, const EnergyAccount&) {},
                                         &state);
  ASSERT_TRUE(result.completed) << result.message;
  const Vector3d tip = model.Interpolate(model.LocateCablePoint(0, 1.0), state.q);
  EXPECT_LT(tip.norm(), 0.01) << "tip at " << tip.transpose();
  // Half way, the beam is at the top of the circle of radius L / 2π.
  const Vector3d middle = model.Interpolate(model.LocateCablePoint(0, 0.5), state.q);
  EXPECT_NEAR(middle.z(), 1.0 / std::numbers::pi, 0.01);
}

}  // namespace
}  // namespace ancfnet
