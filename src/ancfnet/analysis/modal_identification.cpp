#include "ancfnet/analysis/modal_identification.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

using Complex = std::complex<double>;

std::string SignalName(const ModalIdentificationOptions& options, Index c) {
  if (c < static_cast<Index>(options.signal_names.size()))
    return fmt::format("'{}'", options.signal_names[static_cast<std::size_t>(c)]);
  return fmt::format("signal {}", c + 1);
}

void CheckOptions(const ModalIdentificationOptions& options) {
  if (options.modes < 1)
    throw InputError(fmt::format("modal identification: the number of modes must be ≥ 1, got {}",
                                 options.modes));
  if (options.extra_poles < 0)
    throw InputError(
        fmt::format("modal identification: the number of extra poles must be ≥ 0, got {}",
                    options.extra_poles));
  if (!(options.pencil_fraction > 0.0 && options.pencil_fraction < 1.0))
    throw InputError(
        fmt::format("modal identification: the pencil fraction must be in (0, 1), got {}",
                    options.pencil_fraction));
  if (options.decimation < 0)
    throw InputError(fmt::format("modal identification: the decimation must be ≥ 0, got {}",
                                 options.decimation));
  if (options.max_pencil < 2)
    throw InputError(
        fmt::format("modal identification: max_pencil must be ≥ 2, got {}", options.max_pencil));
}

// The upper-triangular factor R of the QR factorisation of the stacked Hankel matrix
// [H_1; …; H_C], H_c(i, j) = y_c[i + j], i < N − L, j ≤ L, accumulated over blocks of rows so
// that the (C (N − L)) × (L + 1) matrix is never formed. RᵀR = HᵀH: same singular values and
// right singular vectors.
MatrixXd CalcHankelR(const MatrixXd& y, Index pencil) {
  const Index n = y.rows();
  const Index cols = pencil + 1;
  const Index block = std::max<Index>(4 * cols, 256);
  MatrixXd r(0, cols);
  MatrixXd stack;
  for (Index c = 0; c < y.cols(); ++c) {
    for (Index first = 0; first < n - pencil; first += block) {
      const Index rows = std::min(block, n - pencil - first);
      stack.resize(r.rows() + rows, cols);
      stack.topRows(r.rows()) = r;
      for (Index i = 0; i < rows; ++i)
        stack.row(r.rows() + i) = y.col(c).segment(first + i, cols).transpose();
      const Eigen::HouseholderQR<MatrixXd> qr(stack);
      const Index kept = std::min(stack.rows(), cols);
      r = qr.matrixQR().topRows(kept).triangularView<Eigen::Upper>();
    }
  }
  return r;
}

struct PoleFit {
  Complex z;
  Complex s;
  Eigen::VectorXcd residue;  // h_c, one per signal, at t_0
  VectorXd energy;           // Σ_n |h_c zⁿ|² / Σ_n y_c², one per signal
};

}  // namespace

