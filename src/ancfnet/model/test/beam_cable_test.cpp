// Beams in the model builder (model/model_builder.hpp, docs/theory.md "Beams in a model"): the
// 12 coordinates of a beam node and its reference frame by Gram–Schmidt, the Timoshenko clamp,
// node sharing with `start_cable`, the Kelvin–Voigt damping of the beam material, nets of beam
// threads, and what beams refuse.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

CableProperties Rod() {
  return MakeCableProperties({.youngs_modulus = 1.0e9, .density = 1000.0},
                             MakeCircleSection(0.01));
}

BeamCableSpec RodBeam(const Vector3d& orientation) {
  return {.material = {.youngs_modulus = 1.0e9, .poisson_ratio = 0.3, .density = 1000.0},
          .section = MakeCircleBeamSection(0.01, 0.3),
          .orientation = orientation};
}

CableSpec BeamAlongX(const std::string& name, double from, double to, const Vector3d& orientation) {
  return {.name = name, .start = Vector3d(from, 0.0, 0.0), .end = Vector3d(to, 0.0, 0.0),
          .num_elements = 2, .properties = Rod(), .beam = RodBeam(orientation)};
}

// Throws InputError whose message contains `text`.
template <class Action>
void ExpectInputError(Action action, const std::string& text) {
  try {
    action();
    FAIL() << "no error; expected one with '" << text << "'";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
  }
}

TEST(BeamCable, NodesCarryTwelveCoordinatesAndTheFrameOfTheOrientation) {
  ModelBuilder builder;
  // (1, 1, 0) loses its component along the axis e_x: d₂ = e_y, d₃ = e_x × e_y = e_z.
  builder.AddCable(BeamAlongX("beam", 0.0, 1.0, Vector3d(1.0, 1.0, 0.0)));
  const Model model = builder.Build();
  ASSERT_EQ(model.num_dofs(), 3 * kBeamNodeDofs);
  ASSERT_EQ(model.beam_elements().size(), 2u);
  EXPECT_EQ(model.cables()[0].element, ElementKind::kBeam);
  const BeamElement& beam = model.beam_elements()[1];
  EXPECT_EQ(model.elements()[beam.element].beam, 1);
  const Vector24d e = model.Gather(beam, model.initial_positions());
  Vector24d expected;
  expected << 0.5, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_EQ(e, expected);
  // The centre line is the cable element on (r, r_x) of the same nodes, with the beam's ρA.
  const CableElement& line = model.elements()[beam.element];
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(line.dofs[i], beam.dofs[i]);
    EXPECT_EQ(line.dofs[6 + i], beam.dofs[12 + i]);
  }
  EXPECT_DOUBLE_EQ(line.parameters.mass_per_length, beam.parameters.mass_per_length);
}

TEST(BeamCable, ClampHoldsPositionAndSectionButNotTheSlope) {
  ModelBuilder builder;
  builder.AddCable(BeamAlongX("beam", 0.0, 1.0, Vector3d::UnitZ()));
  builder.AddClamp({"beam", 0.0});
  builder.AddPin({"beam", 1.0});
  const Model model = builder.Build();
  const CableNode& root = model.nodes().front();
  const CableNode& tip = model.nodes().back();
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(model.fixed()[root.position_dof + k]);
    EXPECT_FALSE(model.fixed()[root.slope_dof + k]);
    EXPECT_TRUE(model.fixed()[tip.position_dof + k]);
    EXPECT_FALSE(model.fixed()[tip.slope_dof + k]);
  }
  for (int k = 0; k < 6; ++k) {
    EXPECT_TRUE(model.fixed()[root.section_dof + k]);
    EXPECT_FALSE(model.fixed()[tip.section_dof + k]);
  }
}

TEST(BeamCable, ABeamContinuingACableSharesItsEndNodeAndItsClampHoldsTheSlope) {
  ModelBuilder builder;
  builder.AddCable({.name = "cable", .start = Vector3d::Zero(), .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 2, .properties = Rod()});
  CableSpec beam = BeamAlongX("beam", 1.0, 2.0, Vector3d::UnitY());
  beam.start_cable = "cable";
  builder.AddCable(beam);
  builder.AddClamp({"beam", 0.0});
  const Model model = builder.Build();
  const CableNode& end = model.nodes()[2];
  const CableNode& start = model.nodes()[3];
  EXPECT_EQ(start.position_dof, end.position_dof);
  EXPECT_EQ(start.slope_dof, end.slope_dof);
  EXPECT_LT(end.section_dof, 0);
  EXPECT_GE(start.section_dof, 0);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(model.fixed()[start.slope_dof + k]);
  // 3 cable nodes (6 each), then 6 section coordinates at the shared node and 2 beam nodes.
  EXPECT_EQ(model.num_dofs(), 3 * 6 + 6 + 2 * kBeamNodeDofs);
}

