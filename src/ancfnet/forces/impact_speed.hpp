#pragma once
/// @file The impact speed v₀ a contact pair remembers between steps (ContactPairHistory::speed),
/// the v₀ of the dissipative normal laws (contact/laws/normal_law.hpp).

#include <algorithm>

#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// After an accepted step, with the pair touching or not and closing at s = max(δ̇, 0) (m/s): a
/// pair apart stores −s; a pair that has just touched (stored ≤ 0) freezes its impact speed
/// max(−stored, s, v_min), the closing speed before the touch or now; a pair in contact keeps it.
inline void UpdateImpactSpeed(bool touching, double closing_speed, double min_speed,
                              ContactPairHistory* history) {
  if (!touching) {
    history->speed = -closing_speed;
  } else if (history->speed <= 0.0) {
    history->speed = std::max(std::max(-history->speed, closing_speed), min_speed);
  }
}

}  // namespace ancfnet
