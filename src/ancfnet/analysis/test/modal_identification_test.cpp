// Modal identification by the matrix pencil method on synthetic free decays whose modes are known
// exactly: y(t) = Σ_k A_k e^{−ζ_k ω_k t} cos(ω_k √(1 − ζ_k²) t + φ_k) (+ offset, + noise).

#include "ancfnet/analysis/modal_identification.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

struct KnownMode {
  double frequency;  // Hz, undamped
  double damping_ratio;
  double amplitude;
  double phase;  // rad
};

// f = 1.3, 8.2, 23, 45, 74 Hz with ζ = 1 … 5 %: close to a cantilever's first modes, the damping
// growing with the mode as it does in a measured structure.
const std::vector<KnownMode> kModes = {{1.3, 0.01, 1.0, 0.3},
                                       {8.2, 0.02, 0.8, -1.1},
                                       {23.0, 0.03, 0.6, 2.0},
                                       {45.0, 0.04, 0.5, 0.7},
                                       {74.0, 0.05, 0.4, -2.5}};
constexpr double kStep = 1.0 / 400.0;  // s: 400 Hz sampling, Nyquist 200 Hz
constexpr Index kSamples = 1200;       // 3 s: about four periods of the 1.3 Hz mode

double ModeValue(const KnownMode& m, double t) {
  const double omega = 2.0 * std::numbers::pi * m.frequency;
  const double omega_d = omega * std::sqrt(1.0 - m.damping_ratio * m.damping_ratio);
  return m.amplitude * std::exp(-m.damping_ratio * omega * t) * std::cos(omega_d * t + m.phase);
}

VectorXd MakeDecay(const std::vector<KnownMode>& modes, double offset = 0.0, Index n = kSamples) {
  VectorXd y = VectorXd::Constant(n, offset);
  for (Index i = 0; i < n; ++i)
    for (const KnownMode& m : modes) y(i) += ModeValue(m, static_cast<double>(i) * kStep);
  return y;
}

// Adds white Gaussian noise of RMS `relative` × the RMS of y (fixed seed).
void AddNoise(double relative, unsigned seed, VectorXd* y) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double rms = std::sqrt(y->squaredNorm() / static_cast<double>(y->size()));
  for (Index i = 0; i < y->size(); ++i) (*y)(i) += relative * rms * normal(generator);
}

ModalIdentificationOptions Options(int modes) {
  ModalIdentificationOptions options;
  options.modes = modes;
  return options;
}

TEST(ModalIdentification, OneModeNoiselessIsExact) {
  const KnownMode mode = kModes[1];
  const ModalIdentification id = IdentifyModes(kStep, MakeDecay({mode}), Options(1));
  ASSERT_EQ(id.modes.size(), 1u);
  const IdentifiedMode& m = id.modes[0];
  EXPECT_NEAR(m.frequency, mode.frequency, 1e-9 * mode.frequency);
  EXPECT_NEAR(m.damping_ratio, mode.damping_ratio, 1e-9);
  EXPECT_NEAR(m.damped_frequency,
              mode.frequency * std::sqrt(1.0 - mode.damping_ratio * mode.damping_ratio), 1e-9);
  EXPECT_NEAR(m.amplitude(0), mode.amplitude, 1e-9);
  EXPECT_NEAR(m.phase(0), mode.phase, 1e-9);
  EXPECT_NEAR(m.energy_fraction, 1.0, 0.05);  // the pair's cross term is left out
  EXPECT_LT(id.relative_residual, 1e-9);
  EXPECT_EQ(id.model_order, 3);  // one pair and the offset pole
  EXPECT_EQ(id.pencil, kSamples / 3);
}