TEST(BeamCable, AContinuationMustBeStraightAndKeepTheSectionFrame) {
  ModelBuilder builder;
  builder.AddCable(BeamAlongX("a", 0.0, 1.0, Vector3d::UnitZ()));
  CableSpec bent = BeamAlongX("b", 1.0, 2.0, Vector3d::UnitZ());
  bent.end = Vector3d(2.0, 0.5, 0.0);
  bent.start_cable = "a";
  ExpectInputError([&] { builder.AddCable(bent); }, "same direction");
  CableSpec turned = BeamAlongX("c", 1.0, 2.0, Vector3d::UnitY());
  turned.start_cable = "a";
  ExpectInputError([&] { builder.AddCable(turned); }, "section frame");
  CableSpec elsewhere = BeamAlongX("d", 1.5, 2.0, Vector3d::UnitZ());
  elsewhere.start_cable = "a";
  ExpectInputError([&] { builder.AddCable(elsewhere); }, "must start at its end");
}

TEST(BeamCable, KelvinVoigtDampingComesFromTheBeamMaterial) {
  ModelBuilder builder;
  CableSpec spec = BeamAlongX("beam", 0.0, 1.0, Vector3d::UnitZ());
  spec.beam->material.axial_damping_time = spec.properties.axial_damping_time = 1e-3;
  spec.beam->material.bending_damping_time = spec.properties.bending_damping_time = 2e-3;
  builder.AddCable(spec);
  const Model model = builder.Build();
  for (const BeamElement& beam : model.beam_elements()) {
    EXPECT_EQ(beam.parameters.axial_damping_time, 1e-3);
    EXPECT_EQ(beam.parameters.bending_damping_time, 2e-3);
  }
  // The centre line is undamped: the beam kernel does the damping.
  for (const CableElement& element : model.elements())
    EXPECT_EQ(element.parameters.axial_damping_time + element.parameters.bending_damping_time, 0.0);
}

// A net of beam threads (NetSpec::beam_threads) with compliant knots: every thread is a beam of
// the net's section with d₂ along the net's normal (not the orientation given), and each thread
// end hangs on its knot by a link, as a cable thread does; per-thread properties are refused.
TEST(BeamCable, NetOfBeamThreadsWithCompliantKnots) {
  NetSpec spec;
  spec.name = "net";
  spec.topology = MakeGridNet({.meshes_u = 2, .meshes_v = 2});
  spec.thread = Rod();
  spec.beam_threads = RodBeam(Vector3d::UnitX());
  spec.elements_per_thread = 2;
  spec.knot_model = KnotModel::kCompliant;
  spec.knot_mass = 0.01;
  spec.link_law = MakeLinearLaw(1e4);
  {
    ModelBuilder builder;
    AddNet(builder, spec);
    const Model model = builder.Build();
    ASSERT_EQ(model.cables().size(), 12u);
    EXPECT_EQ(model.beam_elements().size(), 24u);
    EXPECT_EQ(model.links().size(), 24u);
    for (const Cable& cable : model.cables()) {
      EXPECT_EQ(cable.element, ElementKind::kBeam);
      const CableNode& node = model.nodes()[cable.first_node];
      EXPECT_LT((model.initial_positions().segment<3>(node.section_dof) - Vector3d::UnitZ()).norm(),
                1e-12);
    }
  }
  ThreadDesign own;
  own.properties = Rod();
  spec.thread_designs.assign(12, own);
  ModelBuilder builder;
  ExpectInputError([&] { AddNet(builder, spec); }, "beam threads");
}

TEST(BeamCable, WhatBeamsDoNotSupportIsRefused) {
  {
    ModelBuilder builder;
    CableSpec spec = BeamAlongX("beam", 0.0, 1.0, Vector3d::UnitZ());
    spec.properties.axial_damping_time = 1e-3;  // not the beam material's (0)
    ExpectInputError([&] { builder.AddCable(spec); }, "beam's material");
  }
  {
    ModelBuilder builder;
    CableSpec spec = BeamAlongX("beam", 0.0, 1.0, Vector3d::UnitZ());
    spec.properties.tension_only = true;
    ExpectInputError([&] { builder.AddCable(spec); }, "rope law");
  }
  {
    ModelBuilder builder;
    ExpectInputError(
        [&] { builder.AddCable(BeamAlongX("beam", 0.0, 1.0, Vector3d(2.0, 0.0, 0.0))); },
        "parallel");
  }
}

}  // namespace
}  // namespace ancfnet
