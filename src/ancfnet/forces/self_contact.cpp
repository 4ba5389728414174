#include "ancfnet/forces/self_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/contact/distance/segment_segment.hpp"
#include "ancfnet/contact/elastic_step_force.hpp"
#include "ancfnet/forces/impact_speed.hpp"

namespace ancfnet {
namespace {

// Deepest overlap of a pair accepted at the end of a step, as a fraction of its mean radius.
constexpr double kMaxPenetrationRatio = 0.5;
// Gap below which a candidate pair is coupled in the iteration matrix, as a fraction of its radius
// sum (docs/theory.md, "Self-contact": which pairs are coupled).
constexpr double kCouplingGapRatio = 0.25;

}  // namespace

SelfContact::SelfContact(const Model& model, double near_factor)
    : model_(model),
      primitives_(MakeSelfContactPrimitives(model)),
      filter_(model, primitives_),
      near_factor_(std::max(near_factor, 1.0)) {}

int SelfContact::Blocks(const SelfContactPrimitive& p, double s, std::array<double, 4>* weight,
                        std::array<Index, 4>* dof) const {
  if (p.element < 0) {
    (*weight)[0] = 1.0;
    (*dof)[0] = model_.point_masses()[p.point_mass].dof;
    return 1;
  }
  const CableElement& element = model_.elements()[p.element];
  for (int k = 0; k < 4; ++k) {
    (*weight)[k] = (1.0 - s) * p.shape0[k] + s * p.shape1[k];
    (*dof)[k] = element.dofs[3 * k];
  }
  return 4;
}

void SelfContact::AddOwnBlocks(const SelfContactPrimitive& p, const Matrix24d& jacobian, int first,
                               SystemMatrix* matrix) const {
  if (p.element < 0)
    matrix->AddPointMassBlock(p.point_mass, jacobian.block<3, 3>(first, first));
  else
    matrix->AddElementBlock(p.element, jacobian.block<12, 12>(first, first));
}

SelfContact::PairState SelfContact::CalcPair(const Candidate& c, const VectorXd& q,
                                             const VectorXd& v, PairDetail detail) const {
  const SelfContactPrimitive& pa = primitives_[c.a];
  const SelfContactPrimitive& pb = primitives_[c.b];
  const Axis a = LocateCapsuleAxis(model_, pa, q, &v);
  const Axis b = LocateCapsuleAxis(model_, pb, q, &v);
  const CapsuleCapsuleDistance d =
      CalcCapsuleCapsuleDistance(a.x0, a.x1, pa.radius, b.x0, b.x1, pb.radius);
  PairState r;
  // A chain's vertex belongs to the capsule starting there, and counts only where it is also the
  // closest point seen from the capsule ending there.
  r.counted = OwnsClosestPoint(pa, d.axes.part_p, d.axes.direction, q) &&
              OwnsClosestPoint(pb, d.axes.part_q, -d.axes.direction, q);
  r.s = d.axes.s;
  r.t = d.axes.t;
  r.gap = d.gap;
  r.direction = d.axes.direction;
  r.velocity = (1.0 - r.s) * a.v0 + r.s * a.v1 - (1.0 - r.t) * b.v0 - r.t * b.v1;
  if (detail == PairDetail::kGeometry || !r.counted) return r;
  // Relative position x = x_a − x_b of the closest points: n = u, ∂u/∂x = (I − u uᵀ)/|x|.
  const Vector3d& u = d.axes.direction;
  ContactKinematics k;
  k.penetration = -d.gap;
  k.normal = u;
  if (d.axes.distance > 1e-12 * (pa.radius + pb.radius))
    k.normal_derivative = (Matrix3d::Identity() - u * u.transpose()) / d.axes.distance;
  k.velocity = r.velocity;
  const ContactSpec& spec = model_.contact();
  r.force = CalcContactPairForce(spec.normal, spec.friction, k, c.history.speed, c.history.bristle,
                                 step_, detail == PairDetail::kJacobian);
  // A pair apart at q still needs the geometry of its Jacobian for the discrete gradient of a
  // step whose start or end touches (CalcStepPair).
  if (detail != PairDetail::kJacobian) return r;
  // A closest point inside its axis moves with the coordinates (not for parallel axes, whose
  // closest pair is not unique).
  const auto side = [&](const SelfContactPrimitive& p, const Axis& axis, double parameter,
                        SegmentPart part) {
    SelfPairSide out;
    if (p.element >= 0) {
      out.num_blocks = 4;
      out.weights = (1.0 - parameter) * p.shape0 + parameter * p.shape1;
      out.weight_rates = p.shape1 - p.shape0;
    }
    out.axis = axis.x1 - axis.x0;
    out.axis_rate = axis.v1 - axis.v0;
    out.moving_point =
        part == SegmentPart::kInterior && !d.axes.parallel && out.axis.squaredNorm() > 0.0;
    return out;
  };
  r.side_a = side(pa, a, r.s, d.axes.part_p);
  r.side_b = side(pb, b, r.t, d.axes.part_q);
  r.separation = d.axes.closest_p - d.axes.closest_q;
  return r;
}

bool SelfContact::OwnsClosestPoint(const SelfContactPrimitive& p, SegmentPart part,
                                   const Vector3d& direction, const VectorXd& q) const {
  if (part == SegmentPart::kEnd) return p.next < 0;
  if (part == SegmentPart::kInterior || p.previous < 0) return true;
  // At its start: moving back along the previous capsule must not come closer.
  const Axis here = LocateCapsuleAxis(model_, p, q);
  const Axis before = LocateCapsuleAxis(model_, primitives_[p.previous], q);
  return (here.x0 - before.x0).dot(direction) <= 0.0;
}

void SelfContact::FindCandidates(const State& state, double h) {
  const std::size_t n = primitives_.size();
  step_ = h;
  boxes_.resize(n);
  margin_.resize(n);
  start_x0_.resize(n);
  start_x1_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Axis axis = LocateCapsuleAxis(model_, primitives_[i], state.q, &state.v);
    margin_[i] = 2.0 * h * std::max(axis.v0.norm(), axis.v1.norm()) + 0.5 * primitives_[i].radius;
    boxes_[i] = Aabb::OfCapsule(axis.x0, axis.x1, primitives_[i].radius, margin_[i]);
    start_x0_[i] = axis.x0;
    start_x1_[i] = axis.x1;
  }
  broad_phase_.FindOverlaps(boxes_, &overlaps_);
  candidates_.clear();
  coupled_owners_.clear();
  near_owners_.clear();
  const double min_speed = model_.contact().normal.min_approach_speed;
  const auto& history = state.self_contact_history;
  for (const auto& [a, b] : overlaps_) {
    if (filter_.Excluded(a, b)) continue;
    Candidate c;
    c.a = a;
    c.b = b;
    const PairState pair = CalcPair(c, state.q, state.v, PairDetail::kGeometry);
    if (pair.gap > margin_[a] + margin_[b]) continue;
    c.direction_start = pair.direction;
    c.penetration_start = Penetration(pair);
    const double closing = std::max(-pair.direction.dot(pair.velocity), 0.0);
    const auto it = std::lower_bound(history.begin(), history.end(), c,
                                     [](const SelfContactPairHistory& h, const Candidate& k) {
                                       return h.first != k.a ? h.first < k.a : h.second < k.b;
                                     });
    if (it != history.end() && it->first == a && it->second == b) {
      c.history = it->history;
    } else {
      // A pair new to the search: minus its closing speed now, or its impact speed when it
      // already touches.
      c.history.speed = pair.gap < 0.0 ? std::max(closing, min_speed) : -closing;
    }
    // Coupled: touching or nearly (a fraction of the radius sum), or closing that gap within
    // twice the step at the closing speed now.
    const double coupling_gap =
        kCouplingGapRatio * (primitives_[a].radius + primitives_[b].radius) + 2.0 * h * closing;
    const std::pair<Index, Index> owners(primitives_[a].owner, primitives_[b].owner);
    if (pair.gap < near_factor_ * coupling_gap) near_owners_.push_back(owners);
    c.coupled = pair.gap < coupling_gap;
    if (c.coupled) coupled_owners_.push_back(owners);
    candidates_.push_back(c);
  }
}

