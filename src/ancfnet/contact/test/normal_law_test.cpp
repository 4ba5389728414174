#include "ancfnet/contact/laws/normal_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

const std::vector<NormalLawKind> kDissipative = {
    NormalLawKind::kHuntCrossley, NormalLawKind::kLankaraniNikravesh, NormalLawKind::kFlores,
    NormalLawKind::kGonthier, NormalLawKind::kCarvalhoMartins};

// Both partial derivatives against central differences, 1e-6 relative.
void ExpectDerivativesMatch(const NormalLaw& law, double delta, double delta_dot, double v0,
                            const std::string& what) {
  const NormalForce f = law.Evaluate(delta, delta_dot, v0);
  const double hd = 1e-6 * delta;
  const double hv = 1e-6 * std::max(std::abs(delta_dot), v0);
  const double fd_delta = (law.Evaluate(delta + hd, delta_dot, v0).force -
                           law.Evaluate(delta - hd, delta_dot, v0).force) /
                          (2 * hd);
  const double fd_rate = (law.Evaluate(delta, delta_dot + hv, v0).force -
                          law.Evaluate(delta, delta_dot - hv, v0).force) /
                         (2 * hv);
  const double scale_delta = std::abs(f.dforce_ddelta) + std::abs(fd_delta);
  const double scale_rate = std::abs(f.dforce_ddelta_dot) + std::abs(fd_rate);
  EXPECT_NEAR(f.dforce_ddelta, fd_delta, 1e-6 * scale_delta + 1e-12) << "dF/ddelta " << what;
  EXPECT_NEAR(f.dforce_ddelta_dot, fd_rate, 1e-6 * scale_rate + 1e-12) << "dF/ddelta_dot " << what;
}

TEST(NormalLaw, DerivativesMatchFiniteDifferences) {
  const std::vector<double> rates = {-1.5, -0.3, 0.0, 0.7, 2.0};
  for (double n : {1.0, 1.5, 2.2}) {
    for (NormalLawKind kind : kDissipative) {
      const NormalLaw law = MakeDissipativeContactLaw(kind, 3.0e7, 0.6, n);
      for (double rate : rates) {
        ExpectDerivativesMatch(law, 2e-4, rate, 1.2,
                               "kind " + std::to_string(static_cast<int>(kind)) + " n " +
                                   std::to_string(n) + " rate " + std::to_string(rate));
      }
    }
    ExpectDerivativesMatch(MakeHertzContactLaw(3.0e7, n), 2e-4, 0.3, 1.0, "Hertz");
  }
  const NormalLaw linear = MakeLinearContactLaw(1.0e5, 40.0);
  for (double rate : rates) ExpectDerivativesMatch(linear, 1e-3, rate, 1.0, "linear");
}

TEST(NormalLaw, ValuesOfTheForms) {
  const NormalLaw hc = MakeDissipativeContactLaw(NormalLawKind::kHuntCrossley, 1e6, 0.8);
  const double chi = 1.5 * 0.2;
  EXPECT_DOUBLE_EQ(hc.hysteresis_factor(), chi);
  const NormalForce f = hc.Evaluate(1e-4, 0.5, 2.0);
  EXPECT_NEAR(f.force, 1e6 * std::pow(1e-4, 1.5) * (1 + chi * 0.5 / 2.0), 1e-12);
  EXPECT_NEAR(f.elastic_force, 1e6 * std::pow(1e-4, 1.5), 1e-12);
  // The stored approach speed is floored: v0 = 0 behaves as v0 = v_min.
  EXPECT_DOUBLE_EQ(hc.Evaluate(1e-4, 1e-4, 0.0).force, hc.Evaluate(1e-4, 1e-4, 1e-3).force);
  EXPECT_NEAR(
      MakeDissipativeContactLaw(NormalLawKind::kLankaraniNikravesh, 1, 0.5).hysteresis_factor(),
      0.75 * 0.75, 1e-15);
  EXPECT_NEAR(MakeDissipativeContactLaw(NormalLawKind::kFlores, 1, 0.5).hysteresis_factor(),
              8 * 0.5 / 2.5, 1e-15);
  EXPECT_NEAR(MakeDissipativeContactLaw(NormalLawKind::kGonthier, 1, 0.5).hysteresis_factor(),
              0.75 / 0.5, 1e-15);
  // Carvalho–Martins meets Gonthier at e = 1/3 and Hunt–Crossley's slope at e → 1.
  EXPECT_NEAR(CalcHysteresisFactor(NormalLawKind::kCarvalhoMartins, 1.0 / 3.0),
              CalcHysteresisFactor(NormalLawKind::kGonthier, 1.0 / 3.0), 1e-14);
  EXPECT_NEAR(CalcHysteresisFactor(NormalLawKind::kCarvalhoMartins, 1 - 1e-6),
              CalcHysteresisFactor(NormalLawKind::kHuntCrossley, 1 - 1e-6), 1e-11);
  EXPECT_DOUBLE_EQ(hc.CalcElasticEnergy(1e-4), 1e6 * std::pow(1e-4, 2.5) / 2.5);
}

