// The capstan equation (Euler 1762, Eytelwein 1808): a rope sliding steadily over a fixed rough
// cylinder, wrapped by the angle θ, needs the pull T = W e^{μθ} to lift the weight W on its
// other end. Here a low-bending-stiffness ANCF cable lies over a horizontal cylinder target; its
// pulled end is a point mass moved at constant speed u, its other end a hanging point mass of
// weight W. The tensions are read in the middles of the two straight runs (recovered from the
// elements' end forces, as the VTK field is) once the sliding is steady; the force the contact
// probe reports on the cylinder is checked against the two tensions.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "ancfnet/analysis/cable_tension.hpp"
#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kCylinderRadius = 0.05;  // m
constexpr double kRopeRadius = 1e-3;      // m
constexpr double kWrapRadius = kCylinderRadius + kRopeRadius;
constexpr double kRun = 0.15;            // length of each straight run (m)
constexpr double kElementLength = 0.01;  // m
constexpr double kMass = 1.0;            // hanging mass (kg)
constexpr double kGravity = 9.81;
constexpr double kSpeed = 0.05;  // pulling speed u (m/s)

// The rope's centre line: the pulled run along the tangent at A (angle α_A = π/2 − θ), the arc
// ρ (sin α, 0, cos α) for α ∈ [α_A, π/2], then straight down from B = (ρ, 0, 0).
struct Path {
  double theta;
  double alpha_a() const { return std::numbers::pi / 2 - theta; }
  double length() const { return 2 * kRun + kWrapRadius * theta; }
  Vector3d Tangent(double alpha) const { return {std::cos(alpha), 0.0, -std::sin(alpha)}; }
  // Position and unit tangent at arc length s from the pulled end.
  std::pair<Vector3d, Vector3d> At(double s) const {
    const Vector3d a = kWrapRadius * Vector3d(std::sin(alpha_a()), 0, std::cos(alpha_a()));
    if (s <= kRun) return {a - (kRun - s) * Tangent(alpha_a()), Tangent(alpha_a())};
    const double arc = kWrapRadius * theta;
    if (s <= kRun + arc) {
      const double alpha = alpha_a() + (s - kRun) / kWrapRadius;
      return {kWrapRadius * Vector3d(std::sin(alpha), 0, std::cos(alpha)), Tangent(alpha)};
    }
    return {Vector3d(kWrapRadius, 0, -(s - kRun - arc)), -Vector3d::UnitZ()};
  }
};

struct Capstan {
  double pull = 0.0;          // tension in the middle of the pulled run (N), time average
  double hold = 0.0;          // tension in the middle of the hanging run (N)
  double weight_speed = 0.0;  // upward speed of the weight at the end (m/s)
  Vector3d force_on_cylinder = Vector3d::Zero();  // contact probe, time average (N)
  double max_penetration = 0.0;
  long steps = 0, cuts = 0;
};

Capstan RunCapstan(double theta, std::optional<FrictionLaw> friction) {
  const Path path{theta};
  const int elements = static_cast<int>(std::round(path.length() / kElementLength));
  const double h = path.length() / elements;
  Material rope{.youngs_modulus = 1e9, .density = 1000.0, .axial_damping_time = 1e-2};
  CableProperties properties = MakeCableProperties(rope, MakeCircleSection(2 * kRopeRadius));
  // Rope-like: EI/(W ρ²) = 4·10⁻⁴. With the section's own EI = 7.9·10⁻⁴ N m² (0.031) the ratio
  // comes out 0.5 % low, with 3·10⁻³ N m² (0.12) 2.1 % low: the rope does not follow the
  // cylinder where it enters and leaves it.
  properties.bending_stiffness = 1e-5;
  properties.bending_damping_time = 1e-2;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  const Vector3d start = path.At(0.0).first, end = path.At(path.length()).first;
  builder.AddPointMass("puller", 0.0, start);
  builder.MovePointMass("puller", -kSpeed * path.Tangent(path.alpha_a()));
  builder.AddPointMass("weight", kMass, end);
  builder.AddCable({.name = "rope",
                    .start = start,
                    .end = end,
                    .num_elements = elements,
                    .properties = properties,
                    .natural_length = path.length(),
                    .start_knot = "puller",
                    .end_knot = "weight"});
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.5);
  spec.friction = friction;
  ContactTarget cylinder;
  cylinder.kind = ContactTarget::Kind::kCylinder;
  cylinder.name = "capstan";
  cylinder.normal = Vector3d::UnitY();
  cylinder.radius = kCylinderRadius;
  cylinder.half_length = 0.05;
  spec.targets.push_back(cylinder);
  builder.SetContact(spec);
  const Model model = builder.Build();

  // Lay the rope on its path (the straight cable of the builder is only its chord).
  State state = MakeInitialState(model);
  const Cable& cable = model.cables()[0];
  for (Index k = 0; k <= elements; ++k) {
    const CableElement& element =
        model.elements()[cable.first_element + std::min<Index>(k, elements - 1)];
    const int node = k < elements ? 0 : 2;
    const auto [r, t] = path.At(k * h);
    state.q.segment<3>(element.dofs[3 * node]) = r;
    state.q.segment<3>(element.dofs[3 * node + 3]) = t;
  }

  DynamicSettings settings;
  settings.time_step = 5e-4;
  settings.end_time = 1.0;
  const double average_from = 0.6;
  const TargetContact contact(model);
  std::vector<ContactPoint> records;
  Capstan result;
  int samples = 0;
  const auto tension_at = [&](double s, const State& st) {
    const Index e = cable.first_element + static_cast<Index>(s / h);
    const CableElement& element = model.elements()[e];
    const double xi = s / h - std::floor(s / h);
    // The tension recovered from the elements' end forces (analysis/cable_tension.hpp), the
    // section force N r' along the tangent: N λ, λ = |r'| (without λ, 0.3 % low here).
    const CableStationForces forces =
        CalcCableStationForces(model, cable, e - cable.first_element, st.q);
    return CalcCableStationTension(element.parameters, model.Gather(element, st.q), forces, xi);
  };
  const SolveResult solve = SolveDynamic(
      model, settings, 0.01,
      [&](const State& s, const EnergyAccount&) {
        records.clear();
        contact.CollectContacts(s.q, s.v, s.contact_history, &records);
        const ContactProbeValues c = CalcContactProbeValues(records, 0, Vector3d::Zero());
        result.max_penetration = std::max(result.max_penetration, c.max_penetration);
        if (s.t < average_from - 1e-9) return;
        // The material has moved towards the puller by u t: read the middles of the runs as they
        // are now (the material point at arc length s is at path.At(s − u t)).
        const double drift = kSpeed * s.t;
        result.pull += tension_at(0.5 * (kRun + drift), s);
        result.hold += tension_at(path.length() - 0.5 * (kRun - drift), s);
        result.force_on_cylinder += c.force_on_target;
        ++samples;
      },
      &state);
  EXPECT_TRUE(solve.completed) << solve.message;
  result.pull /= samples;
  result.hold /= samples;
  result.force_on_cylinder /= samples;
  result.weight_speed = state.v.segment<3>(model.point_masses()[1].dof).z();
  result.steps = solve.statistics.steps;
  result.cuts = solve.statistics.step_cuts;
  return result;
}

