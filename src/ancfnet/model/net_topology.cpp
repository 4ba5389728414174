#include "ancfnet/model/net_topology.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

void ValidateGrid(const GridNetSpec& spec) {
  if (!(spec.side_u > 0.0 && spec.side_v > 0.0 && std::isfinite(spec.side_u) &&
        std::isfinite(spec.side_v)))
    throw InputError(fmt::format("net sides must be > 0 (got {} × {})", spec.side_u, spec.side_v));
  if (spec.meshes_u < 1 || spec.meshes_v < 1)
    throw InputError(fmt::format("a net needs at least 1 mesh per side (got {} × {})",
                                 spec.meshes_u, spec.meshes_v));
  const bool orthonormal = std::abs(spec.axis_u.norm() - 1.0) < 1e-9 &&
                           std::abs(spec.axis_v.norm() - 1.0) < 1e-9 &&
                           std::abs(spec.axis_u.dot(spec.axis_v)) < 1e-9;
  if (!orthonormal || !spec.center.allFinite())
    throw InputError("net axes u and v must be orthogonal unit vectors");
  if (spec.diamond && spec.side_u != spec.side_v)
    throw InputError("a diamond net is square: give equal sides");
}

}  // namespace

int MeshesForSize(double side, double mesh_size) {
  if (!(side > 0.0 && mesh_size > 0.0))
    throw InputError(fmt::format("net side and mesh size must be > 0 (got {}, {})", side, mesh_size));
  return std::max(1, static_cast<int>(std::lround(side / mesh_size)));
}

NetTopology MakeGridNet(const GridNetSpec& spec) {
  ValidateGrid(spec);
  const int nu = spec.meshes_u, nv = spec.meshes_v;
  // In-plane directions of the grid lines: the axes, or turned by 45° for a diamond net.
  Vector3d du = spec.axis_u, dv = spec.axis_v;
  if (spec.diamond) {
    du = (spec.axis_u + spec.axis_v) / std::numbers::sqrt2;
    dv = (spec.axis_v - spec.axis_u) / std::numbers::sqrt2;
  }
  NetTopology net;
  const auto index = [nu](int i, int j) { return static_cast<Index>(i + (nu + 1) * j); };
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      net.knots.push_back(spec.center + (spec.side_u * (static_cast<double>(i) / nu - 0.5)) * du +
                          (spec.side_v * (static_cast<double>(j) / nv - 0.5)) * dv);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) net.threads.push_back({index(i, j), index(i + 1, j)});
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j < nv; ++j) net.threads.push_back({index(i, j), index(i, j + 1)});
  // Perimeter counter-clockwise about u × v, starting at corner (0, 0).
  for (int i = 0; i < nu; ++i) net.perimeter.push_back(index(i, 0));
  for (int j = 0; j < nv; ++j) net.perimeter.push_back(index(nu, j));
  for (int i = nu; i > 0; --i) net.perimeter.push_back(index(i, nv));
  for (int j = nv; j > 0; --j) net.perimeter.push_back(index(0, j));
  net.corners = {index(0, 0), index(nu, 0), index(nu, nv), index(0, nv)};
  return net;
}

NetTopology MakeGraphNet(std::vector<Vector3d> knots, std::vector<std::array<Index, 2>> threads,
                         std::vector<Index> perimeter, std::vector<Index> corners) {
  const Index n = static_cast<Index>(knots.size());
  if (n < 2) throw InputError("a net graph needs at least 2 knots");
  for (const Vector3d& knot : knots)
    if (!knot.allFinite()) throw InputError("net knot positions must be finite");
  std::set<std::pair<Index, Index>> seen;
  for (std::size_t t = 0; t < threads.size(); ++t) {
    const auto [a, b] = threads[t];
    if (a < 0 || b < 0 || a >= n || b >= n)
      throw InputError(fmt::format("thread {} joins knot {} and {}: knots are 0 … {}", t, a, b, n - 1));
    if (a == b) throw InputError(fmt::format("thread {} joins knot {} to itself", t, a));
    if (!seen.insert({std::min(a, b), std::max(a, b)}).second)
      throw InputError(fmt::format("thread {} repeats the thread between knots {} and {}", t, a, b));
    if ((knots[a] - knots[b]).norm() == 0.0)
      throw InputError(fmt::format("thread {} joins coincident knots {} and {}", t, a, b));
  }
  if (threads.empty()) throw InputError("a net graph needs at least one thread");
  for (const std::vector<Index>* list : {&perimeter, &corners})
    for (Index k : *list)
      if (k < 0 || k >= n)
        throw InputError(fmt::format("perimeter or corner knot {} is not in 0 … {}", k, n - 1));
  return {std::move(knots), std::move(threads), std::move(perimeter), std::move(corners)};
}

}  // namespace ancfnet
