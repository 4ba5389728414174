#include "ancfnet/forces/joint_constraints.hpp"

#include <algorithm>
#include <cmath>

#include "ancfnet/common/skew.hpp"

namespace ancfnet {
namespace {

bool IsBody(const AnchorMotion& m) { return m.kind == JointAnchor::Kind::kBody; }

// The part of an anchor centre's acceleration that does not depend on a: ω × (ω × R s) for a
// body (c = x + R s), zero for a point (c = Σ w_b q_b is linear in q).
Vector3d CenterConvective(const AnchorMotion& m) {
  if (!IsBody(m)) return Vector3d::Zero();
  const Vector3d& w = m.angular_velocity;
  return w.cross(w.cross(m.rotation * m.body_point));
}

// Which kinds of equation a joint has, in the order of its rows: coincidence, in-plane,
// perpendicular, slope (forces/joint_constraints.hpp).
bool HasCoincidence(IdealJoint::Type type) {
  return type == IdealJoint::Type::kSpherical || type == IdealJoint::Type::kRevolute ||
         type == IdealJoint::Type::kWeld;
}
bool HasInPlane(IdealJoint::Type type) {
  return type == IdealJoint::Type::kLine || type == IdealJoint::Type::kPrismatic;
}

// A perpendicularity equation (R₁ u)·(R₂ w) = 0, u fixed in the first side, w in the second.
struct Perpendicular {
  const Vector3d* u = nullptr;
  const Vector3d* w = nullptr;
};

// The perpendicularity equations of a joint: a revolute's axis u against w₁ and w₂; a prismatic
// joint's the same and v against w₂, which locks the turning about the axis too. Returns their
// number.
int CollectPerpendiculars(const IdealJoint& joint, std::array<Perpendicular, 3>* out) {
  const Vector3d* u = &joint.axis_in_first;
  const Vector3d* w1 = &joint.normal1_in_second;
  const Vector3d* w2 = &joint.normal2_in_second;
  switch (joint.type) {
    case IdealJoint::Type::kRevolute:
      *out = {Perpendicular{u, w1}, Perpendicular{u, w2}, Perpendicular{}};
      return 2;
    case IdealJoint::Type::kPrismatic:
      *out = {Perpendicular{u, w1}, Perpendicular{u, w2},
              Perpendicular{&joint.normal1_in_first, w2}};
      return 3;
    default:
      return 0;
  }
}

// The first side's direction of a perpendicularity equation: R₁ u for the ground or a body, the
// slope r' itself for a cable point (a revolute joint about the cable's tangent), and its rate.
Vector3d FirstDirection(const AnchorMotion& m, const Vector3d& u) {
  return m.has_slope ? m.slope : Vector3d(m.rotation * u);
}
Vector3d FirstDirectionRate(const AnchorMotion& m, const Vector3d& u) {
  return m.has_slope ? m.slope_rate : Vector3d(m.angular_velocity.cross(m.rotation * u));
}

// The blocks of an anchor in the order of AnchorMotion (and of SystemMatrix's joint couplings).
void AppendBlocks(const Model& model, const JointAnchor& anchor, std::vector<Index>* blocks) {
  if (anchor.kind == JointAnchor::Kind::kBody) {
    const RigidBody& body = model.rigid_bodies()[anchor.body];
    blocks->push_back(body.position_dof());
    blocks->push_back(body.rotation_dof());
  } else if (anchor.kind == JointAnchor::Kind::kPoint) {
    blocks->insert(blocks->end(), anchor.dof.begin(), anchor.dof.begin() + anchor.num_blocks);
  }
}

}  // namespace

JointConstraints::JointConstraints(const Model& model) : model_(model) {
  Index rows = 0;
  for (const IdealJoint& joint : model.ideal_joints()) {
    first_row_.push_back(rows);
    rows += joint.num_equations();
    std::vector<Index> blocks;
    AppendBlocks(model, joint.first, &blocks);
    AppendBlocks(model, joint.second, &blocks);
    joint_blocks_.push_back(blocks);
  }
  first_motion_.resize(model.ideal_joints().size());
  second_motion_.resize(model.ideal_joints().size());
  rows_.resize(rows);
  violation_ = VectorXd::Zero(rows);
  convective_ = VectorXd::Zero(rows);
}

Index JointConstraints::BlockDof(Index row, int k) const {
  return joint_blocks_[rows_[row].joint][k];
}

int JointConstraints::NumBlocks(Index row) const {
  return static_cast<int>(joint_blocks_[rows_[row].joint].size());
}

void JointConstraints::Evaluate(const VectorXd& q, const VectorXd& v,
                                const std::vector<Matrix3d>& rotation) {
  const auto& joints = model_.ideal_joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    first_motion_[j] = CalcAnchorMotion(model_, joints[j].first, q, v, rotation);
    second_motion_[j] = CalcAnchorMotion(model_, joints[j].second, q, v, rotation);
    EvaluateJoint(static_cast<Index>(j), first_motion_[j], second_motion_[j], first_row_[j]);
  }
}

