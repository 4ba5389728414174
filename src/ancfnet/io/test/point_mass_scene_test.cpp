// Scene files with point masses and spring-dampers: every key read into the model, and bad
// input reported with file, line and key.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

constexpr const char* kTwoMasses = R"(gravity: [0, 0, 0]
point_masses:
  - {name: m1, mass: 0.05, position: [0, 0, 0], fixed: true}
  - {name: m2, mass: 0.15, position: [0.51, 0, 0], velocity: [0, 1, 0]}
spring_dampers:
  - {name: link, from: m1, to: m2, natural_length: 0.5, law: {type: linear, stiffness: 200, damping: 0.1}}
probes:
  - {name: p2, quantity: position, at: m2}
analysis: {type: dynamic, time_step: 1.0e-3, end_time: 0.1}
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PointMassScene, ReadsMassesLinksAndProbes) {
  const Scene scene = ParseScene(kTwoMasses);
  const Model& model = scene.model;
  ASSERT_EQ(model.point_masses().size(), 2u);
  EXPECT_EQ(model.point_masses()[1].name, "m2");
  EXPECT_DOUBLE_EQ(model.point_masses()[1].mass, 0.15);
  const Index d1 = model.point_masses()[0].dof, d2 = model.point_masses()[1].dof;
  EXPECT_TRUE(model.fixed()[d1] && model.fixed()[d1 + 2]);
  EXPECT_FALSE(model.fixed()[d2]);
  EXPECT_EQ(model.initial_velocities().segment<3>(d2), Vector3d(0, 1, 0));
  ASSERT_EQ(model.links().size(), 1u);
  EXPECT_DOUBLE_EQ(model.links()[0].natural_length, 0.5);
  EXPECT_EQ(model.links()[0].law.spring, SpringKind::kLinear);
  EXPECT_DOUBLE_EQ(model.links()[0].law.k1, 200.0);
  EXPECT_DOUBLE_EQ(model.links()[0].law.damping_coefficient, 0.1);
  ASSERT_EQ(scene.probes.size(), 1u);
  EXPECT_EQ(Model::Locate(scene.probes[0].point, model.initial_positions()), Vector3d(0.51, 0, 0));
}

TEST(PointMassScene, ReadsEveryLawType) {
  const std::string linear = "law: {type: linear, stiffness: 200, damping: 0.1}";
  const auto law = [&](const std::string& text) {
    return ParseScene(Replace(kTwoMasses, linear, text)).model.links()[0].law;
  };
  const ConnectionLaw rope = law("law: {type: tension_only, stiffness: 300, gap: 0.002}");
  EXPECT_EQ(rope.spring, SpringKind::kTensionOnly);
  EXPECT_DOUBLE_EQ(rope.gap, 0.002);
  const ConnectionLaw cubic = law("law: {type: polynomial, k1: 10, k3: 5000, damping_time: 0.01}");
  EXPECT_EQ(cubic.spring, SpringKind::kPolynomial);
  EXPECT_DOUBLE_EQ(cubic.k3, 5000.0);
  EXPECT_EQ(cubic.damping, DampingKind::kStiffnessProportional);
  const ConnectionLaw table = law("law: {type: table, table: [[0, 0], [0.01, 2], [0.05, 30]]}");
  EXPECT_EQ(table.spring, SpringKind::kPiecewiseLinear);
  ASSERT_EQ(table.table.size(), 3u);
  EXPECT_DOUBLE_EQ(table.CalcSpring(0.03).force, 16.0);
}

TEST(PointMassScene, ReadsTheOrbitalFrame) {
  const std::string gravity = "gravity: [0, 0, 0]";
  const Scene by_rate =
      ParseScene(Replace(kTwoMasses, gravity, "orbital_frame: {mean_motion: 0.001}"));
  EXPECT_DOUBLE_EQ(*by_rate.model.orbital_frame(), 0.001);
  // A 400 km orbit: a = 6778.137 km, n = √(μ/a³) = 1.1313e-3 rad/s.
  const Scene by_radius =
      ParseScene(Replace(kTwoMasses, gravity, "orbital_frame: {orbit_radius: 6778137}"));
  EXPECT_NEAR(*by_radius.model.orbital_frame(), 1.1313e-3, 1e-7);
  EXPECT_FALSE(ParseScene(kTwoMasses).model.orbital_frame());
}

