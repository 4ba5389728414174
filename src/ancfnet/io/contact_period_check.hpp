#pragma once
/// @file A plausibility check of a contact law's stiffness against the time step.

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// A contact this many times shorter than the time step is refused.
inline constexpr double kMinContactPeriodSteps = 1e-3;

/// Refuses (at `stiffness`, the contact law's key) a law so stiff that a contact of the lightest
/// contact point lasts less than kMinContactPeriodSteps · h: its period T = 2π √(m / k_eff), m
/// the point's share of its element's mass (or its point mass), k_eff = n k δⁿ⁻¹ the law's
/// stiffness at a penetration δ of a tenth of the point's radius. No step could resolve such a
/// contact (a stiffness of 10³⁰ N/m^1.5 once "completed" with 10¹³ J dissipated from 0.002 J).
void CheckContactPeriod(const Model& model, double time_step, const YamlValue& stiffness);

}  // namespace ancfnet