ModalIdentification IdentifyModes(double time_step, const MatrixXd& signals,
                                  const ModalIdentificationOptions& options) {
  CheckOptions(options);
  if (!(std::isfinite(time_step) && time_step > 0.0))
    throw InputError(fmt::format(
        "modal identification: the sampling step must be positive and finite, got {}", time_step));
  if (signals.cols() < 1) throw InputError("modal identification: no signal given");
  const Index samples = signals.rows();
  const Index decimation =
      options.decimation > 0
          ? options.decimation
          : std::max<Index>(1, (samples + 3 * options.max_pencil - 1) / (3 * options.max_pencil));
  const Index n = samples / decimation;  // fitted points
  const Index k = options.modes;
  const Index order = 2 * k + options.extra_poles + (options.fit_offset ? 1 : 0);
  if (n < 2 * order + 1)
    throw InputError(fmt::format(
        "modal identification: {} samples{} are too few for {} modes (model order {}): at least "
        "{} are needed, and several periods of the slowest mode",
        samples, decimation > 1 ? fmt::format(" in blocks of {}", decimation) : "", k, order,
        (2 * order + 1) * decimation));
  for (Index c = 0; c < signals.cols(); ++c) {
    for (Index i = 0; i < samples; ++i) {
      if (!std::isfinite(signals(i, c)))
        throw InputError(fmt::format("modal identification: {} has a non-finite value at sample {}",
                                     SignalName(options, c), i));
    }
  }

  MatrixXd y(n, signals.cols());
  for (Index m = 0; m < n; ++m)
    y.row(m) = signals.middleRows(m * decimation, decimation).colwise().mean();
  if (options.remove_mean) y.rowwise() -= y.colwise().mean();
  const double record_step = time_step;
  time_step *= static_cast<double>(decimation);
  VectorXd energy_total(y.cols());
  MatrixXd scaled = y;
  for (Index c = 0; c < y.cols(); ++c) {
    energy_total(c) = y.col(c).squaredNorm();
    const double rms = std::sqrt(energy_total(c) / static_cast<double>(n));
    const double range = y.col(c).maxCoeff() - y.col(c).minCoeff();
    if (!(rms > 0.0) || !(range > 1e-14 * rms))
      throw InputError(fmt::format("modal identification: {} is constant{}", SignalName(options, c),
                                   options.remove_mean ? " (zero once its mean is removed)" : ""));
    scaled.col(c) /= rms;
  }

  // L within [M + 1, N − M]: V₁, V₂ (L × M) need full column rank and each Hankel block M rows.
  const auto fraction_pencil = static_cast<Index>(std::lround(options.pencil_fraction * n));
  const Index pencil =
      std::clamp(std::min(fraction_pencil, options.max_pencil), order + 1, n - order);

  ModalIdentification result;
  result.time_step = record_step;
  result.samples = samples;
  result.decimation = decimation;
  result.nyquist_frequency = 0.5 / time_step;
  result.pencil = pencil;
  result.model_order = order;

  const MatrixXd r = CalcHankelR(scaled, pencil);
  const Eigen::BDCSVD<MatrixXd> svd(r, Eigen::ComputeThinV);
  const VectorXd& sigma = svd.singularValues();
  for (Index i = 0; i < std::min<Index>(sigma.size(), 3 * order); ++i)
    result.singular_values.push_back(sigma(0) > 0.0 ? sigma(i) / sigma(0) : 0.0);

  // Pencil reduced to rank M: Y₁ = U Σ V₁ᵀ, Y₂ = U Σ V₂ᵀ with V₁, V₂ the first and last L rows
  // of the M leading right singular vectors; the poles are the eigenvalues of V₁⁺ V₂.
  const MatrixXd v = svd.matrixV().leftCols(order);
  const MatrixXd pencil_matrix =
      v.topRows(pencil).colPivHouseholderQr().solve(v.bottomRows(pencil));
  const Eigen::EigenSolver<MatrixXd> eigen(pencil_matrix, false);
  if (eigen.info() != Eigen::Success)
    throw InputError("modal identification: the eigenvalues of the pencil did not converge");
  const Eigen::VectorXcd z = eigen.eigenvalues();

  // Residues: least squares on the Vandermonde system y_c[n] = Σ_i h_ci z_iⁿ, each column
  // scaled by exp(−c_i), c_i = max(0, (N − 1) ln|z_i|), so that a growing pole cannot overflow.
  Eigen::MatrixXcd vandermonde(n, order);
  VectorXd column_scale(order);
  for (Index i = 0; i < order; ++i) {
    const Complex log_z = std::log(std::abs(z(i)) > 1e-300 ? z(i) : Complex(1e-300, 0.0));
    const double shift = std::max(0.0, static_cast<double>(n - 1) * log_z.real());
    column_scale(i) = shift;
    for (Index j = 0; j < n; ++j)
      vandermonde(j, i) = std::exp(static_cast<double>(j) * log_z - shift);
  }
  const Eigen::MatrixXcd scaled_residues =
      vandermonde.colPivHouseholderQr().solve(y.cast<Complex>());
  const Eigen::MatrixXcd fitted = vandermonde * scaled_residues;
  result.relative_residual = (fitted.real() - y).norm() / y.norm();

  std::vector<PoleFit> pairs;  // oscillating: Im z > 0 (their conjugates are skipped)
  for (Index i = 0; i < order; ++i) {
    PoleFit fit;
    fit.z = z(i);
    fit.s = std::log(std::abs(z(i)) > 1e-300 ? z(i) : Complex(1e-300, 0.0)) / time_step;
    // Block means scale each term by G(z) = (1/D) Σ_{j<D} z^j, z = exp(s Δt) of the record.
    Complex gain = 0.0;
    for (Index j = 0; j < decimation; ++j) gain += std::exp(fit.s * (record_step * j));
    gain /= static_cast<double>(decimation);
    fit.residue = scaled_residues.row(i).transpose() * (std::exp(-column_scale(i)) / gain);
    const double column_energy = vandermonde.col(i).squaredNorm();
    fit.energy.resize(y.cols());
    for (Index c = 0; c < y.cols(); ++c)
      fit.energy(c) = std::norm(scaled_residues(i, c)) * column_energy / energy_total(c);
    if (z(i).imag() > 0.0) {
      pairs.push_back(fit);
    } else if (z(i).imag() == 0.0) {
      result.other_poles.push_back({fit.s, fit.energy.mean()});
    }
  }
  if (static_cast<Index>(pairs.size()) < k)
    throw InputError(fmt::format(
        "modal identification: found {} oscillating pole pair(s) for {} modes; ask for fewer "
        "modes, or for more poles, or check that the record is a free decay",
        pairs.size(), k));

  std::sort(pairs.begin(), pairs.end(),
            [](const PoleFit& a, const PoleFit& b) { return a.energy.mean() > b.energy.mean(); });
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const PoleFit& fit = pairs[i];
    if (static_cast<Index>(i) >= k) {
      result.other_poles.push_back({fit.s, 2.0 * fit.energy.mean()});
      continue;
    }
    IdentifiedMode mode;
    mode.pole = fit.s;
    const double omega_n = std::abs(fit.s);
    mode.frequency = omega_n / (2.0 * std::numbers::pi);
    mode.damping_ratio = -fit.s.real() / omega_n;
    mode.damped_frequency = fit.s.imag() / (2.0 * std::numbers::pi);
    mode.amplitude = 2.0 * fit.residue.cwiseAbs();
    mode.phase = fit.residue.unaryExpr([](const Complex& h) { return std::arg(h); });
    mode.energy_fraction = 2.0 * fit.energy.mean();
    result.modes.push_back(mode);
  }
  std::sort(
      result.modes.begin(), result.modes.end(),
      [](const IdentifiedMode& a, const IdentifiedMode& b) { return a.frequency < b.frequency; });
  std::sort(
      result.other_poles.begin(), result.other_poles.end(),
      [](const OtherPole& a, const OtherPole& b) { return a.energy_fraction > b.energy_fraction; });
  return result;
}

ModalIdentification IdentifyModes(const VectorXd& time, const MatrixXd& signals,
                                  const ModalIdentificationOptions& options) {
  if (time.size() != signals.rows())
    throw InputError(fmt::format("modal identification: {} sample times for {} samples",
                                 time.size(), signals.rows()));
  if (time.size() < 2) throw InputError("modal identification: fewer than two samples");
  if (!time.allFinite()) throw InputError("modal identification: a sample time is not finite");
  const Index n = time.size();
  const double step = (time(n - 1) - time(0)) / static_cast<double>(n - 1);
  if (!(step > 0.0)) throw InputError("modal identification: the sample times do not increase");
  for (Index i = 0; i + 1 < n; ++i) {
    const double delta = time(i + 1) - time(i);
    if (std::abs(delta - step) > options.sampling_tolerance * step)
      throw InputError(fmt::format(
          "modal identification: the sampling is not uniform: the step from t = {} s to t = {} s "
          "is {} s, the mean step is {} s (tolerance {} %)",
          time(i), time(i + 1), delta, step, 100.0 * options.sampling_tolerance));
  }
  return IdentifyModes(step, signals, options);
}

}  // namespace ancfnet
