// ANCF beams in a model, from scene text through the loader (issue 13): `element: ancf_beam` on a
// cable. Each case names its reference and a tolerance that fails when the wiring is wrong:
//  - the Timoshenko cantilever (Nachbagauer et al. 2011; PL³/(3EI) + PL/(kGA)): a point force on
//    a beam node, the clamp fixing all 12 coordinates; without shear the deflection is 4.6 % less;
//  - Saint-Venant torsion of a square bar, φ = TL/(GJ) (Timoshenko & Goodier 1970, §109), from a
//    point moment on the end node (docs/theory.md, "Point moment on a beam node");
//  - a mixed mesh, beam elements then cable elements sharing a node, against PL³/(3EI): a joint
//    that did not share the slope would be a hinge and the tip cable a mechanism;
//  - the first torsion frequency of a clamped–free shaft, f = (1/4L) √(GJ/(ρI_p)) (Blevins 1979,
//    table 8-19), found among the modes of the modal analysis, and its Rayleigh damping ratio.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/solvers/modal.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

// Solves the static scene; fails the test if it does not complete.
State SolveStaticScene(const Scene& scene) {
  State state = MakeInitialState(scene.model);
  const SolveResult result = SolveStatic(
      scene.model, scene.analysis.statics, [](const State&, const EnergyAccount&) {}, &state);
  EXPECT_TRUE(result.completed) << result.message;
  return state;
}

// The node at the end of a cable.
const CableNode& EndNode(const Model& model, const std::string& cable) {
  const Cable& c = model.cables()[model.FindCable(cable)];
  return model.nodes()[c.first_node + c.num_elements];
}

TEST(BeamScene, TimoshenkoCantileverTipDeflection) {
  // L = 2 m, height 0.5 m along d₂ = e_y (the load's direction), width 0.1 m, E = 2.07e11 Pa,
  // ν = 0.3 (Cowper's k = 0.849673), P = 62.5 kN; 64 elements as in the kernel's test.
  const Scene scene = ParseScene(R"(materials:
  steel: {youngs_modulus: 2.07e11, density: 7800, poisson_ratio: 0.3}
sections:
  beam: {shape: rectangle, width: 0.1, height: 0.5}
cables:
  - {name: beam, element: ancf_beam, orientation: [0, 1, 0], start: [0, 0, 0], end: [2, 0, 0],
     elements: 64, material: steel, section: beam}
constraints:
  - {type: clamp, at: beam.start}
loads:
  - {type: point_force, at: beam.end, force: [0, 62.5e3, 0]}
)");
  ASSERT_EQ(scene.model.beam_elements().size(), 64u);
  const State state = SolveStaticScene(scene);
  const double deflection = state.q[EndNode(scene.model, "beam").position_dof + 1];
  std::printf("Timoshenko cantilever: tip deflection %.7e m (reference 8.099034e-4 m)\n",
              deflection);
  EXPECT_NEAR(deflection, 8.099034e-4, 1e-4 * 8.099034e-4);
}

TEST(BeamScene, SaintVenantTorsionFromAnEndMoment) {
  const Scene scene = LoadScene(std::string(std::getenv("ANCFNET_SOURCE_DIR")) +
                                "/examples/beam_torsion.yaml");
  const State state = SolveStaticScene(scene);
  const CableNode& tip = EndNode(scene.model, "bar");
  const Vector3d d2 = state.q.segment<3>(tip.section_dof);
  const double twist = std::atan2(d2.z(), d2.y());
  std::printf("square bar: twist %.6f rad (TL/(GJ) with J = 0.1406 a^4: 0.263815 rad)\n", twist);
  EXPECT_NEAR(twist, 0.263815, 0.01 * 0.263815);
  // The axis neither moves nor bends.
  EXPECT_LT((state.q.segment<3>(tip.position_dof) - Vector3d::UnitX()).norm(), 1e-8);
}

