#pragma once
/// @file Checks of the values given to ModelBuilder (model/model_builder.hpp), shared by the
/// files that define its members. Each throws InputError naming the quantity `what` and the value
/// it got.

#include <fmt/format.h>

#include <cmath>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Every component of v is finite.
inline void RequireFinite(const Vector3d& v, const char* what) {
  if (!v.allFinite())
    throw InputError(
        fmt::format("{} must be finite (got [{}, {}, {}])", what, v.x(), v.y(), v.z()));
}

/// 0 < value < ∞.
inline void RequirePositive(double value, const char* what) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(fmt::format("{} must be > 0 (got {})", what, value));
}

/// value > 0, infinity allowed (a breaking force that is never reached); NaN refused.
inline void RequireBreakingForce(double value, const char* what) {
  if (!(value > 0.0)) throw InputError(fmt::format("{} must be > 0 (got {})", what, value));
}

/// 0 ≤ value < ∞.
inline void RequireNonNegative(double value, const char* what) {
  if (!(value >= 0.0 && std::isfinite(value)))
    throw InputError(fmt::format("{} must be ≥ 0 (got {})", what, value));
}

}  // namespace ancfnet