TEST(PointMassScene, ReadsANetWithBulletsAndNetProbes) {
  const Scene scene = ParseScene(R"(gravity: [0, 0, 0]
materials:
  dyneema: {youngs_modulus: 1.0e11, density: 970}
sections:
  thread: {shape: circle, diameter: 0.001}
nets:
  - {name: net, type: square, side: 2.0, meshes: [2, 1], material: dyneema, section: thread,
     knot_model: compliant, knot_mass: 0.001, knot_link: {type: linear, stiffness: 1.0e4},
     packing_ratio: 0.5, bullets: {mass: 0.1, speed: 10, angle: 90, knots: [0]}}
probes:
  - {name: mouth, quantity: mouth_area, net: net}
  - {name: travel, quantity: distance, net: net}
  - {name: k0, quantity: velocity, at: net.k0}
)");
  const Model& model = scene.model;
  ASSERT_EQ(model.nets().size(), 1u);
  const Net& net = model.nets()[0];
  EXPECT_EQ(net.knots.size(), 6u);
  EXPECT_EQ(net.threads.size(), 7u);
  EXPECT_EQ(model.links().size(), 14u);  // two per thread
  // Tension-only threads with the simple bending model by default, half their natural length.
  const CableElementParameters& p = model.elements()[0].parameters;
  EXPECT_TRUE(p.tension_only);
  EXPECT_EQ(p.bending_model, BendingModel::kSecondDerivative);
  EXPECT_DOUBLE_EQ(p.length, 1.0);
  // The bullet at knot 0 flies at 90° from the axis: radially, away from the centre.
  const Vector3d v0 = model.initial_velocities().segment<3>(model.point_masses()[0].dof);
  EXPECT_TRUE(v0.isApprox(10.0 * Vector3d(-1.0, -1.0, 0.0).normalized()));  // knot 0 at (−1, −1)
  EXPECT_DOUBLE_EQ(model.point_masses()[0].mass, 0.101);
  std::vector<double> values;
  EvaluateProbe(scene.probes[0], model, MakeInitialState(model), {}, {}, &values);
  EXPECT_NEAR(values[0], 1.0, 1e-12);  // 2 m × 2 m packed by 0.5 in both directions
  EXPECT_EQ(ProbeColumns(scene.probes[1]), std::vector<std::string>{"travel.distance"});
}

struct BadCase {
  std::string from, to, message;
};