TEST(BeamScene, MixedMeshOfBeamAndCableElementsBendsAsOneCantilever) {
  // 1 m steel bar of 10 × 10 mm: 4 beam elements to x = 0.5, clamped, then 4 cable elements
  // continuing them; tip force 1 N along z: δ = PL³/(3EI) = 2.0 mm (shear adds 4e-5 of it,
  // (δ/L)² nonlinearity 4e-6). Measured +0.21 %: the joint passes the moment from the cable's
  // slope to the beam's section through the shear of the last beam element, a compliance that
  // grows as that element shrinks (+0.36 % with 8 beam elements, +0.58 % with 32; docs/theory.md,
  // "Beams in a model"). With the slope not shared the joint would be a hinge and the tip cable a
  // mechanism. (The other order, a beam continuing a cable, has a free spin about its axis, which
  // a cable does not hold, and needs a torsional support of its own in statics.)
  const Scene scene = ParseScene(R"(materials:
  steel: {youngs_modulus: 2.0e11, density: 7800, poisson_ratio: 0.3}
sections:
  bar: {shape: rectangle, width: 0.01, height: 0.01}
cables:
  - {name: root, element: ancf_beam, orientation: [0, 0, 1], start: [0, 0, 0], end: [0.5, 0, 0],
     elements: 4, material: steel, section: bar}
  - {name: tip, continues: root, start: [0.5, 0, 0], end: [1, 0, 0], elements: 4,
     material: steel, section: bar}
constraints:
  - {type: clamp, at: root.start}
loads:
  - {type: point_force, at: tip.end, force: [0, 0, 1]}
)");
  const Model& model = scene.model;
  // The cable starts at the beam's end node: the same position and slope coordinates.
  const CableNode& joint = EndNode(model, "root");
  const CableNode& start = model.nodes()[model.cables()[model.FindCable("tip")].first_node];
  EXPECT_EQ(start.position_dof, joint.position_dof);
  EXPECT_EQ(start.slope_dof, joint.slope_dof);
  EXPECT_GE(joint.section_dof, 0);
  EXPECT_EQ(model.beam_elements().size(), 4u);
  EXPECT_EQ(model.elements().size(), 8u);
  const State state = SolveStaticScene(scene);
  const double ei = 2.0e11 * 1e-8 / 12.0;
  const double expected = 1.0 / (3.0 * ei);
  const double deflection = state.q[EndNode(model, "tip").position_dof + 2];
  std::printf("mixed mesh: tip deflection %.7e m (PL^3/(3EI) = %.7e m)\n", deflection, expected);
  EXPECT_NEAR(deflection, expected, 5e-3 * expected);
}

TEST(BeamScene, ModalAnalysisFindsTheFirstTorsionMode) {
  // Steel shaft, L = 0.1 m, d = 0.05 m, clamped at x = 0: f_torsion = (1/4L) √(G/ρ) (J = I_p for
  // a circle) = 7851 Hz, between the first bending pair (≈ 3.3 kHz) and the axial mode (12.7 kHz).
  // Rayleigh damping C = β K₀ gives every mode ζ = β ω/2 (the beam elements' own K_e in C).
  const Scene scene = ParseScene(R"(materials:
  steel: {youngs_modulus: 2.0e11, density: 7800, poisson_ratio: 0.3}
damping:
  rayleigh: {alpha: 0, beta: 1.0e-7}
sections:
  shaft: {shape: circle, diameter: 0.05}
cables:
  - {name: shaft, element: ancf_beam, orientation: [0, 1, 0], start: [0, 0, 0],
     end: [0.1, 0, 0], elements: 16, material: steel, section: shaft}
constraints:
  - {type: clamp, at: shaft.start}
)");
  const Model& model = scene.model;
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 6});
  ASSERT_TRUE(modes.converged) << modes.message;
  // The torsion mode turns d₂ = e_y about the axis (towards e_z) at the tip; bending modes tilt
  // d₂ towards the axis or leave it, the axial mode leaves it.
  const Index d2_z = EndNode(model, "shaft").section_dof + 2;
  Eigen::Index torsion = 0;
  for (Eigen::Index i = 1; i < modes.shapes.cols(); ++i)
    if (std::abs(modes.shapes(d2_z, i)) > std::abs(modes.shapes(d2_z, torsion))) torsion = i;
  const double g = 2.0e11 / (2.0 * 1.3);
  const double expected = std::sqrt(g / 7800.0) / (4.0 * 0.1);
  std::printf("shaft: torsion mode %ld at %.1f Hz (closed form %.1f Hz)\n",
              static_cast<long>(torsion), modes.frequency_hz[torsion], expected);
  EXPECT_NEAR(modes.frequency_hz[torsion], expected, 0.01 * expected);
  const double omega = 2.0 * std::numbers::pi * modes.frequency_hz[torsion];
  EXPECT_NEAR(modes.damping_ratio[torsion], 0.5e-7 * omega, 1e-3 * 0.5e-7 * omega);
}

}  // namespace
}  // namespace ancfnet