void JointConstraints::EvaluateJoint(Index j, const AnchorMotion& m1, const AnchorMotion& m2,
                                     Index row) {
  const IdealJoint& joint = model_.ideal_joints()[j];
  const int n1 = m1.num_blocks;
  const int n2 = m2.num_blocks;
  const int psi1 = 1;       // a body's rotation block among the first's blocks
  const int psi2 = n1 + 1;  // among the second's
  auto next_row = [&](double g, double convective, double length_scale) -> Row& {
    violation_[row] = g;
    convective_[row] = convective;
    Row& r = rows_[row++];
    r.joint = j;
    r.gradient.fill(Vector3d::Zero());
    r.length_scale = length_scale;
    return r;
  };
  const Vector3d d = m1.center - m2.center;
  const Vector3d d_rate = m1.velocity - m2.velocity;
  const Vector3d d_convective = CenterConvective(m1) - CenterConvective(m2);
  const double length = std::max(m1.center.norm(), m2.center.norm());
  const Vector3d& w1 = m1.angular_velocity;
  const Vector3d& w2 = m2.angular_velocity;
  const Matrix3d& r1 = m1.rotation;  // the identity for the ground
  const Matrix3d& r2 = m2.rotation;

  if (HasCoincidence(joint.type)) {
    // Coincidence g = c₁ − c₂: G = (A₁_b, −A₂_b) (forces/joint_anchor.hpp), g̈ = G a + Ġv with
    // Ġv = ω₁ × (ω₁ × R₁ s₁) − ω₂ × (ω₂ × R₂ s₂) (Géradin & Cardona 2001).
    for (int i = 0; i < 3; ++i) {
      Row& r = next_row(d[i], d_convective[i], length);
      for (int k = 0; k < n1; ++k) r.gradient[k] = m1.a[k].row(i).transpose();
      for (int k = 0; k < n2; ++k) r.gradient[n1 + k] = -m2.a[k].row(i).transpose();
    }
  }
  if (HasInPlane(joint.type)) {
    // In-plane g = d·e, d = c₁ − c₂, e = R₂ w: G = (A₁_bᵀ e, −A₂_bᵀ e) plus w × (R₂ᵀ d) on ψ₂;
    // g̈ = G a + (Ġv of d)·e + 2 ḋ·(ω₂ × e) + d·(ω₂ × (ω₂ × e)).
    for (const Vector3d* w : {&joint.normal1_in_second, &joint.normal2_in_second}) {
      const Vector3d e = r2 * *w;
      const double convective = d_convective.dot(e) + 2.0 * d_rate.dot(w2.cross(e)) +
                                d.dot(w2.cross(w2.cross(e)));
      Row& r = next_row(d.dot(e), convective, length);
      for (int k = 0; k < n1; ++k) r.gradient[k] = m1.a[k].transpose() * e;
      for (int k = 0; k < n2; ++k) r.gradient[n1 + k] = -m2.a[k].transpose() * e;
      if (IsBody(m2)) r.gradient[psi2] += w->cross(r2.transpose() * d);
    }
  }
  // Perpendicularity g = d₁·e, d₁ = R₁ u, e = R₂ w: with δR = R δψ̃,
  // ∂g/∂ψ₁ = u × (R₁ᵀ e), ∂g/∂ψ₂ = w × (R₂ᵀ d₁) (Bauchau 2011), and
  // g̈ = G a + (ω₁ × (ω₁ × d₁))·e + 2 ḋ₁·(ω₂ × e) + d₁·(ω₂ × (ω₂ × e)). On a cable point
  // d₁ = r' = Σ w'_b q_b, linear in q: ∂g/∂q_b = w'_b e and no convective term of its own.
  std::array<Perpendicular, 3> perpendiculars;
  const int num_perpendiculars = CollectPerpendiculars(joint, &perpendiculars);
  for (int p = 0; p < num_perpendiculars; ++p) {
    const Vector3d& u = *perpendiculars[p].u;
    const Vector3d& w = *perpendiculars[p].w;
    const Vector3d d1 = FirstDirection(m1, u);
    const Vector3d d1_rate = FirstDirectionRate(m1, u);
    const Vector3d e = r2 * w;
    const double convective = (m1.has_slope ? 0.0 : w1.cross(w1.cross(d1)).dot(e)) +
                              2.0 * d1_rate.dot(w2.cross(e)) + d1.dot(w2.cross(w2.cross(e)));
    Row& r = next_row(d1.dot(e), convective, 1.0);
    if (IsBody(m1)) r.gradient[psi1] = u.cross(r1.transpose() * e);
    if (m1.has_slope)
      for (int k = 0; k < n1; ++k) r.gradient[k] = m1.slope_weight[k] * e;
    if (IsBody(m2)) r.gradient[psi2] = w.cross(r2.transpose() * d1);
  }
  if (joint.type == IdealJoint::Type::kWeld) {
    // Slope g = r'₁ − R₂ t: G = (w'_b I, R₂ t̃ on ψ₂), Ġv = −ω₂ × (ω₂ × R₂ t).
    const Vector3d slope = r2 * joint.slope_in_second;
    const Vector3d convective = -w2.cross(w2.cross(slope));
    const Matrix3d on_psi2 = r2 * Skew(joint.slope_in_second);
    for (int i = 0; i < 3; ++i) {
      Row& r = next_row(m1.slope[i] - slope[i], convective[i], 1.0);
      for (int k = 0; k < n1; ++k) r.gradient[k] = m1.slope_weight[k] * Vector3d::Unit(i);
      if (IsBody(m2)) r.gradient[psi2] = on_psi2.row(i).transpose();
    }
  }
}

