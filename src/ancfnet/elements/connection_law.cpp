#include "ancfnet/elements/connection_law.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// Index i of the table segment [x_i, x_{i+1}] that holds e: the segment to the right of a table
// point, the first segment below the table and the last one above it.
std::size_t FindSegment(const std::vector<ForceTablePoint>& table, double e) {
  const auto after = std::upper_bound(
      table.begin(), table.end(), e,
      [](double value, const ForceTablePoint& point) { return value < point.elongation; });
  const std::ptrdiff_t i = (after - table.begin()) - 1;
  return static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(table.size()) - 2));
}

// T_s(e) on segment i, in the form (1 − t) f_i + t f_{i+1} that returns f_i and f_{i+1} exactly
// at t = 0 and t = 1.
double SegmentForce(const std::vector<ForceTablePoint>& table, std::size_t i, double e) {
  const ForceTablePoint& a = table[i];
  const ForceTablePoint& b = table[i + 1];
  const double t = (e - a.elongation) / (b.elongation - a.elongation);
  return (1.0 - t) * a.force + t * b.force;
}

// ∫ₐᵇ T_s for a ≤ b, exact: the trapezoid rule on each segment's part of [a, b], the end segments
// reaching to ∓∞.
double IntegrateTable(const std::vector<ForceTablePoint>& table, double a, double b) {
  double integral = 0.0;
  const std::size_t last = table.size() - 2;
  for (std::size_t i = 0; i <= last; ++i) {
    const double lo = (i == 0) ? a : std::max(a, table[i].elongation);
    const double hi = (i == last) ? b : std::min(b, table[i + 1].elongation);
    if (hi > lo)
      integral += 0.5 * (hi - lo) * (SegmentForce(table, i, lo) + SegmentForce(table, i, hi));
  }
  return integral;
}

void RequirePositive(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0))
    throw InputError(
        fmt::format("connection law: {} must be positive and finite (got {})", what, value));
}

void RequireNonNegative(double value, const char* what) {
  if (!(std::isfinite(value) && value >= 0.0))
    throw InputError(
        fmt::format("connection law: {} must be non-negative and finite (got {})", what, value));
}

void ValidateTable(const std::vector<ForceTablePoint>& table) {
  if (table.size() < 2)
    throw InputError(fmt::format(
        "connection law: a force table needs at least 2 (elongation, force) rows (got {})",
        table.size()));
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (!std::isfinite(table[i].elongation) || !std::isfinite(table[i].force))
      throw InputError(fmt::format("connection law: force table row {} is not finite ({}, {})",
                                   i + 1, table[i].elongation, table[i].force));
    if (i > 0 && !(table[i].elongation > table[i - 1].elongation))
      throw InputError(fmt::format(
          "connection law: force table elongations must increase strictly (row {}: {} after {})",
          i + 1, table[i].elongation, table[i - 1].elongation));
  }
}

}  // namespace

SpringTerms ConnectionLaw::CalcSpring(double e) const {
  switch (spring) {
    case SpringKind::kLinear:
      return {k1 * e, k1, 0.0};
    case SpringKind::kTensionOnly:
      if (e <= gap) return {};
      return {k1 * (e - gap), k1, 0.0};
    case SpringKind::kPolynomial:
      return {e * (k1 + k3 * e * e), k1 + 3.0 * k3 * e * e, 6.0 * k3 * e};
    case SpringKind::kPiecewiseLinear: {
      const std::size_t i = FindSegment(table, e);
      const double slope =
          (table[i + 1].force - table[i].force) / (table[i + 1].elongation - table[i].elongation);
      return {SegmentForce(table, i, e), slope, 0.0};
    }
  }
  return {};
}

DampingTerms ConnectionLaw::CalcDamping(double e) const {
  if (damping == DampingKind::kConstant) {
    if (spring == SpringKind::kTensionOnly && e <= gap) return {};  // slack: nothing to damp
    return {damping_coefficient, 0.0};
  }
  const SpringTerms s = CalcSpring(e);
  if (s.stiffness <= 0.0) return {};
  return {damping_coefficient * s.stiffness, damping_coefficient * s.curvature};
}

