// The tether of a net: where it starts and ends, how it meets the net (shared coordinates or a
// link), the bridle's geometry, bad values refused, and a tether that holds a launched net.

#include "ancfnet/model/net_tether.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/common/error.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

// A 1 m square net of 2 × 2 meshes in the xy-plane (knot 4 at the centre), launched along +z.
NetSpec MakeSpec(KnotModel knots) {
  NetSpec spec;
  spec.name = "net";
  spec.topology = MakeGridNet({.side_u = 1.0, .side_v = 1.0, .meshes_u = 2, .meshes_v = 2});
  spec.thread =
      MakeRopeProperties({.youngs_modulus = 3e9, .density = 1140}, MakeCircleSection(0.001));
  spec.knot_model = knots;
  spec.knot_mass = 1e-3;
  spec.link_law = MakeLinearLaw(1e4);
  TetherSpec tether;
  tether.chaser = Vector3d(0, 0, -2);
  tether.properties = spec.thread;
  spec.tether = tether;
  return spec;
}

Vector3d PositionOf(const Model& model, const std::string& point) {
  return model.initial_positions().segment<3>(model.point_masses()[model.FindPointMass(point)].dof);
}

TEST(NetTether, CenterTetherSharesTheCentralKnotOfAnIdealNet) {
  ModelBuilder builder;
  AddNet(builder, MakeSpec(KnotModel::kIdeal));
  const Model model = builder.Build();
  const Index tether = model.FindCable("net.tether");
  const Cable& cable = model.cables()[tether];
  EXPECT_DOUBLE_EQ(cable.length, 2.0);
  const Index chaser = model.point_masses()[model.FindPointMass("net.chaser")].dof;
  const Index center = model.point_masses()[model.FindPointMass("net.k4")].dof;
  EXPECT_EQ(model.NodePositionDof(cable.first_node), chaser);
  EXPECT_EQ(model.NodePositionDof(cable.first_node + cable.num_elements), center);
  EXPECT_TRUE(model.fixed()[chaser]);
  EXPECT_TRUE(model.links().empty());
}

TEST(NetTether, CompliantNetsHoldTheTetherByALink) {
  ModelBuilder builder;
  AddNet(builder, MakeSpec(KnotModel::kCompliant));
  const Model model = builder.Build();
  const SpringDamperLink& link = model.links().back();
  EXPECT_EQ(link.name, "net.tether.end");
  EXPECT_EQ(link.second_cable, model.FindCable("net.tether"));
  EXPECT_EQ(Model::Locate(link.first, model.initial_positions()), PositionOf(model, "net.k4"));
}

TEST(NetTether, BridleLinesReachTheCornersFromTheAxis) {
  NetSpec spec = MakeSpec(KnotModel::kIdeal);
  spec.packing_ratio = 0.5;
  spec.tether->attachment = TetherAttachment::kBridle;
  spec.tether->bridle_length = 0.6;
  spec.tether->chaser_velocity = Vector3d(0, 0, 0.5);
  ModelBuilder builder;
  AddNet(builder, spec);
  const Model model = builder.Build();
  // Packed corners are √2/4 m from the axis; the apex sits √(0.6² − 1/8) m behind the centre.
  const Vector3d apex = PositionOf(model, "net.bridle");
  EXPECT_NEAR(apex.z(), -std::sqrt(0.36 - 0.125), 1e-12);
  EXPECT_NEAR(apex.head<2>().norm(), 0.0, 1e-12);
  for (int i = 0; i < 4; ++i) {
    const Cable& line = model.cables()[model.FindCable(fmt::format("net.bridle{}", i))];
    EXPECT_DOUBLE_EQ(line.length, 0.6);
    const Vector3d corner = PositionOf(model, KnotName("net", spec.topology.corners[i]));
    EXPECT_NEAR((corner - apex).norm(), 0.6, 1e-12);
  }
  // A moving chaser: prescribed, with its velocity.
  const Index chaser = model.point_masses()[model.FindPointMass("net.chaser")].dof;
  EXPECT_TRUE(model.fixed()[chaser + 2]);
  EXPECT_DOUBLE_EQ(model.initial_velocities()[chaser + 2], 0.5);
  EXPECT_EQ(model.cables()[model.FindCable("net.tether")].length, 2.0 - std::sqrt(0.36 - 0.125));
}

TEST(NetTether, RefusesWhatCannotBeBuilt) {
  NetSpec short_bridle = MakeSpec(KnotModel::kIdeal);
  short_bridle.tether->attachment = TetherAttachment::kBridle;
  short_bridle.tether->bridle_length = 0.5;  // corners are √2/2 m from the axis
  ModelBuilder a;
  EXPECT_THROW(AddNet(a, short_bridle), InputError);
  NetSpec on_knot = MakeSpec(KnotModel::kIdeal);
  on_knot.tether->chaser = Vector3d::Zero();
  ModelBuilder b;
  EXPECT_THROW(AddNet(b, on_knot), InputError);
  NetSpec no_elements = MakeSpec(KnotModel::kIdeal);
  no_elements.tether->elements = 0;
  ModelBuilder c;
  EXPECT_THROW(AddNet(c, no_elements), InputError);
}

// Launched at 2 m/s away from a fixed chaser 2 m behind, a net on a 2.2 m rope tether is caught:
// untethered it would travel 3 m in 1.5 s; tethered its centre stays within the tether's length
// plus its stretch. (With h = 2e-4 s the snapping threads pump energy from t ≈ 0.7 s on and the run
// fails at 0.98 s; the step control has no energy criterion.)
TEST(NetTether, HoldsALaunchedNet) {
  NetSpec spec = MakeSpec(KnotModel::kIdeal);
  spec.velocity = Vector3d(0, 0, 2.0);
  spec.tether->natural_length = 2.2;
  spec.tether->properties.axial_damping_time = 1e-3;
  ModelBuilder builder;
  AddNet(builder, spec);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.time_step = 1e-4;
  settings.end_time = 1.5;
  settings.spectral_radius = 0.8;
  const Index center = model.point_masses()[model.FindPointMass("net.k4")].dof;
  double farthest = 0.0;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 1e-3,
      [&](const State& s, const EnergyAccount&) {
        farthest = std::max(farthest, (s.q.segment<3>(center) - Vector3d(0, 0, -2)).norm());
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_GT(farthest, 2.2);         // the tether went taut
  EXPECT_LT(farthest, 2.2 * 1.05);  // and held
}

}  // namespace
}  // namespace ancfnet