// 1 to 5 modes at once, noiseless: f within 1e-6 relative, ζ within 1e-6 absolute.
TEST(ModalIdentification, UpToFiveModesNoiseless) {
  for (std::size_t k = 1; k <= kModes.size(); ++k) {
    SCOPED_TRACE(k);
    const std::vector<KnownMode> modes(kModes.begin(), kModes.begin() + k);
    const ModalIdentification id =
        IdentifyModes(kStep, MakeDecay(modes), Options(static_cast<int>(k)));
    ASSERT_EQ(id.modes.size(), k);
    for (std::size_t i = 0; i < k; ++i) {
      EXPECT_NEAR(id.modes[i].frequency, modes[i].frequency, 1e-6 * modes[i].frequency);
      EXPECT_NEAR(id.modes[i].damping_ratio, modes[i].damping_ratio, 1e-6);
      EXPECT_NEAR(id.modes[i].amplitude(0), modes[i].amplitude, 1e-6);
      EXPECT_NEAR(id.modes[i].phase(0), modes[i].phase, 1e-6);
    }
    EXPECT_LT(id.relative_residual, 1e-8);
  }
}

// A static offset is one more (real) pole at z = 1, s = 0: the modes stay exact.
TEST(ModalIdentification, ConstantOffsetIsAPoleAtZero) {
  const ModalIdentification id = IdentifyModes(kStep, MakeDecay(kModes, 0.7), Options(5));
  ASSERT_EQ(id.modes.size(), 5u);
  for (std::size_t i = 0; i < kModes.size(); ++i) {
    EXPECT_NEAR(id.modes[i].frequency, kModes[i].frequency, 1e-6 * kModes[i].frequency);
    EXPECT_NEAR(id.modes[i].damping_ratio, kModes[i].damping_ratio, 1e-6);
  }
  ASSERT_EQ(id.other_poles.size(), 1u);
  EXPECT_LT(std::abs(id.other_poles[0].pole), 1e-8);
  EXPECT_GT(id.other_poles[0].energy_fraction, 0.5);  // 0.7² against the decaying part

  // Without the offset pole the constant takes one of the 10 poles, and one mode is lost.
  ModalIdentificationOptions no_offset = Options(5);
  no_offset.fit_offset = false;
  EXPECT_THROW(IdentifyModes(kStep, MakeDecay(kModes, 0.7), no_offset), InputError);
}

// Removing the mean leaves the offset pole to absorb what the mean subtraction left over.
TEST(ModalIdentification, RemovingTheMeanKeepsTheModes) {
  ModalIdentificationOptions options = Options(5);
  options.remove_mean = true;
  const ModalIdentification id = IdentifyModes(kStep, MakeDecay(kModes, 100.0), options);
  for (std::size_t i = 0; i < kModes.size(); ++i) {
    EXPECT_NEAR(id.modes[i].frequency, kModes[i].frequency, 1e-6 * kModes[i].frequency);
    EXPECT_NEAR(id.modes[i].damping_ratio, kModes[i].damping_ratio, 1e-6);
    EXPECT_NEAR(id.modes[i].amplitude(0), kModes[i].amplitude, 1e-6);
  }
}

// 1 % RMS white noise: f within 0.5 % and ζ within 5 % (relative), for several seeds, with and
// without model-order over-estimation.
TEST(ModalIdentification, FiveModesWithNoise) {
  for (const int extra : {0, 10}) {
    for (const unsigned seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(::testing::Message() << "extra poles " << extra << ", seed " << seed);
      VectorXd y = MakeDecay(kModes, 0.2);
      AddNoise(0.01, seed, &y);
      ModalIdentificationOptions options = Options(5);
      options.extra_poles = extra;
      const ModalIdentification id = IdentifyModes(kStep, y, options);
      ASSERT_EQ(id.modes.size(), 5u);
      for (std::size_t i = 0; i < kModes.size(); ++i) {
        EXPECT_NEAR(id.modes[i].frequency, kModes[i].frequency, 5e-3 * kModes[i].frequency);
        EXPECT_NEAR(id.modes[i].damping_ratio, kModes[i].damping_ratio,
                    0.05 * kModes[i].damping_ratio);
      }
      EXPECT_LT(id.relative_residual, 0.02);  // about the noise
    }
  }
}