void ExpectCapstan(double theta, std::optional<FrictionLaw> friction, double tolerance) {
  const Capstan c = RunCapstan(theta, friction);
  const double mu = friction ? friction->kinetic_coefficient : 0.0;
  const double weight = kMass * kGravity;
  const double expected = std::exp(mu * theta);
  std::printf(
      "capstan θ = %.4f, μ = %.2f: T_pull/W = %.4f (e^μθ = %.4f, error %+.2f %%), T_hold/W = "
      "%.4f, weight rises at %.4f m/s, deepest %.2e m, %ld steps, %ld cut\n",
      theta, mu, c.pull / weight, expected, 100 * (c.pull / weight / expected - 1), c.hold / weight,
      c.weight_speed, c.max_penetration, c.steps, c.cuts);
  EXPECT_NEAR(c.pull / weight / expected, 1.0, tolerance);
  EXPECT_NEAR(c.hold / weight, 1.0, 0.005);
  EXPECT_NEAR(c.weight_speed, kSpeed, 0.01 * kSpeed);
  // The cylinder carries both runs' tensions, along their directions.
  const Path path{theta};
  const Vector3d expected_force =
      -c.pull * path.Tangent(path.alpha_a()) - c.hold * Vector3d::UnitZ();
  std::printf(
      "  force on the cylinder (%.4f, %.4f, %.4f) N, from the tensions (%.4f, %.4f, %.4f)\n",
      c.force_on_cylinder.x(), c.force_on_cylinder.y(), c.force_on_cylinder.z(), expected_force.x(),
      expected_force.y(), expected_force.z());
  EXPECT_LT((c.force_on_cylinder - expected_force).norm(), 0.005 * expected_force.norm());
  EXPECT_LT(c.max_penetration, 0.1 * kRopeRadius);
}

// The issue asks for 3 %; measured: +0.08 % (half turn, tanh), +0.09 % (quarter turn), +0.09 %
// (Ambrósio), +0.03 % without friction, so 1 % is asserted.
// tanh with v_r = 10⁻³ m/s: tanh(u/v_r) = tanh(50) = 1 at the sliding speed.
TEST(Capstan, HalfTurnTanhFriction) {
  ExpectCapstan(std::numbers::pi, MakeTanhFriction(0.25, 0.25, 1e-3, 1.0), 0.01);
}
TEST(Capstan, QuarterTurnTanhFriction) {
  ExpectCapstan(std::numbers::pi / 2, MakeTanhFriction(0.25, 0.25, 1e-3, 1.0), 0.01);
}
// Ambrósio's ramp from 10⁻⁴ to 10⁻³ m/s, full μ at the sliding speed.
TEST(Capstan, HalfTurnAmbrosioFriction) {
  ExpectCapstan(std::numbers::pi, MakeAmbrosioFriction(0.3, 1e-4, 1e-3), 0.01);
}
TEST(Capstan, HalfTurnWithoutFriction) { ExpectCapstan(std::numbers::pi, std::nullopt, 0.01); }

}  // namespace
}  // namespace ancfnet
