#pragma once
/// @file Modal identification: natural frequencies, damping ratios, amplitudes and phases of the
/// damped modes in a free-decay (or post-impulse) record, by the matrix pencil method.
///
/// The record of each signal c is modelled as a sum of M damped complex exponentials,
///   y_c(t_n) = Σ_i h_ci z_iⁿ,  z_i = exp(s_i Δt),  t_n = t_0 + n Δt,
/// whose poles z_i are shared by all signals. A real damped mode is a conjugate pair
/// s = −ζ ω_n ± i ω_n √(1 − ζ²), and contributes A e^{−ζ ω_n (t − t_0)} cos(ω_d (t − t_0) + φ).
/// The poles come from the matrix pencil of the (block) Hankel matrix of the samples with SVD
/// truncation to rank M (Hua & Sarkar 1990, IEEE Trans. ASSP 38(5) 814–824; Sarkar & Pereira 1995,
/// IEEE Antennas Propag. Mag. 37(1) 48–55); the residues h_ci from linear least squares on the
/// Vandermonde system. Derivation and the choice of method: docs/theory.md, "Modal identification
/// (matrix pencil)".

#include <complex>
#include <string>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Settings of IdentifyModes.
struct ModalIdentificationOptions {
  /// K: the number of damped (oscillating) modes to report, ≥ 1.
  int modes = 1;
  /// Poles fitted beyond the 2K of the modes (model-order over-estimation), ≥ 0. The model order
  /// is M = 2K + extra_poles (+ 1 with fit_offset). The extra poles soak up noise, a drift or a
  /// weak mode that was not asked for; the K oscillating pole pairs with the largest energy are
  /// reported and the others listed in ModalIdentification::other_poles. Without noise the true
  /// poles are exact eigenvalues of the pencil whatever the extra poles, so this costs no accuracy.
  int extra_poles = 0;
  /// Fit one more (real) pole for a constant offset (a static deflection, a sensor bias): it lands
  /// at z ≈ 1 and is listed in other_poles. Recommended; off only for a record known to have none.
  bool fit_offset = true;
  /// Subtract each signal's mean before the fit. The mean of a decaying record is not its static
  /// offset (the decaying part has a mean too), so this does not replace fit_offset; it keeps a
  /// large offset from dominating the singular values. Amplitudes are unaffected.
  bool remove_mean = false;
  /// Pencil parameter L as a fraction of the number of samples N: L = round(fraction · N), capped
  /// at max_pencil. Hua & Sarkar (1990) find the least noise sensitivity for N/3 ≤ L ≤ N/2.
  double pencil_fraction = 1.0 / 3.0;
  /// Upper bound of L, which bounds the cost O(N L²) and the memory O(L²) for long records.
  Index max_pencil = 600;
  /// D: fit the means of consecutive blocks of D samples, ȳ[m] = (1/D) Σ_{j<D} y[mD + j], at the
  /// step D Δt. Block means of Σ h zⁿ are Σ h G(z) (z^D)^m with G(z) = (1/D) Σ_{j<D} z^j: the poles
  /// are kept exactly and the residues are divided by G back, while white noise falls by √D. It
  /// makes an over-sampled record usable (a pencil of L ≤ max_pencil samples must span a good part
  /// of the slowest period) but lowers the Nyquist frequency to 1/(2 D Δt): faster modes alias.
  /// 0 (default): the smallest D with N/D ≤ 3 max_pencil, so that L ≈ N/(3D) is not capped.
  Index decimation = 0;
  /// Names of the signals for the error messages (e.g. "tip.z"); "signal 1", … when empty.
  std::vector<std::string> signal_names;
  /// IdentifyModes(time, …) accepts |t_{n+1} − t_n − Δt| ≤ tolerance · Δt, Δt the mean step.
  double sampling_tolerance = 1e-3;
};