void SelfContact::AddForces(const VectorXd& q, const VectorXd& v, Workspace& ws) const {
  for (const Candidate& c : candidates_) {
    const PairState pair = step_end_ ? CalcStepPair(c, q, v, false, &ws.contact_energy)
                                     : CalcPair(c, q, v, PairDetail::kForce);
    if (!step_end_) {
      if (!pair.force.touching) continue;
      ws.contact_energy += pair.force.energy;
    }
    ApplyPairForce(c, pair, ws);
  }
}

SelfContact::PairState SelfContact::CalcStepPair(const Candidate& c, const VectorXd& q,
                                                 const VectorXd& v, bool jacobian,
                                                 double* energy) const {
  PairState pair = CalcPair(c, q, v, jacobian ? PairDetail::kJacobian : PairDetail::kForce);
  const double start = c.penetration_start;
  const double end = Penetration(CalcPair(c, *step_end_, v, PairDetail::kGeometry));
  const NormalLaw& law = model_.contact().normal;
  *energy += law.CalcElasticEnergy(end);
  // The elastic part at the midpoint gives way to the discrete gradient (zero when apart at
  // both ends), along d, the step's displacement of a's closest point relative to b's.
  const Vector3d elastic = pair.force.force - pair.force.dissipative;
  std::array<double, 4> wa, wb;
  std::array<Index, 4> da, db;
  const int na = Blocks(primitives_[c.a], pair.s, &wa, &da);
  const int nb = Blocks(primitives_[c.b], pair.t, &wb, &db);
  Vector3d d = Vector3d::Zero();
  const VectorXd& q0 = *step_start_;
  const VectorXd& q1 = *step_end_;
  for (int k = 0; k < na; ++k) d += wa[k] * (q1.segment<3>(da[k]) - q0.segment<3>(da[k]));
  for (int k = 0; k < nb; ++k) d -= wb[k] * (q1.segment<3>(db[k]) - q0.segment<3>(db[k]));
  // CalcElasticStepForce's least displacement: 10⁻⁶ of the radii, as for targets.
  const double least = 1e-6 * (primitives_[c.a].radius + primitives_[c.b].radius);
  pair.force.force += CalcElasticStepForce(law, start, end, pair.direction, d, least) - elastic;
  pair.step_force = pair.counted && (start > 0.0 || end > 0.0);
  if (jacobian && (pair.step_force || pair.force.touching)) {
    // Also where the pair is apart at the midpoint but touches at an end of the step: without
    // this slope its force would have no Jacobian, and Newton would cycle as the end of the
    // step touches at one iterate and not at the next (issue 17).
    const double slope =
        2.0 * CalcElasticStepMagnitude(law, start, end).dforce_dend -
        (pair.force.touching ? law.Evaluate(pair.force.penetration, 0.0, 1.0).dforce_ddelta : 0.0);
    pair.force.dforce_dx -= slope * pair.direction * pair.direction.transpose();
  }
  return pair;
}

