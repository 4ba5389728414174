// The recovered tension of a beam cable (analysis/cable_tension.hpp with the beam's own section
// force, docs/theory.md "Tension of a beam"), from scene text through the static solver. The
// material is soft (strains of 2 to 3 %), so that the beam's normal force N = EA Γ₁ differs by
// several per cent from its centre line read as a cable (EA (ε + ε²/2)(1 + ε)):
//  - a hanging rod carries the weight of what hangs below, N(s) = ρA g (L − s) (s: reference arc
//    length from the clamp), at every station of every element;
//  - a cantilever under a tip force F only has the section force F everywhere, so
//    N(ξ) = F · n(ξ) with the section's normal n; at the clamp n = e_x and N = F_x exactly. A
//    shear strain of 0.4 % turns n away from the tangent, which would read 0.04 N more.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ancfnet/analysis/cable_tension.hpp"
#include "ancfnet/elements/ancf_beam_tension.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

State SolveStaticScene(const Scene& scene) {
  State state = MakeInitialState(scene.model);
  const SolveResult result = SolveStatic(
      scene.model, scene.analysis.statics, [](const State&, const EnergyAccount&) {}, &state);
  EXPECT_TRUE(result.completed) << result.message;
  return state;
}

constexpr double kStations[] = {0.0, 0.25, 0.5, 0.75, 1.0};

TEST(BeamTension, HangingRodCarriesTheWeightBelow) {
  // E = 1 MPa, ρ = 1000 kg/m³, d = 20 mm: ρA g L = 6.163 N, EA = 314 N, 2 % strain at the top.
  const Scene scene = ParseScene(R"(gravity: [0, 0, -9.81]
materials:
  soft: {youngs_modulus: 1.0e6, density: 1000, poisson_ratio: 0.3}
sections:
  rod: {shape: circle, diameter: 0.02}
cables:
  - {name: rod, element: ancf_beam, orientation: [1, 0, 0], start: [0, 0, 0], end: [0, 0, -2],
     elements: 8, material: soft, section: rod}
constraints:
  - {type: clamp, at: rod.start}
analysis: {type: static, load_steps: 2}
)");
  const State state = SolveStaticScene(scene);
  const Model& model = scene.model;
  const Cable& rod = model.cables()[0];
  const double weight_per_length = 1000.0 * 3.14159265358979 * 1e-4 * 9.81;
  const double element_length = rod.length / rod.num_elements;
  double worst = 0.0;
  for (Index k = 0; k < rod.num_elements; ++k) {
    const CableStationForces forces = CalcCableStationForces(model, rod, k, state.q);
    for (double xi : kStations) {
      const double s = (k + xi) * element_length;
      const double tension = CalcCableElementTension(model, rod, k, state.q, forces, xi);
      worst = std::max(worst, std::abs(tension - weight_per_length * (rod.length - s)));
    }
  }
  const double top = weight_per_length * rod.length;
  std::printf("hanging rod: worst tension error %.3e N of %.4f N at the top\n", worst, top);
  EXPECT_LT(worst, 1e-6 * top);
  EXPECT_NEAR(CalcCableMaxTension(model, rod, state.q), top, 1e-6 * top);
}

TEST(BeamTension, CantileverNormalForceIsTheTipForceOnTheSectionNormal) {
  // E = 1 MPa, d = 0.1 m, L = 0.5 m: EA = 7854 N, kGA = 2.7 kN; F = (200, 0, 10) N bends the beam
  // (less than PL³/(3EI) = 0.085 m: the tension stiffens it) and stretches it by 2.5 %.
  const Scene scene = ParseScene(R"(gravity: [0, 0, 0]
materials:
  soft: {youngs_modulus: 1.0e6, density: 1000, poisson_ratio: 0.3}
sections:
  rod: {shape: circle, diameter: 0.1}
cables:
  - {name: rod, element: ancf_beam, orientation: [0, 1, 0], start: [0, 0, 0], end: [0.5, 0, 0],
     elements: 8, material: soft, section: rod}
constraints:
  - {type: clamp, at: rod.start}
loads:
  - {type: point_force, at: rod.end, force: [200, 0, 10]}
analysis: {type: static, load_steps: 4}
)");
  const State state = SolveStaticScene(scene);
  const Model& model = scene.model;
  const Cable& rod = model.cables()[0];
  const Vector3d tip_force(200.0, 0.0, 10.0);
  double worst = 0.0, bend = 0.0;
  for (Index k = 0; k < rod.num_elements; ++k) {
    const CableStationForces forces = CalcCableStationForces(model, rod, k, state.q);
    const Vector24d e = model.Gather(model.beam_elements()[k], state.q);
    for (double xi : kStations) {
      const Vector3d normal = CalcBeamSectionNormal(e, xi);
      bend = std::max(bend, std::abs(normal.z()));
      const double tension = CalcCableElementTension(model, rod, k, state.q, forces, xi);
      worst = std::max(worst, std::abs(tension - tip_force.dot(normal)));
    }
  }
  const CableStationForces root = CalcCableStationForces(model, rod, 0, state.q);
  const double root_tension = CalcCableElementTension(model, rod, 0, state.q, root, 0.0);
  std::printf("cantilever: worst N error %.3e N, root N %.6f N (F_x = 200), section turns %.3f\n",
              worst, root_tension, bend);
  EXPECT_GT(bend, 0.02);  // the sections do turn: n is not e_x along the beam
  EXPECT_LT(worst, 1e-6 * tip_force.norm());
  EXPECT_NEAR(root_tension, tip_force.x(), 1e-6 * tip_force.norm());
}

}  // namespace
}  // namespace ancfnet
