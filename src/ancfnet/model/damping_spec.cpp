#include "ancfnet/model/damping_spec.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

RayleighDamping FitRayleighDamping(double f1, double zeta1, double f2, double zeta2) {
  if (!(f1 > 0.0 && f2 > 0.0 && std::isfinite(f1) && std::isfinite(f2) && f1 != f2))
    throw InputError(fmt::format(
        "Rayleigh damping needs two different positive frequencies (got {} and {} Hz)", f1, f2));
  if (!(zeta1 >= 0.0 && zeta2 >= 0.0 && std::isfinite(zeta1) && std::isfinite(zeta2)))
    throw InputError("Rayleigh damping needs damping ratios ≥ 0");
  const double w1 = 2.0 * std::numbers::pi * f1, w2 = 2.0 * std::numbers::pi * f2;
  const double d = w2 * w2 - w1 * w1;
  const RayleighDamping r{.alpha = 2.0 * w1 * w2 * (zeta1 * w2 - zeta2 * w1) / d,
                          .beta = 2.0 * (zeta2 * w2 - zeta1 * w1) / d};
  if (r.alpha < 0.0 || r.beta < 0.0)
    throw InputError(fmt::format(
        "no Rayleigh damping gives ζ = {} at {} Hz and ζ = {} at {} Hz with α, β ≥ 0 (α = {:.4g}, "
        "β = {:.4g})",
        zeta1, f1, zeta2, f2, r.alpha, r.beta));
  return r;
}

double ModalDamping::Ratio(int i, double f) const {
  if (!ratios.empty()) return ratios[i];
  if (f <= table.front().first) return table.front().second;
  if (f >= table.back().first) return table.back().second;
  for (std::size_t j = 1; j < table.size(); ++j) {
    if (f > table[j].first) continue;
    const auto [f0, z0] = table[j - 1];
    const auto [f1, z1] = table[j];
    return z0 + (z1 - z0) * (f - f0) / (f1 - f0);
  }
  return table.back().second;
}

}  // namespace ancfnet