void SelfContact::ApplyPairForce(const Candidate& c, const PairState& pair, Workspace& ws) const {
  std::array<double, 4> wa, wb;
  std::array<Index, 4> da, db;
  const int na = Blocks(primitives_[c.a], pair.s, &wa, &da);
  const int nb = Blocks(primitives_[c.b], pair.t, &wb, &db);
  for (int k = 0; k < na; ++k) {
    ws.internal_force.segment<3>(da[k]) -= wa[k] * pair.force.force;
    ws.viscous_force.segment<3>(da[k]) -= wa[k] * pair.force.dissipative;
  }
  for (int k = 0; k < nb; ++k) {
    ws.internal_force.segment<3>(db[k]) += wb[k] * pair.force.force;
    ws.viscous_force.segment<3>(db[k]) += wb[k] * pair.force.dissipative;
  }
}

void SelfContact::AddJacobian(const VectorXd& q, const VectorXd& v, const IterationWeights& weights,
                              SystemMatrix* matrix) const {
  for (const Candidate& c : candidates_) {
    double energy = 0.0;
    const PairState pair = step_end_ ? CalcStepPair(c, q, v, true, &energy)
                                     : CalcPair(c, q, v, PairDetail::kJacobian);
    if (!pair.force.touching && !pair.step_force) continue;
    const Matrix24d jacobian = CalcSelfPairJacobian(pair.side_a, pair.side_b, pair.separation,
                                                    pair.force, weights.stiffness, weights.damping);
    const SelfContactPrimitive& pa = primitives_[c.a];
    const SelfContactPrimitive& pb = primitives_[c.b];
    const int na = pair.side_a.num_blocks, nb = pair.side_b.num_blocks;
    if (pa.element >= 0 && pa.element == pb.element) {
      // Both on one element: every block is the element's own.
      Matrix12d block = Matrix12d::Zero();
      for (int i : {0, 12})
        for (int j : {0, 12}) block += jacobian.block<12, 12>(i, j);
      matrix->AddElementBlock(pa.element, block);
      continue;
    }
    const int coupling =
        matrix->FindContactCoupling(std::min(pa.owner, pb.owner), std::max(pa.owner, pb.owner));
    if (!c.coupled || coupling < 0) {
      // Apart at the step start (even where the pattern still holds their coupling, so that the
      // matrix does not depend on the pattern's history): each primitive's own blocks only.
      AddOwnBlocks(pa, jacobian, 0, matrix);
      AddOwnBlocks(pb, jacobian, 12, matrix);
      continue;
    }
    // The coupling's blocks: the lower owner's first.
    const bool a_first = pa.owner <= pb.owner;
    const int offset_a = a_first ? 0 : nb, offset_b = a_first ? na : 0;
    const auto block_of = [&](int k) { return k < na ? offset_a + k : offset_b + (k - na); };
    const auto row_of = [&](int k) { return k < na ? 3 * k : 12 + 3 * (k - na); };
    for (int i = 0; i < na + nb; ++i)
      for (int j = 0; j < na + nb; ++j)
        matrix->AddContactBlock(coupling, block_of(i), block_of(j),
                                jacobian.block<3, 3>(row_of(i), row_of(j)));
  }
}