double JointConstraints::MaxViolation() const {
  return empty() ? 0.0 : violation_.cwiseAbs().maxCoeff();
}

double JointConstraints::ScaledViolation(double rtol, double atol) const {
  double scaled = 0.0;
  for (Index i = 0; i < size(); ++i)
    scaled = std::max(scaled, std::abs(violation_[i]) / (atol + rtol * rows_[i].length_scale));
  return scaled;
}

JointReaction JointConstraints::CalcReaction(Index joint, const VectorXd& lambda) const {
  // The residual carries +Gᵀλ, so the joint's generalised force is −Gᵀλ: on the second side's
  // position equations −(−λ) = λ, and on a body's ψ the moment in its frame, R_B m_B = m_W.
  const IdealJoint& spec = model_.ideal_joints()[joint];
  const AnchorMotion& m1 = first_motion_[joint];
  const AnchorMotion& m2 = second_motion_[joint];
  const Matrix3d& r2 = m2.rotation;
  Index row = first_row_[joint];
  JointReaction reaction;
  if (HasCoincidence(spec.type)) {
    reaction.force = lambda.segment<3>(row);
    row += 3;
  }
  if (HasInPlane(spec.type)) {
    // λ e on the second, acting at the first's centre on the line: about c₂ its moment is
    // d × λ e, the −λ R₂ (w × R₂ᵀ d) of the rows on ψ₂.
    for (const Vector3d* w : {&spec.normal1_in_second, &spec.normal2_in_second})
      reaction.force += lambda[row++] * (r2 * *w);
    reaction.moment = (m1.center - m2.center).cross(reaction.force);
  }
  // A perpendicularity equation's −λ R₂ (w × R₂ᵀ d₁) = λ d₁ × e.
  std::array<Perpendicular, 3> perpendiculars;
  const int num_perpendiculars = CollectPerpendiculars(spec, &perpendiculars);
  for (int p = 0; p < num_perpendiculars; ++p)
    reaction.moment += lambda[row++] * FirstDirection(m1, *perpendiculars[p].u)
                                           .cross(r2 * *perpendiculars[p].w);
  if (spec.type == IdealJoint::Type::kWeld)
    // −R₂ (R₂ t̃)ᵀ λ = (R₂ t) × λ.
    reaction.moment = (r2 * spec.slope_in_second).cross(lambda.segment<3>(row));
  return reaction;
}