ConnectionForce ConnectionLaw::Evaluate(double e, double e_dot) const {
  const SpringTerms s = CalcSpring(e);
  const DampingTerms b = CalcDamping(e);
  const ConnectionForce t{s.force + b.coefficient * e_dot, s.stiffness + b.dcoefficient_de * e_dot,
                          b.coefficient};
  // A tension-only connection never pushes, even while it shortens quickly.
  if (spring == SpringKind::kTensionOnly && (e <= gap || t.force <= 0.0)) return {};
  return t;
}

double ConnectionLaw::CalcEnergy(double e) const {
  switch (spring) {
    case SpringKind::kLinear:
      return 0.5 * k1 * e * e;
    case SpringKind::kTensionOnly:
      return e > gap ? 0.5 * k1 * (e - gap) * (e - gap) : 0.0;
    case SpringKind::kPolynomial:
      return e * e * (0.5 * k1 + 0.25 * k3 * e * e);
    case SpringKind::kPiecewiseLinear:
      return e >= 0.0 ? IntegrateTable(table, 0.0, e) : -IntegrateTable(table, e, 0.0);
  }
  return 0.0;
}

ConnectionLaw MakeLinearLaw(double k1) {
  ConnectionLaw law;
  law.spring = SpringKind::kLinear;
  law.k1 = k1;
  ValidateConnectionLaw(law);
  return law;
}

ConnectionLaw MakeTensionOnlyLaw(double k1, double gap) {
  ConnectionLaw law;
  law.spring = SpringKind::kTensionOnly;
  law.k1 = k1;
  law.gap = gap;
  ValidateConnectionLaw(law);
  return law;
}

ConnectionLaw MakePolynomialLaw(double k1, double k3) {
  ConnectionLaw law;
  law.spring = SpringKind::kPolynomial;
  law.k1 = k1;
  law.k3 = k3;
  ValidateConnectionLaw(law);
  return law;
}

ConnectionLaw MakePiecewiseLinearLaw(const std::vector<ForceTablePoint>& table) {
  ConnectionLaw law;
  law.spring = SpringKind::kPiecewiseLinear;
  law.table = table;
  ValidateConnectionLaw(law);
  return law;
}

ConnectionLaw WithConstantDamping(ConnectionLaw law, double b0) {
  RequireNonNegative(b0, "damping coefficient b0 (N s/m)");
  law.damping = DampingKind::kConstant;
  law.damping_coefficient = b0;
  return law;
}

ConnectionLaw WithStiffnessProportionalDamping(ConnectionLaw law, double beta) {
  RequireNonNegative(beta, "stiffness-proportional damping time beta (s)");
  law.damping = DampingKind::kStiffnessProportional;
  law.damping_coefficient = beta;
  return law;
}

void ValidateConnectionLaw(const ConnectionLaw& law) {
  switch (law.spring) {
    case SpringKind::kLinear:
      RequirePositive(law.k1, "stiffness k1 (N/m)");
      break;
    case SpringKind::kTensionOnly:
      RequirePositive(law.k1, "stiffness k1 (N/m)");
      RequireNonNegative(law.gap, "gap (m)");
      break;
    case SpringKind::kPolynomial:
      RequirePositive(law.k1, "stiffness k1 (N/m)");
      RequireNonNegative(law.k3, "cubic coefficient k3 (N/m^3) of a hardening spring");
      break;
    case SpringKind::kPiecewiseLinear:
      ValidateTable(law.table);
      break;
  }
  RequireNonNegative(law.damping_coefficient, law.damping == DampingKind::kConstant
                                                  ? "damping coefficient b0 (N s/m)"
                                                  : "stiffness-proportional damping time beta (s)");
}

}  // namespace ancfnet