std::string SelfContact::CheckStep(const VectorXd& q) const {
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    const Axis axis = LocateCapsuleAxis(model_, primitives_[i], q);
    const double moved = std::max((axis.x0 - start_x0_[i]).norm(), (axis.x1 - start_x1_[i]).norm());
    if (moved > margin_[i])
      return fmt::format(
          "self-contact: a primitive moved {:.3g} m in one step, more than its "
          "search margin {:.3g} m",
          moved, margin_[i]);
  }
  auto name = [&](const SelfContactPrimitive& p) {
    return p.element >= 0 ? fmt::format("element {}", p.element)
                          : fmt::format("point mass {}", p.point_mass);
  };
  for (const Candidate& c : candidates_) {
    const PairState pair = CalcPair(c, q, q, PairDetail::kGeometry);
    const SelfContactPrimitive& a = primitives_[c.a];
    const SelfContactPrimitive& b = primitives_[c.b];
    if (pair.direction.dot(c.direction_start) < 0.0)
      return fmt::format("self-contact: {} and {} passed through each other", name(a), name(b));
    const double allowed = kMaxPenetrationRatio * 0.5 * (a.radius + b.radius);
    if (pair.counted && -pair.gap > allowed)
      return fmt::format(
          "self-contact: {} and {} overlap by {:.3g} m, more than {:.3g} m (a "
          "step too long for the impact, or a contact law too soft)",
          name(a), name(b), -pair.gap, allowed);
  }
  return {};
}

void SelfContact::UpdateHistory(const VectorXd& q, const VectorXd& v,
                                std::vector<SelfContactPairHistory>* history) const {
  history->clear();
  const double min_speed = model_.contact().normal.min_approach_speed;
  for (const Candidate& c : candidates_) {
    const PairState pair = CalcPair(c, q, v, PairDetail::kForce);
    const double closing = std::max(-pair.direction.dot(pair.velocity), 0.0);
    ContactPairHistory value{.speed = c.history.speed, .bristle = pair.force.bristle};
    UpdateImpactSpeed(pair.force.touching, closing, min_speed, &value);
    history->push_back({c.a, c.b, value});
  }
}

void SelfContact::CollectContacts(const VectorXd& q, const VectorXd& v,
                                  std::vector<ContactPoint>* out) const {
  for (const Candidate& c : candidates_) {
    const PairState pair = CalcPair(c, q, v, PairDetail::kForce);
    if (!pair.force.touching) continue;
    const SelfContactPrimitive& a = primitives_[c.a];
    const SelfContactPrimitive& b = primitives_[c.b];
    const Axis axis_b = LocateCapsuleAxis(model_, b, q, &v);
    ContactPoint p;
    p.point_W = (1.0 - pair.t) * axis_b.x0 + pair.t * axis_b.x1 + b.radius * pair.direction;
    p.normal_W = pair.direction;
    p.penetration = pair.force.penetration;
    p.normal_force = pair.force.normal_force;
    p.friction_force_W = pair.force.friction;
    p.force_W = pair.force.force;
    p.element = a.element;
    p.point_mass = a.point_mass;
    p.xi = a.xi0 + pair.s * (a.xi1 - a.xi0);
    out->push_back(p);
  }
}

SelfContact::Summary SelfContact::Summarize(const VectorXd& q, const VectorXd& v) const {
  Summary s;
  for (const Candidate& c : candidates_) {
    const PairState pair = CalcPair(c, q, v, PairDetail::kForce);
    if (!pair.force.touching) continue;
    ++s.active;
    s.normal_force += pair.force.normal_force;
    s.max_penetration = std::max(s.max_penetration, pair.force.penetration);
  }
  return s;
}

}  // namespace ancfnet
