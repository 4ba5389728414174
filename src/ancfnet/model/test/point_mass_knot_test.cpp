// Point masses and ideal knots: a cable end that shares its position coordinates with a point
// mass moves with it, and a mass hanging from a cable stretches it by the analytical amount.

#include <gtest/gtest.h>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

CableProperties Cord() {
  return MakeCableProperties({.youngs_modulus = 1.0e9, .density = 1000.0},
                             MakeCircleSection(0.002));
}

TEST(PointMassKnot, CableEndSharesTheKnotCoordinates) {
  ModelBuilder builder;
  builder.AddPointMass("knot", 0.1, Vector3d(1.0, 0.0, 0.0));
  builder.AddCable({.name = "a", .start = Vector3d::Zero(), .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 2, .properties = Cord(), .end_knot = "knot"});
  builder.AddCable({.name = "b", .start = Vector3d(1.0, 0.0, 0.0), .end = Vector3d(1.0, 1.0, 0.0),
                    .num_elements = 3, .properties = Cord(), .start_knot = "knot"});
  const Model model = builder.Build();
  const Index knot_dof = model.point_masses()[0].dof;
  EXPECT_EQ(model.NodePositionDof(model.LocateCableNode(0, 1.0)), knot_dof);
  EXPECT_EQ(model.NodePositionDof(model.LocateCableNode(1, 0.0)), knot_dof);
  // Each thread keeps its own slope at the knot.
  EXPECT_NE(model.NodeSlopeDof(model.LocateCableNode(0, 1.0)),
            model.NodeSlopeDof(model.LocateCableNode(1, 0.0)));
  // 3 knot + (3 nodes − 1 shared) · 6 + 3 + (4 nodes − 1 shared) · 6 + 3 coordinates.
  EXPECT_EQ(model.num_dofs(), 3 + 15 + 21);
  EXPECT_DOUBLE_EQ(model.total_mass(), 0.1 + 2.0 * Cord().mass_per_length);
}

TEST(PointMassKnot, CableEndMustBeAtItsKnot) {
  ModelBuilder builder;
  builder.AddPointMass("knot", 0.1, Vector3d(1.0, 0.0, 0.0));
  EXPECT_THROW(builder.AddCable({.name = "a", .start = Vector3d::Zero(),
                                 .end = Vector3d(1.0, 0.1, 0.0), .num_elements = 2,
                                 .properties = Cord(), .end_knot = "knot"}),
               InputError);
  EXPECT_THROW(builder.AddCable({.name = "knot", .start = Vector3d::Zero(),
                                 .end = Vector3d(1.0, 0.0, 0.0), .properties = Cord()}),
               InputError);
  EXPECT_THROW(builder.AddPointMass("m", -1.0, Vector3d::Zero()), InputError);
}

// Elongation of a hanging cable of length L under its weight and an end mass m. At material
// coordinate x the tension is T = m g + ρA g (L − x); with the Green strain law the axial force
// N = EA (λ² − 1)/2 acts along r', so T = N λ with the stretch λ = |r'|, i.e. λ³ − λ = 2T/EA.
// The elongation ∫ (λ − 1) dx is integrated with the midpoint rule on 4000 intervals.
double ExactHangingElongation(double mass, double g, double length, const CableProperties& p) {
  const int n = 4000;
  double elongation = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * length / n;
    const double tension = mass * g + p.mass_per_length * g * (length - x);
    double stretch = 1.0;
    for (int it = 0; it < 30; ++it)  // Newton on λ³ − λ − 2T/EA = 0
      stretch -= (stretch * stretch * stretch - stretch - 2.0 * tension / p.axial_stiffness) /
                 (3.0 * stretch * stretch - 1.0);
    elongation += (stretch - 1.0) * length / n;
  }
  return elongation;
}

TEST(PointMassKnot, HangingMassStretchesTheCableByTheExactAmount) {
  const double mass = 2.0;
  const double g = 9.81;
  const double length = 1.5;
  const CableProperties cord = Cord();
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -g));
  builder.AddPointMass("weight", mass, Vector3d(0.0, 0.0, -length));
  builder.AddCable({.name = "cord", .start = Vector3d::Zero(), .end = Vector3d(0.0, 0.0, -length),
                    .num_elements = 4, .properties = cord, .end_knot = "weight"});
  builder.AddPin({"cord", 0.0});
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  StaticSettings settings;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  const SolveResult result =
      SolveStatic(model, settings, [](const State&, const EnergyAccount&) {}, &state);
  ASSERT_TRUE(result.completed) << result.message;
  const double elongation = -state.q[model.point_masses()[0].dof + 2] - length;
  const double expected = ExactHangingElongation(mass, g, length, cord);
  EXPECT_NEAR(elongation, expected, 1e-5 * expected);  // about 9.3 mm
}

}  // namespace
}  // namespace ancfnet
