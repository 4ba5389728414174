#include "ancfnet/solvers/energy_step_control.hpp"

#include <algorithm>
#include <cmath>

namespace ancfnet {
namespace {

double EnergyScale(const EnergyAccount& a) {
  return a.kinetic + std::abs(a.strain) + std::abs(a.gravity) + std::abs(a.work) +
         std::abs(a.dissipated);
}

// The least factor one step may be cut by.
constexpr double kSmallestCut = 0.25;
// Aim below the budget, so that the next step does not just miss it.
constexpr double kSafety = 0.9;

}  // namespace

EnergyStepControl::EnergyStepControl(double drift, double start, double end,
                                     const EnergyAccount& initial)
    : drift_(drift),
      duration_(end - start),
      scale_(EnergyScale(initial)),
      balance_(initial.Balance()) {}

double EnergyStepControl::Cut(double h, const EnergyAccount& account) {
  const double balance = account.Balance();
  const double error = std::abs(balance - balance_);
  balance_ = balance;
  scale_ = std::max(scale_, EnergyScale(account));
  may_grow_ = true;
  if (!enabled() || !(duration_ > 0.0) || !(scale_ > 0.0)) return 1.0;
  const double budget = drift_ * scale_ * h / duration_;
  may_grow_ = error <= 0.5 * budget;
  if (error <= budget) return 1.0;
  return std::max(kSmallestCut, kSafety * budget / error);
}

void EnergyStepControl::SaveCheckpoint(ArchiveWriter* out) const {
  out->Write(scale_);
  out->Write(balance_);
  out->Write(may_grow_);
}

void EnergyStepControl::LoadCheckpoint(ArchiveReader* in) {
  scale_ = in->Read<double>();
  balance_ = in->Read<double>();
  may_grow_ = in->Read<bool>();
}

}  // namespace ancfnet