// Two signals sharing the poles, in different units, one lacking a mode: stacked Hankel blocks.
TEST(ModalIdentification, TwoSignalsSharePoles) {
  std::vector<KnownMode> second = kModes;
  for (KnownMode& m : second) {
    m.amplitude *= 1e-3;
    m.phase += 1.0;
  }
  second[2].amplitude = 0.0;  // a node of mode 3
  MatrixXd y(kSamples, 2);
  y.col(0) = MakeDecay(kModes);
  y.col(1) = MakeDecay(second, 5e-4);
  const ModalIdentification id = IdentifyModes(kStep, y, Options(5));
  ASSERT_EQ(id.modes.size(), 5u);
  for (std::size_t i = 0; i < kModes.size(); ++i) {
    EXPECT_NEAR(id.modes[i].frequency, kModes[i].frequency, 1e-6 * kModes[i].frequency);
    EXPECT_NEAR(id.modes[i].damping_ratio, kModes[i].damping_ratio, 1e-6);
    EXPECT_NEAR(id.modes[i].amplitude(0), kModes[i].amplitude, 1e-6);
    EXPECT_NEAR(id.modes[i].amplitude(1), second[i].amplitude, 1e-9);
    if (second[i].amplitude > 0.0) {
      EXPECT_NEAR(std::remainder(id.modes[i].phase(1) - second[i].phase, 2 * std::numbers::pi), 0.0,
                  1e-6);
    }
  }
}

// Extra poles do not disturb a noiseless fit; the K strongest pairs are the modes.
TEST(ModalIdentification, OverEstimatedOrderKeepsTheStrongestModes) {
  ModalIdentificationOptions options = Options(3);
  options.extra_poles = 8;
  const std::vector<KnownMode> modes(kModes.begin(), kModes.begin() + 3);
  const ModalIdentification id = IdentifyModes(kStep, MakeDecay(modes), options);
  EXPECT_EQ(id.model_order, 15);
  ASSERT_EQ(id.modes.size(), 3u);
  for (std::size_t i = 0; i < modes.size(); ++i) {
    EXPECT_NEAR(id.modes[i].frequency, modes[i].frequency, 1e-6 * modes[i].frequency);
    EXPECT_NEAR(id.modes[i].damping_ratio, modes[i].damping_ratio, 1e-6);
  }
  for (const OtherPole& p : id.other_poles) EXPECT_LT(p.energy_fraction, 1e-6);
  // The record has rank 6 (3 pairs, no offset): the singular values drop after the 6th, which
  // shows the order the record supports.
  EXPECT_LT(id.singular_values[6], 1e-8);
  EXPECT_GT(id.singular_values[5], 1e-4);
}

// Block means keep the poles exactly and the residues are corrected for the averaging.
TEST(ModalIdentification, DecimationKeepsPolesAndAmplitudes) {
  ModalIdentificationOptions options = Options(3);
  options.decimation = 3;  // Nyquist 200/3 Hz, above the third mode (23 Hz)
  const std::vector<KnownMode> modes(kModes.begin(), kModes.begin() + 3);
  const ModalIdentification id = IdentifyModes(kStep, MakeDecay(modes, 0.1), options);
  EXPECT_EQ(id.decimation, 3);
  EXPECT_NEAR(id.nyquist_frequency, 200.0 / 3.0, 1e-9);
  EXPECT_EQ(id.pencil, kSamples / 9);
  for (std::size_t i = 0; i < modes.size(); ++i) {
    EXPECT_NEAR(id.modes[i].frequency, modes[i].frequency, 1e-6 * modes[i].frequency);
    EXPECT_NEAR(id.modes[i].damping_ratio, modes[i].damping_ratio, 1e-6);
    EXPECT_NEAR(id.modes[i].amplitude(0), modes[i].amplitude, 1e-6);
    EXPECT_NEAR(id.modes[i].phase(0), modes[i].phase, 1e-6);
  }
}

