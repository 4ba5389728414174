#include "ancfnet/model/net_topology.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// How far from a unit orthogonal pair the axes of a grid net may be: a scene file's 7 digits.
constexpr double kAxisTolerance = 1e-6;
constexpr double kMaxMeshesPerSide = 1e6;

std::string Format(const Vector3d& v) { return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z()); }

// Checks the spec and returns its axes made exactly orthonormal.
std::pair<Vector3d, Vector3d> ValidateGrid(const GridNetSpec& spec) {
  if (!(spec.side_u > 0.0 && spec.side_v > 0.0 && std::isfinite(spec.side_u) &&
        std::isfinite(spec.side_v)))
    throw InputError(
        fmt::format("net sides must be > 0 (got {} × {} m)", spec.side_u, spec.side_v));
  if (spec.meshes_u < 1 || spec.meshes_v < 1)
    throw InputError(fmt::format("a net needs at least 1 mesh per side (got {} × {})",
                                 spec.meshes_u, spec.meshes_v));
  if (!spec.center.allFinite())
    throw InputError(fmt::format("net centre must be finite (got {})", Format(spec.center)));
  const Vector3d& u = spec.axis_u;
  const Vector3d& v = spec.axis_v;
  if (!(std::abs(u.norm() - 1.0) <= kAxisTolerance && std::abs(v.norm() - 1.0) <= kAxisTolerance))
    throw InputError(
        fmt::format("net axes u = {} and v = {} must be unit vectors", Format(u), Format(v)));
  if (!(std::abs(u.dot(v)) <= kAxisTolerance))
    throw InputError(fmt::format("net axes u = {} and v = {} must be orthogonal (u·v = {})",
                                 Format(u), Format(v), u.dot(v)));
  if (spec.diamond && spec.side_u != spec.side_v)
    throw InputError(fmt::format("a diamond net is square: give equal sides (got {} × {} m)",
                                 spec.side_u, spec.side_v));
  const Vector3d unit_u = u.normalized();
  return {unit_u, (v - v.dot(unit_u) * unit_u).normalized()};
}

}  // namespace

int MeshesForSize(double side, double mesh_size) {
  if (!(side > 0.0 && mesh_size > 0.0 && std::isfinite(side) && std::isfinite(mesh_size)))
    throw InputError(
        fmt::format("net side and mesh size must be > 0 (got {} m, {} m)", side, mesh_size));
  const double ratio = side / mesh_size;
  if (!(ratio <= kMaxMeshesPerSide))
    throw InputError(
        fmt::format("a net side of {} m with meshes of {} m has too many meshes", side, mesh_size));
  return std::max(1, static_cast<int>(std::lround(ratio)));
}

NetTopology MakeGridNet(const GridNetSpec& spec) {
  const auto [axis_u, axis_v] = ValidateGrid(spec);
  const Index nu = spec.meshes_u, nv = spec.meshes_v;
  // In-plane directions of the grid lines: the axes, or turned by 45° for a diamond net.
  Vector3d du = axis_u, dv = axis_v;
  if (spec.diamond) {
    du = (axis_u + axis_v) / std::numbers::sqrt2;
    dv = (axis_v - axis_u) / std::numbers::sqrt2;
  }
  const auto index = [nu](Index i, Index j) { return i + (nu + 1) * j; };
  NetTopology net;
  net.knots.reserve((nu + 1) * (nv + 1));
  for (Index j = 0; j <= nv; ++j)
    for (Index i = 0; i <= nu; ++i)
      net.knots.push_back(spec.center + (spec.side_u * (static_cast<double>(i) / nu - 0.5)) * du +
                          (spec.side_v * (static_cast<double>(j) / nv - 0.5)) * dv);
  net.threads.reserve(nu * (nv + 1) + nv * (nu + 1));
  for (Index j = 0; j <= nv; ++j)
    for (Index i = 0; i < nu; ++i) net.threads.push_back({index(i, j), index(i + 1, j)});
  for (Index i = 0; i <= nu; ++i)
    for (Index j = 0; j < nv; ++j) net.threads.push_back({index(i, j), index(i, j + 1)});
  // Perimeter counter-clockwise about u × v (du × dv = u × v), starting at corner (0, 0).
  net.perimeter.reserve(2 * (nu + nv));
  for (Index i = 0; i < nu; ++i) net.perimeter.push_back(index(i, 0));
  for (Index j = 0; j < nv; ++j) net.perimeter.push_back(index(nu, j));
  for (Index i = nu; i > 0; --i) net.perimeter.push_back(index(i, nv));
  for (Index j = nv; j > 0; --j) net.perimeter.push_back(index(0, j));
  net.corners = {index(0, 0), index(nu, 0), index(nu, nv), index(0, nv)};
  return net;
}

NetTopology MakeGraphNet(std::vector<Vector3d> knots, std::vector<std::array<Index, 2>> threads,
                         std::vector<Index> perimeter, std::vector<Index> corners) {
  const Index n = static_cast<Index>(knots.size());
  if (n < 2) throw InputError(fmt::format("a net graph needs at least 2 knots (got {})", n));
  for (Index k = 0; k < n; ++k)
    if (!knots[k].allFinite())
      throw InputError(fmt::format("net knot {} is not finite: {}", k, Format(knots[k])));
  if (threads.empty()) throw InputError("a net graph needs at least one thread");
  std::set<std::pair<Index, Index>> seen;
  for (std::size_t t = 0; t < threads.size(); ++t) {
    const auto [a, b] = threads[t];
    if (a < 0 || b < 0 || a >= n || b >= n)
      throw InputError(
          fmt::format("thread {} joins knots {} and {}: knots are 0 … {}", t, a, b, n - 1));
    if (a == b) throw InputError(fmt::format("thread {} joins knot {} to itself", t, a));
    if (!seen.insert({std::min(a, b), std::max(a, b)}).second)
      throw InputError(
          fmt::format("thread {} repeats the thread between knots {} and {}", t, a, b));
    if (knots[a] == knots[b])
      throw InputError(fmt::format("thread {} joins knots {} and {} at the same place {}", t, a, b,
                                   Format(knots[a])));
  }
  if (!perimeter.empty() && perimeter.size() < 3)
    throw InputError(
        fmt::format("a net perimeter needs at least 3 knots (got {})", perimeter.size()));
  std::set<Index> on_perimeter;
  for (Index k : perimeter) {
    if (k < 0 || k >= n)
      throw InputError(fmt::format("perimeter knot {} is not in 0 … {}", k, n - 1));
    if (!on_perimeter.insert(k).second)
      throw InputError(fmt::format("perimeter knot {} is listed twice (it closes by itself)", k));
  }
  std::set<Index> seen_corners;
  for (Index k : corners) {
    if (!on_perimeter.contains(k))
      throw InputError(fmt::format("corner knot {} is not a perimeter knot", k));
    if (!seen_corners.insert(k).second)
      throw InputError(fmt::format("corner knot {} is listed twice", k));
  }
  return {std::move(knots), std::move(threads), std::move(perimeter), std::move(corners)};
}

}  // namespace ancfnet