VectorXd JointConstraints::CalcRate(const VectorXd& v) const {
  VectorXd rate = VectorXd::Zero(size());
  for (Index i = 0; i < size(); ++i) {
    const std::vector<Index>& blocks = joint_blocks_[rows_[i].joint];
    for (std::size_t k = 0; k < blocks.size(); ++k)
      rate[i] += rows_[i].gradient[k].dot(v.segment<3>(blocks[k]));
  }
  return rate;
}

void JointConstraints::AddReaction(const VectorXd& lambda, VectorXd* force) const {
  for (Index i = 0; i < size(); ++i) {
    const std::vector<Index>& blocks = joint_blocks_[rows_[i].joint];
    for (std::size_t k = 0; k < blocks.size(); ++k)
      force->segment<3>(blocks[k]) += lambda[i] * rows_[i].gradient[k];
  }
}

void JointConstraints::AddGeometricStiffness(const VectorXd& lambda, double scale,
                                             SystemMatrix* matrix) const {
  const auto& joints = model_.ideal_joints();
  std::array<std::array<Matrix3d, kMaxBlocks>, kMaxBlocks> h;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const IdealJoint& joint = joints[j];
    const AnchorMotion& m1 = first_motion_[j];
    const AnchorMotion& m2 = second_motion_[j];
    const int n1 = m1.num_blocks;
    const int n = n1 + m2.num_blocks;
    const int psi1 = 1;
    const int psi2 = n1 + 1;
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < n; ++l) h[k][l].setZero();
    // The Hessian of λᵀ g over each anchor's own blocks, for a force f on its centre.
    auto add_center_force = [&](const Vector3d& f) {
      for (int k = 0; k < n1; ++k)
        for (int l = 0; l < n1; ++l) h[k][l] += m1.GeometricStiffness(k, l, f, Vector3d::Zero());
      for (int k = 0; k < m2.num_blocks; ++k)
        for (int l = 0; l < m2.num_blocks; ++l)
          h[n1 + k][n1 + l] += m2.GeometricStiffness(k, l, -f, Vector3d::Zero());
    };
    Index row = first_row_[j];
    const Matrix3d& r1 = m1.rotation;
    const Matrix3d& r2 = m2.rotation;
    if (HasCoincidence(joint.type)) {
      add_center_force(lambda.segment<3>(row));
      row += 3;
    }
    if (HasInPlane(joint.type)) {
      const Vector3d d = m1.center - m2.center;
      for (const Vector3d* w : {&joint.normal1_in_second, &joint.normal2_in_second}) {
        const double l = lambda[row++];
        const Vector3d e = r2 * *w;
        add_center_force(l * e);
        if (!IsBody(m2)) continue;
        // e turns with the second: ∂e/∂ψ₂ = −R₂ w̃, and its gradient w × (R₂ᵀ d) on ψ₂
        // depends on d and R₂.
        const Matrix3d de = -r2 * Skew(*w);
        for (int k = 0; k < n1; ++k) {
          h[k][psi2] += l * m1.a[k].transpose() * de;
          h[psi2][k] += l * Skew(*w) * r2.transpose() * m1.a[k];
        }
        for (int k = 0; k < m2.num_blocks; ++k) {
          h[n1 + k][psi2] -= l * m2.a[k].transpose() * de;
          h[psi2][n1 + k] -= l * Skew(*w) * r2.transpose() * m2.a[k];
        }
        h[psi2][psi2] += l * Skew(*w) * Skew(r2.transpose() * d);
      }
    }
    // ∂/∂ψ₁ (u × R₁ᵀ e) = ũ (R₁ᵀ e)~, ∂/∂ψ₂ (u × R₁ᵀ e) = −ũ R₁ᵀ R₂ w̃, and the same with the
    // sides exchanged.
    std::array<Perpendicular, 3> perpendiculars;
    const int num_perpendiculars = CollectPerpendiculars(joint, &perpendiculars);
    for (int p = 0; p < num_perpendiculars; ++p) {
      const Vector3d& u = *perpendiculars[p].u;
      const Vector3d& w = *perpendiculars[p].w;
      const double l = lambda[row++];
      const Vector3d d1 = FirstDirection(m1, u);
      const Vector3d e = r2 * w;
      if (IsBody(m1)) h[psi1][psi1] += l * Skew(u) * Skew(r1.transpose() * e);
      if (IsBody(m2)) h[psi2][psi2] += l * Skew(w) * Skew(r2.transpose() * d1);
      if (IsBody(m1) && IsBody(m2)) {
        h[psi1][psi2] -= l * Skew(u) * r1.transpose() * r2 * Skew(w);
        h[psi2][psi1] -= l * Skew(w) * r2.transpose() * r1 * Skew(u);
      }
      // A cable point's slope against a turning second side: ∂(w'_k e)/∂ψ₂ = −w'_k R₂ w̃ and
      // ∂(w × R₂ᵀ r')/∂q_k = w'_k w̃ R₂ᵀ.
      if (m1.has_slope && IsBody(m2))
        for (int k = 0; k < n1; ++k) {
          h[k][psi2] -= l * m1.slope_weight[k] * r2 * Skew(w);
          h[psi2][k] += l * m1.slope_weight[k] * Skew(w) * r2.transpose();
        }
    }
    if (joint.type == IdealJoint::Type::kWeld && IsBody(m2))
      // ∂/∂ψ₂ ((R₂ t̃)ᵀ λ) = −t̃ (R₂ᵀ λ)~.
      h[psi2][psi2] -=
          Skew(joint.slope_in_second) * Skew(r2.transpose() * lambda.segment<3>(row));
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < n; ++l)
        matrix->AddIdealJointBlock(static_cast<Index>(j), k, l, h[k][l], scale);
  }
}

void JointConstraints::AssembleBorderedMatrix(const SparseMatrixd& s, const DofMap& dofs,
                                              SparseMatrixd* out) {
  const Index n = dofs.num_unknowns();
  triplets_.clear();
  for (Index k = 0; k < s.outerSize(); ++k)
    for (SparseMatrixd::InnerIterator it(s, k); it; ++it)
      triplets_.emplace_back(it.row(), it.col(), it.value());
  for (Index i = 0; i < size(); ++i) {
    const std::vector<Index>& blocks = joint_blocks_[rows_[i].joint];
    for (std::size_t k = 0; k < blocks.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        const Index col = dofs.unknown(blocks[k] + c);
        if (col < 0) continue;
        const double value = rows_[i].gradient[k][c];
        triplets_.emplace_back(n + i, col, value);
        triplets_.emplace_back(col, n + i, value);
      }
  }
  out->resize(n + size(), n + size());
  out->setFromTriplets(triplets_.begin(), triplets_.end());
  out->makeCompressed();
}

}  // namespace ancfnet