TEST(PointMassScene, BadInputNamesFileLineAndKey) {
  const std::string linear = "law: {type: linear, stiffness: 200, damping: 0.1}";
  const BadCase cases[] = {
      {linear, "law: {type: linaer, stiffness: 200}",
       "scene.yaml:6:69: expected one of linear, tension_only, polynomial, table, got 'linaer'; "
       "did you mean 'linear'? (key 'type')"},
      {linear, "law: {type: linear, stiffness: -200}",
       "scene.yaml:6:88: expected a number > 0, got '-200' (key 'stiffness')"},
      {linear, "law: {type: table, table: [[0, 0], [0.01]]}",
       "scene.yaml:6:92: expected a row [elongation, force], got a list of 1 item (key "
       "'table[1]')"},
      {linear, "law: {type: table, table: [[0, 0], [0, 2]]}",
       "scene.yaml:6:83: connection law: force table elongations must increase strictly"},
      {linear, "law: {type: linear, stiffness: 1, damping: 1, damping_time: 1}", "damping_time"},
      {"mass: 0.15", "mass: 0", "scene.yaml:4:22: expected a number > 0, got '0' (key 'mass')"},
      {"to: m2", "to: m3", "scene.yaml:6:"},
  };
  for (const BadCase& bad : cases) {
    try {
      ParseScene(Replace(kTwoMasses, bad.from, bad.to), "scene.yaml");
      ADD_FAILURE() << "no error for " << bad.to;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(bad.message), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

TEST(PointMassScene, ReadsBreakingForcesAndLinkProbes) {
  std::string text =
      Replace(kTwoMasses, "natural_length: 0.5,", "natural_length: 0.5, breaking_force: 3.5,");
  text = Replace(text, "  - {name: p2, quantity: position, at: m2}",
                 "  - {name: p2, quantity: position, at: m2}\n"
                 "  - {name: pull, quantity: link_force, link: link}");
  const Scene scene = ParseScene(text);
  EXPECT_DOUBLE_EQ(scene.model.links()[0].breaking_force, 3.5);
  ASSERT_EQ(scene.probes.size(), 2u);
  EXPECT_EQ(scene.probes[1].quantity, ProbeQuantity::kLinkForce);
  EXPECT_EQ(scene.probes[1].link, 0);
  EXPECT_EQ(ProbeColumns(scene.probes[1]),
            (std::vector<std::string>{"pull.tension", "pull.fx", "pull.fy", "pull.fz"}));
  // 10 mm stretched, 200 N/m: T = 2 N pulling the second mass back towards the first.
  State state = MakeInitialState(scene.model);
  state.v.setZero();
  std::vector<double> values;
  EvaluateProbe(scene.probes[1], scene.model, state, {}, {}, &values);
  EXPECT_NEAR(values[0], 2.0, 1e-12);
  EXPECT_NEAR(values[1], -2.0, 1e-12);
  state.link_broken[0] = 1;  // a broken link carries nothing
  values.clear();
  EvaluateProbe(scene.probes[1], scene.model, state, {}, {}, &values);
  EXPECT_EQ(values, (std::vector<double>{0.0, 0.0, 0.0, 0.0}));
}

TEST(PointMassScene, RefusesBadBreakingForcesAndUnknownLinks) {
  const auto message = [](const std::string& text) {
    try {
      ParseScene(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(Replace(kTwoMasses, "natural_length: 0.5,",
                            "natural_length: 0.5, breaking_force: -1,"))
                .find("breaking_force"),
            std::string::npos);
  const std::string probe = Replace(kTwoMasses, "  - {name: p2, quantity: position, at: m2}",
                                    "  - {name: pull, quantity: link_force, link: lnk}");
  EXPECT_NE(message(probe).find("no spring-damper named 'lnk'; did you mean 'link'?"),
            std::string::npos)
      << message(probe);
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

constexpr const char* kTetheredNet = R"(gravity: [0, 0, 0]
materials:
  dyneema: {youngs_modulus: 1.0e11, density: 970}
sections:
  thread: {shape: circle, diameter: 0.001}
  rope: {shape: circle, diameter: 0.003}
nets:
  - {name: net, type: square, side: 2.0, meshes: 2, material: dyneema, section: thread,
     knot_model: compliant, knot_mass: 0.001, knot_link: {type: linear, stiffness: 1.0e4},
     thread_breaking_force: 80, link_breaking_force: 120,
     tether: {chaser: [0, 0, -3], velocity: [0, 0, 0.5], attach: bridle, bridle_length: 2.0,
              material: dyneema, section: rope, elements: 6, natural_length: 2.0}}
probes:
  - {name: pull, quantity: max_tension, net: net}
  - {name: grip, quantity: link_force, link: net.bridle2.end}
)";

TEST(NetScene, ReadsTetherFailureAndTensionProbes) {
  const Scene scene = ParseScene(kTetheredNet);
  const Model& model = scene.model;
  const Cable& tether = model.cables()[model.FindCable("net.tether")];
  EXPECT_EQ(tether.num_elements, 6);
  EXPECT_DOUBLE_EQ(tether.length, 2.0);
  EXPECT_TRUE(tether.properties.tension_only);  // the net's rope defaults
  EXPECT_DOUBLE_EQ(tether.properties.rope_smoothing_strain, 1e-4);
  const Index chaser = model.point_masses()[model.FindPointMass("net.chaser")].dof;
  EXPECT_DOUBLE_EQ(model.initial_velocities()[chaser + 2], 0.5);
  EXPECT_TRUE(model.fixed()[chaser]);
  EXPECT_DOUBLE_EQ(model.cables()[model.FindCable("net.t0")].breaking_force, 80.0);
  EXPECT_DOUBLE_EQ(model.links()[0].breaking_force, 120.0);
  ASSERT_EQ(scene.probes.size(), 2u);
  EXPECT_EQ(scene.probes[0].quantity, ProbeQuantity::kMaxTension);
  EXPECT_EQ(model.links()[scene.probes[1].link].name, "net.bridle2.end");
}

TEST(NetScene, RefusesABridleLengthWithoutABridle) {
  std::string text = kTetheredNet;
  text.replace(text.find("attach: bridle, "), 16, "");
  try {
    ParseScene(text, "net.yaml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("net.yaml:11:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bridle_length needs attach: bridle"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

TEST(NetScene, GraphThreadsMayHaveTheirOwnSectionElementsAndLength) {
  const Scene scene = ParseScene(R"(gravity: [0, 0, 0]
materials:
  dyneema: {youngs_modulus: 1.0e11, density: 970}
  nylon: {youngs_modulus: 3.0e9, density: 1140}
sections:
  thread: {shape: circle, diameter: 0.001}
  rope: {shape: circle, diameter: 0.004}
nets:
  - name: kite
    type: graph
    material: dyneema
    section: thread
    knot_positions: [[0, 0, 0], [1, 0, 0], [1, 1, 0]]
    threads: [[0, 1], {knots: [1, 2], section: rope, elements: 3},
              {knots: [2, 0], material: nylon, natural_length: 1.5}]
)");
  const Model& model = scene.model;
  const auto& cables = model.cables();
  const Cable& plain = cables[model.FindCable("kite.t0")];
  const Cable& thick = cables[model.FindCable("kite.t1")];
  const Cable& soft = cables[model.FindCable("kite.t2")];
  EXPECT_EQ(plain.num_elements, 1);
  EXPECT_DOUBLE_EQ(plain.length, 1.0);
  EXPECT_EQ(thick.num_elements, 3);
  EXPECT_NEAR(thick.properties.axial_stiffness / plain.properties.axial_stiffness, 16.0, 1e-12);
  EXPECT_TRUE(thick.properties.tension_only);  // the net's rope settings stay
  EXPECT_DOUBLE_EQ(soft.length, 1.5);          // slack: √2 m apart
  EXPECT_NEAR(soft.properties.axial_stiffness / plain.properties.axial_stiffness, 0.03, 1e-12);
}

}  // namespace
}  // namespace ancfnet
