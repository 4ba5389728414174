// A mass m hits a rigid wall at v0: m δ̈ = −F_n(δ, δ̇, v0), δ(0) = 0, δ̇(0) = v0, integrated
// with classical RK4 at a small step until the mass leaves the wall. Checks the achieved
// restitution of every dissipative law against the exact relation, the Hertz impact duration and
// peak force, and the energy balance (docs/validation.md, "Contact force laws").

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ancfnet/contact/laws/normal_law.hpp"

namespace ancfnet {
namespace {

struct ImpactResult {
  double restitution = 0.0;      // e* = −δ̇_out/v0
  double duration = 0.0;         // time from touching to leaving (δ back to 0) (s)
  double max_penetration = 0.0;  // (m)
  double max_force = 0.0;        // (N)
  double dissipated = 0.0;       // ∫ (F − k δⁿ) δ̇ dt (J)
};

ImpactResult SimulateImpact(const NormalLaw& law, double mass, double v0, int steps_per_scale) {
  // Hertz-like scale of the penetration, ((n+1) m v0²/(2k))^(1/(n+1)), and of the time.
  const double n = law.exponent;
  const double delta_scale = std::pow((n + 1) * mass * v0 * v0 / (2 * law.stiffness), 1 / (n + 1));
  const double h = delta_scale / v0 / steps_per_scale;
  using S = std::array<double, 3>;  // δ, δ̇, dissipated energy
  ImpactResult out;
  const auto rate = [&](const S& s) {
    const NormalForce f = law.Evaluate(s[0], s[1], v0);
    out.max_force = std::max(out.max_force, f.force);
    return S{s[1], -f.force / mass, (f.force - f.elastic_force) * s[1]};
  };
  S s = {0.0, v0, 0.0};
  double t = 0.0;
  for (int i = 0; i < 100 * steps_per_scale; ++i) {
    const S k1 = rate(s);
    S tmp;
    for (int j = 0; j < 3; ++j) tmp[j] = s[j] + 0.5 * h * k1[j];
    const S k2 = rate(tmp);
    for (int j = 0; j < 3; ++j) tmp[j] = s[j] + 0.5 * h * k2[j];
    const S k3 = rate(tmp);
    for (int j = 0; j < 3; ++j) tmp[j] = s[j] + h * k3[j];
    const S k4 = rate(tmp);
    S next;
    for (int j = 0; j < 3; ++j) next[j] = s[j] + h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    out.max_penetration = std::max(out.max_penetration, next[0]);
    if (next[0] <= 0.0 && next[1] < 0.0) {
      // Left the wall inside this step: the crossing time by linear interpolation in δ; the
      // velocity is constant once δ < 0 (no force).
      out.duration = t + h * s[0] / (s[0] - next[0]);
      out.restitution = -next[1] / v0;
      out.dissipated = next[2];
      return out;
    }
    s = next;
    t += h;
  }
  ADD_FAILURE() << "the mass never left the wall";
  return out;
}

struct LawCase {
  NormalLawKind kind;
  const char* name;
};
const std::vector<LawCase> kLaws = {{NormalLawKind::kHuntCrossley, "Hunt-Crossley"},
                                    {NormalLawKind::kLankaraniNikravesh, "Lankarani-Nikravesh"},
                                    {NormalLawKind::kFlores, "Flores"},
                                    {NormalLawKind::kGonthier, "Gonthier"},
                                    {NormalLawKind::kCarvalhoMartins, "Carvalho-Martins"}};
const std::vector<double> kRestitutions = {0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95};

// e* solves χ̂(1 + e*) = ln[(1 + χ̂)/(1 − χ̂ e*)] whatever k, n, m and v0: two values of each.
TEST(NormalImpact, AchievedRestitutionFollowsTheExactRelation) {
  double worst = 0.0;
  for (const LawCase& c : kLaws) {
    for (double e : kRestitutions) {
      const double chi = CalcHysteresisFactor(c.kind, e);
      const double expected = CalcRestitutionForHysteresisFactor(chi);
      for (double k : {1e6, 5e8}) {
        for (double n : {1.0, 1.5}) {
          for (double m : {0.01, 2.0}) {
            for (double v0 : {0.2, 15.0}) {
              const NormalLaw law = MakeDissipativeContactLaw(c.kind, k, e, n);
              const double achieved = SimulateImpact(law, m, v0, 400).restitution;
              worst = std::max(worst, std::abs(achieved - expected));
              EXPECT_NEAR(achieved, expected, 2e-3)
                  << c.name << " e " << e << " k " << k << " n " << n << " m " << m << " v0 " << v0;
            }
          }
        }
      }
    }
  }
  std::printf("largest |e* - e*_exact| over 640 impacts: %.1e\n", worst);
}

// The table of docs/validation.md: e* of each law against its input e.
TEST(NormalImpact, RestitutionTableAndCarvalhoMartinsStaysClose) {
  std::printf("| e |");
  for (const LawCase& c : kLaws) std::printf(" %s |", c.name);
  std::printf("\n");
  for (double e : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
    std::printf("| %.2f |", e);
    for (const LawCase& c : kLaws) {
      const NormalLaw law = MakeDissipativeContactLaw(c.kind, 1e7, e);
      const double achieved = SimulateImpact(law, 0.1, 2.0, 2000).restitution;
      std::printf(" %.4f |", achieved);
      // Carvalho & Martins (2019) give their χ̂ for e ≥ 1/3 (below it Gonthier's, which equals
      // it at 1/3): within 2 % of e from 0.3 up (measured ≤ 1.4 %).
      if (c.kind == NormalLawKind::kCarvalhoMartins && e >= 0.3) {
        EXPECT_NEAR(achieved, e, 0.02 * e) << "e " << e;
      }
      // Hunt–Crossley and Lankarani–Nikravesh are built for e → 1 and overshoot e below 0.7.
      if ((c.kind == NormalLawKind::kHuntCrossley ||
           c.kind == NormalLawKind::kLankaraniNikravesh) &&
          e <= 0.5) {
        EXPECT_GT(achieved, e + 0.15) << c.name << " e " << e;
      }
    }
    std::printf("\n");
  }
}

// Hertz: δ_max = (5 m v0²/(4k))^(2/5), F_max = k δ_max^(3/2), t_c = 2.943275 δ_max/v0
// (Johnson 1985, ch. 11), e* = 1.
TEST(NormalImpact, HertzDurationAndPeakForce) {
  for (double k : {1e7, 3e9}) {
    for (double m : {0.05, 4.0}) {
      for (double v0 : {0.5, 10.0}) {
        const ImpactResult r = SimulateImpact(MakeHertzContactLaw(k), m, v0, 2000);
        const double delta_max = std::pow(5 * m * v0 * v0 / (4 * k), 0.4);
        EXPECT_NEAR(r.max_penetration, delta_max, 1e-4 * delta_max);
        EXPECT_NEAR(r.max_force, k * std::pow(delta_max, 1.5), 5e-3 * k * std::pow(delta_max, 1.5));
        EXPECT_NEAR(r.duration, 2.943275 * delta_max / v0, 5e-3 * 2.943275 * delta_max / v0);
        EXPECT_NEAR(r.restitution, 1.0, 1e-6);
        std::printf("Hertz k %.0e m %.2f v0 %.1f: t_c %+.1e, F_max %+.1e relative\n", k, m, v0,
                    r.duration / (2.943275 * delta_max / v0) - 1,
                    r.max_force / (k * std::pow(delta_max, 1.5)) - 1);
      }
    }
  }
}

// The energy the law dissipates, ∫ (F − k δⁿ) δ̇ dt, equals the kinetic energy lost.
TEST(NormalImpact, DissipatedEnergyEqualsKineticEnergyLost) {
  const double m = 0.3;
  const double v0 = 3.0;
  std::vector<NormalLaw> laws;
  for (const LawCase& c : kLaws) laws.push_back(MakeDissipativeContactLaw(c.kind, 2e7, 0.5));
  laws.push_back(MakeLinearContactLaw(1e5, 30.0));  // clips to 0 before δ returns to 0
  for (const NormalLaw& law : laws) {
    const ImpactResult r = SimulateImpact(law, m, v0, 2000);
    const double lost = 0.5 * m * v0 * v0 * (1 - r.restitution * r.restitution);
    ASSERT_GT(lost, 0.0);
    EXPECT_NEAR(r.dissipated, lost, 5e-3 * lost) << "kind " << static_cast<int>(law.kind);
    std::printf("kind %d: e* %.4f, dissipated/lost - 1 = %+.1e\n", static_cast<int>(law.kind),
                r.restitution, r.dissipated / lost - 1);
  }
}

}  // namespace
}  // namespace ancfnet