TEST(NormalLaw, NeverPullsAndNothingApart) {
  for (NormalLawKind kind : kDissipative) {
    const NormalLaw law = MakeDissipativeContactLaw(kind, 1e6, 0.3);
    const double pulling_rate = -2.0 / law.hysteresis_factor();  // 1 + χ̂ δ̇/v0 = −1 at v0 = 1
    const NormalForce f = law.Evaluate(1e-4, pulling_rate, 1.0);
    EXPECT_EQ(f.force, 0.0);
    EXPECT_EQ(f.dforce_ddelta, 0.0);
    EXPECT_EQ(f.dforce_ddelta_dot, 0.0);
    EXPECT_EQ(law.Evaluate(-1e-4, 1.0, 1.0).force, 0.0);
    EXPECT_EQ(law.Evaluate(0.0, 1.0, 1.0).force, 0.0);
  }
  const NormalLaw linear = MakeLinearContactLaw(1e5, 100.0);
  EXPECT_EQ(linear.Evaluate(1e-3, -2.0, 0.0).force, 0.0);  // 100 − 200 < 0
  EXPECT_DOUBLE_EQ(linear.Evaluate(1e-3, 0.5, 0.0).force, 150.0);
}

TEST(NormalLaw, RestitutionRelationIsSolved) {
  for (double chi : {1e-6, 0.01, 0.3, 1.0, 2.5, 10.0}) {
    const double e = CalcRestitutionForHysteresisFactor(chi);
    ASSERT_GT(e, 0.0);
    ASSERT_LE(e, 1.0);
    EXPECT_NEAR(chi * (1 + e), std::log((1 + chi) / (1 - chi * e)), 1e-12 * (1 + chi))
        << "chi " << chi;
  }
  EXPECT_EQ(CalcRestitutionForHysteresisFactor(0.0), 1.0);
  // Small damping: e* ≈ 1 − 2χ̂/3 (Hunt–Crossley's linearisation).
  EXPECT_NEAR(CalcRestitutionForHysteresisFactor(1e-3), 1 - 2e-3 / 3, 1e-5);
  EXPECT_THROW(CalcRestitutionForHysteresisFactor(-1.0), InputError);
}

TEST(NormalLaw, InvalidParametersThrow) {
  EXPECT_THROW(MakeHertzContactLaw(0.0), InputError);
  EXPECT_THROW(MakeHertzContactLaw(1e6, 0.0), InputError);
  EXPECT_THROW(MakeHertzContactLaw(std::nan(""), 1.5), InputError);
  EXPECT_THROW(MakeLinearContactLaw(1e5, -1.0), InputError);
  EXPECT_THROW(MakeDissipativeContactLaw(NormalLawKind::kFlores, 1e6, 0.0), InputError);
  EXPECT_THROW(MakeDissipativeContactLaw(NormalLawKind::kFlores, 1e6, 1.2), InputError);
  EXPECT_THROW(MakeDissipativeContactLaw(NormalLawKind::kGonthier, -1e6, 0.5), InputError);
  EXPECT_THROW(MakeDissipativeContactLaw(NormalLawKind::kGonthier, 1e6, 0.5, 1.5, 0.0), InputError);
  EXPECT_THROW(MakeDissipativeContactLaw(NormalLawKind::kHertz, 1e6, 0.5), InputError);
  EXPECT_NO_THROW(MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 1.0));
}

}  // namespace
}  // namespace ancfnet
