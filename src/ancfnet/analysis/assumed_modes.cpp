#include "ancfnet/analysis/assumed_modes.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/quadrature.hpp"

namespace ancfnet {
namespace {

// β_i L of the clamped–free beam, cos βL cosh βL = −1 (Blevins 1979, table 8-1).
constexpr double kBetaL[] = {1.875104069, 4.694091133, 7.854757438,
                             10.99554073, 14.13716839, 17.27875953};

// Unnormalised clamped–free mode: cosh βx − cos βx − σ (sinh βx − sin βx).
double ModeShape(double beta_l, double xi) {
  const double sigma =
      (std::cosh(beta_l) + std::cos(beta_l)) / (std::sinh(beta_l) + std::sin(beta_l));
  const double b = beta_l * xi;
  return std::cosh(b) - std::cos(b) - sigma * (std::sinh(b) - std::sin(b));
}

struct Mode {
  double omega = 0.0;   // rad/s
  double scale = 0.0;   // ψ = scale · ModeShape, ∫ ρA ψ² dx = 1
  double tip = 0.0;     // ψ(L)
  double moment = 0.0;  // ∫ ρA x ψ dx
};

// Mass normalisation and the first moment by Gauss quadrature on 64 intervals (8 points each).
Mode MakeMode(const AssumedModesBeam& beam, int i) {
  const double beta_l = kBetaL[i], l = beam.length;
  const GaussRule& rule = GetGaussRule(8);
  double norm = 0.0, moment = 0.0;
  constexpr int kIntervals = 64;
  for (int k = 0; k < kIntervals; ++k)
    for (int g = 0; g < rule.size; ++g) {
      const double xi = (k + rule.points[g]) / kIntervals;
      const double w = rule.weights[g] * l / kIntervals;
      const double psi = ModeShape(beta_l, xi);
      norm += w * beam.mass_per_length * psi * psi;
      moment += w * beam.mass_per_length * xi * l * psi;
    }
  Mode mode;
  mode.scale = 1.0 / std::sqrt(norm);
  mode.omega =
      beta_l * beta_l * std::sqrt(beam.bending_stiffness / (beam.mass_per_length * std::pow(l, 4)));
  mode.tip = mode.scale * ModeShape(beta_l, 1.0);
  mode.moment = mode.scale * moment;
  return mode;
}

}  // namespace

AssumedModesResponse SimulateAssumedModes(const AssumedModesBeam& beam, const AngleProfile& hub,
                                          double end_time, double h, double divergence_limit) {
  if (!(beam.length > 0.0 && beam.bending_stiffness > 0.0 && beam.mass_per_length > 0.0))
    throw InputError("assumed modes: length, EI and ρA must be > 0");
  if (beam.num_modes < 1 || beam.num_modes > 6)
    throw InputError(fmt::format("assumed modes: 1 … 6 modes (got {})", beam.num_modes));
  if (!(h > 0.0 && end_time > 0.0)) throw InputError("assumed modes: h and end_time must be > 0");
  std::vector<Mode> modes;
  for (int i = 0; i < beam.num_modes; ++i) modes.push_back(MakeMode(beam, i));
  const int n = beam.num_modes;
  // State y = (q, q̇); ẏ = f(t, y).
  const auto rate = [&](double t, const VectorXd& y) {
    const auto [theta, theta_dot, theta_ddot] = hub.Evaluate(t);
    VectorXd dy(2 * n);
    for (int i = 0; i < n; ++i) {
      const double omega2 = modes[i].omega * modes[i].omega;
      dy[i] = y[n + i];
      dy[n + i] = -(omega2 - theta_dot * theta_dot) * y[i] - theta_ddot * modes[i].moment;
    }
    return dy;
  };
  AssumedModesResponse response;
  for (const Mode& m : modes) response.omega.push_back(m.omega);
  VectorXd y = VectorXd::Zero(2 * n);
  const long steps = std::lround(end_time / h);
  for (long k = 0; k <= steps; ++k) {
    const double t = k * h;
    double tip = 0.0;
    for (int i = 0; i < n; ++i) tip += modes[i].tip * y[i];
    response.time.push_back(t);
    response.tip_deflection.push_back(tip);
    if (std::abs(tip) > divergence_limit || k == steps) break;
    const VectorXd k1 = rate(t, y);
    const VectorXd k2 = rate(t + 0.5 * h, y + 0.5 * h * k1);
    const VectorXd k3 = rate(t + 0.5 * h, y + 0.5 * h * k2);
    const VectorXd k4 = rate(t + h, y + h * k3);
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return response;
}

}  // namespace ancfnet