/// One identified damped mode.
struct IdentifiedMode {
  double frequency = 0.0;         ///< undamped natural frequency f = ω_n / 2π = |s| / 2π (Hz)
  double damping_ratio = 0.0;     ///< ζ = −Re(s) / |s| (negative: a growing oscillation)
  double damped_frequency = 0.0;  ///< f_d = Im(s) / 2π = f √(1 − ζ²) (Hz)
  std::complex<double> pole;      ///< s = ln(z) / Δt (1/s), Im(s) > 0
  /// Per signal: A_c = 2 |h_c|, in the signal's unit, at the first sample time t_0.
  VectorXd amplitude;
  /// Per signal: φ_c = arg h_c (rad), so that y_c ∋ A_c e^{Re(s)(t − t_0)} cos(Im(s)(t − t_0) +
  /// φ_c).
  VectorXd phase;
  /// Share of the record's energy Σ_n y_c² carried by the mode (both poles of the pair), averaged
  /// over the signals: Σ_n |A_c e^{Re(s) t_n} cos(…)|² ≈ 2 |h_c|² Σ_n |z|²ⁿ over Σ_n y_c².
  double energy_fraction = 0.0;
};

/// A pole that is not reported as a mode: a real pole (offset, drift, over-damped term), the
/// weaker of surplus oscillating pairs, or a pole at the Nyquist frequency.
struct OtherPole {
  std::complex<double> pole;     ///< s = ln(z) / Δt (1/s); for a pair, the one with Im(s) > 0
  double energy_fraction = 0.0;  ///< as IdentifiedMode::energy_fraction (one pole, or the pair)
};

/// What IdentifyModes found.
struct ModalIdentification {
  std::vector<IdentifiedMode> modes;  ///< K modes, by increasing frequency
  std::vector<OtherPole> other_poles;
  double time_step = 0.0;  ///< Δt of the record (s)
  Index samples = 0;       ///< N, per signal, in the record
  Index decimation = 1;    ///< D, the samples averaged per fitted point
  /// 1 / (2 D Δt) (Hz): modes above it alias.
  double nyquist_frequency = 0.0;
  Index pencil = 0;       ///< the pencil parameter L
  Index model_order = 0;  ///< M, the number of poles fitted
  /// The singular values of the Hankel matrix divided by the largest, the first min(L + 1, 3M):
  /// a gap after the M-th says the model order fits the record.
  std::vector<double> singular_values;
  /// ‖y − ŷ‖ / ‖y‖ over all signals, ŷ the sum of all M fitted terms (also the other poles).
  double relative_residual = 0.0;
};

/// Identifies options.modes damped modes shared by the signals sampled every `time_step` seconds:
/// `signals` has one column per signal and one row per sample (row n at t_0 + n Δt). Phases refer
/// to the first row. Each signal is scaled to unit RMS in the Hankel matrix, so that signals in
/// different units weigh alike. The pencil of the stacked Hankel matrix is reduced to rank M by
/// its SVD (computed through a row-blocked QR, so that memory stays O(L²)); its eigenvalues z_i
/// give s_i = ln(z_i) / Δt, ω_n = |s_i|, ζ = −Re(s_i) / |s_i|. Frequencies above the Nyquist
/// frequency 1/(2Δt) alias and cannot be identified.
/// Throws InputError when K < 1, extra_poles < 0, the step is not positive and finite, a value is
/// not finite, a signal is constant (zero after the mean is removed), there are too few samples
/// (L ≥ M + 1 and N/D − L ≥ M are needed: about 2M + 1 points after the decimation D) or fewer than
/// K oscillating pole pairs are found.
ModalIdentification IdentifyModes(double time_step, const MatrixXd& signals,
                                  const ModalIdentificationOptions& options);

/// As above with sample times `time` (s, one per row of `signals`), which must be uniform within
/// options.sampling_tolerance (else InputError naming the first offending sample).
ModalIdentification IdentifyModes(const VectorXd& time, const MatrixXd& signals,
                                  const ModalIdentificationOptions& options);

}  // namespace ancfnet