// A record sampled 50 times faster than needed (20 kHz, 100 000 samples, 1 % noise). With D = 1
// the pencil, capped at 600 samples (30 ms, a twenty-fifth of the slowest period), cannot see the
// 1.3 Hz mode (it comes out at 2.26 Hz, and it takes 6 s); the automatic decimation (D = 56) fits
// block means and finds all five.
TEST(ModalIdentification, OverSampledRecordIsDecimated) {
  const double step = 1.0 / 20000.0;
  const Index n = 100000;
  VectorXd y = VectorXd::Zero(n);
  for (Index i = 0; i < n; ++i)
    for (const KnownMode& m : kModes) y(i) += ModeValue(m, static_cast<double>(i) * step);
  AddNoise(0.01, 4, &y);
  const ModalIdentification id = IdentifyModes(step, y, Options(5));
  EXPECT_EQ(id.decimation, 56);
  ASSERT_EQ(id.modes.size(), 5u);
  for (std::size_t i = 0; i < kModes.size(); ++i) {
    EXPECT_NEAR(id.modes[i].frequency, kModes[i].frequency, 5e-3 * kModes[i].frequency);
    EXPECT_NEAR(id.modes[i].damping_ratio, kModes[i].damping_ratio, 0.05 * kModes[i].damping_ratio);
    EXPECT_NEAR(id.modes[i].amplitude(0), kModes[i].amplitude, 0.02 * kModes[i].amplitude);
  }
}

// Sample times: t_0 ≠ 0 is fine (phases refer to t_0); a non-uniform step is refused.
TEST(ModalIdentification, SampleTimes) {
  const KnownMode mode = kModes[1];
  VectorXd time(kSamples);
  for (Index i = 0; i < kSamples; ++i) time(i) = 2.0 + static_cast<double>(i) * kStep;
  const ModalIdentification id = IdentifyModes(time, MakeDecay({mode}), Options(1));
  EXPECT_NEAR(id.time_step, kStep, 1e-15);
  EXPECT_NEAR(id.modes[0].frequency, mode.frequency, 1e-9 * mode.frequency);
  EXPECT_NEAR(id.modes[0].phase(0), mode.phase, 1e-9);

  time(500) += 0.01 * kStep;
  try {
    IdentifyModes(time, MakeDecay({mode}), Options(1));
    FAIL() << "a non-uniform sampling was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not uniform"), std::string::npos) << e.what();
  }
  EXPECT_THROW(IdentifyModes(time.head(10), MakeDecay({mode}), Options(1)), InputError);
}

TEST(ModalIdentification, BadInputIsRefused) {
  const VectorXd y = MakeDecay(kModes);
  EXPECT_THROW(IdentifyModes(kStep, y, Options(0)), InputError);
  ModalIdentificationOptions negative = Options(1);
  negative.extra_poles = -1;
  EXPECT_THROW(IdentifyModes(kStep, y, negative), InputError);
  EXPECT_THROW(IdentifyModes(0.0, y, Options(1)), InputError);
  EXPECT_THROW(IdentifyModes(std::nan(""), y, Options(1)), InputError);
  // 5 modes and the offset: order 11, 23 samples needed.
  EXPECT_THROW(IdentifyModes(kStep, MakeDecay(kModes, 0.0, 22), Options(5)), InputError);
  EXPECT_NO_THROW(IdentifyModes(kStep, MakeDecay(kModes, 0.0, 23), Options(5)));
  VectorXd with_nan = y;
  with_nan(7) = std::nan("");
  EXPECT_THROW(IdentifyModes(kStep, with_nan, Options(1)), InputError);
  EXPECT_THROW(IdentifyModes(kStep, VectorXd::Constant(100, 3.0), Options(1)), InputError);
  EXPECT_THROW(IdentifyModes(kStep, MatrixXd(100, 0), Options(1)), InputError);
  try {
    IdentifyModes(kStep, MakeDecay(kModes, 0.0, 20), Options(5));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too few"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ancfnet
