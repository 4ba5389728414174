#include "ancfnet/elements/ancf_cable.hpp"

#include <algorithm>
#include <cmath>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/common/skew.hpp"
#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/elements/rope_law.hpp"

namespace ancfnet {
namespace {

using Matrix34d = Eigen::Matrix<double, 3, 4>;
using Matrix12x3d = Eigen::Matrix<double, 12, 3>;

// κ_ε L_e: curvature (times element length) around which bending damping passes from the rate of
// the curvature vector (near straight) to the rate of its magnitude (bent). A bent element in
// rigid rotation dissipates a fraction κ_ε²/(κ² + κ_ε²) of what the vector rate would give.
constexpr double kCurvatureBlend = 1e-3;

// K += scale · (u vᵀ ⊗ X): the 12×12 matrix whose 3×3 block (j, l) is u_j v_l X. Every term of
// the cable's Jacobians has this Kronecker form because S = [S1 I, …, S4 I].
void AddKronecker(const Vector4d& u, const Vector4d& v, const Matrix3d& x, double scale,
                  Matrix12d& k) {
  for (int j = 0; j < 4; ++j)
    for (int l = 0; l < 4; ++l) k.block<3, 3>(3 * j, 3 * l) += (scale * u[j] * v[l]) * x;
}

// K += scale · (u vᵀ ⊗ I).
void AddKroneckerIdentity(const Vector4d& u, const Vector4d& v, double scale, Matrix12d& k) {
  for (int j = 0; j < 4; ++j)
    for (int l = 0; l < 4; ++l)
      k.block<3, 3>(3 * j, 3 * l).diagonal().array() += scale * u[j] * v[l];
}

// 12×3 matrix whose 3×3 block j is u_j X + v_j Y.
Matrix12x3d StackBlocks(const Vector4d& u, const Matrix3d& x, const Vector4d& v,
                        const Matrix3d& y) {
  Matrix12x3d m;
  for (int j = 0; j < 4; ++j) m.block<3, 3>(3 * j, 0) = u[j] * x + v[j] * y;
  return m;
}

// The smooth rope law at one Gauss point: N = EA φ(ε) + EA τ φ'(ε) ε̇ with φ of
// elements/rope_law.hpp, so that Newton sees no kink where a thread goes slack. de = ∂ε/∂e,
// de_dot = ∂ε̇/∂e.
void AddSmoothRopeTerms(const CableElementParameters& p, double strain, double strain_rate,
                        const Vector12d& de, const Vector12d& de_dot, const Vector4d& ds,
                        double weight, const CableForceOutputs& out) {
  const RopeLawValue phi = CalcSmoothRopeLaw(strain, p.rope_smoothing_strain);
  const double ea = p.axial_stiffness;
  const double ea_tau = ea * p.axial_damping_time;
  const double viscous_n = ea_tau * phi.slope * strain_rate;
  const double n = ea * phi.force + viscous_n;
  if (out.force) *out.force += (weight * n) * de;
  if (out.viscous_force) *out.viscous_force += (weight * viscous_n) * de;
  if (out.stiffness) {
    const double dn_dstrain = ea * phi.slope + ea_tau * phi.curvature * strain_rate;
    out.stiffness->noalias() += (weight * dn_dstrain) * de * de.transpose();
    AddKroneckerIdentity(ds, ds, weight * n, *out.stiffness);
    if (ea_tau > 0.0)
      out.stiffness->noalias() += (weight * ea_tau * phi.slope) * de * de_dot.transpose();
  }
  if (out.damping && ea_tau > 0.0)
    out.damping->noalias() += (weight * ea_tau * phi.slope) * de * de.transpose();
}

// Axial term at one Gauss point of weight w·L: N ∂ε/∂e with ∂ε/∂e = Sₓᵀ r'.
// Gerstmayr & Shabana (2006), eq. 9 and 14; tangent from differentiating once more.
void AddAxialTerms(const CableElementParameters& p, const Matrix34d& e, const Matrix34d& e_dot,
                   const Vector4d& ds, double weight, const CableForceOutputs& out) {
  const Vector3d a = e * ds;
  const Vector3d a_dot = e_dot * ds;
  const double strain = 0.5 * (a.squaredNorm() - 1.0);
  const double strain_rate = a.dot(a_dot);
  const double ea = p.axial_stiffness;
  const double viscous_n = ea * p.axial_damping_time * strain_rate;
  const double n = ea * strain + viscous_n;
  if (p.tension_only && p.rope_smoothing_strain > 0.0)
    return AddSmoothRopeTerms(p, strain, strain_rate, DistributeForce(ds, a),
                              DistributeForce(ds, a_dot), ds, weight, out);
  // A rope carries no axial force while slack, and never pushes: N = max(EA (ε + τ ε̇), 0).
  if (p.tension_only && strain <= 0.0) return;
  if (p.tension_only && n <= 0.0) {
    // Stretched but shortening faster than ε/τ: the dashpot takes up the whole elastic force, so
    // N = 0 is EA ε (elastic, stored in U) plus −EA ε (viscous, dissipated).
    if (out.viscous_force) *out.viscous_force -= (weight * ea * strain) * DistributeForce(ds, a);
    return;
  }
  const Vector12d de = DistributeForce(ds, a);
  if (out.force) *out.force += (weight * n) * de;
  if (out.viscous_force) *out.viscous_force += (weight * viscous_n) * de;
  if (out.stiffness) {
    out.stiffness->noalias() += (weight * ea) * de * de.transpose();
    AddKroneckerIdentity(ds, ds, weight * n, *out.stiffness);
    if (p.axial_damping_time > 0.0)
      out.stiffness->noalias() +=
          (weight * ea * p.axial_damping_time) * de * DistributeForce(ds, a_dot).transpose();
  }
  if (out.damping && p.axial_damping_time > 0.0)
    out.damping->noalias() += (weight * ea * p.axial_damping_time) * de * de.transpose();
}

// Bending term at one Gauss point, with the curvature vector k = h c, c = r' × r'', h = g^{-3/2},
// g = r'·r' (|k| = κ, Gerstmayr & Shabana 2006, eq. 11). Elastic part EI kᵀ ∂k/∂e. Damping from
// the dissipation function D = ½ EI τ ((k·k̇)² + κ_ε² |k̇|²) / (κ² + κ_ε²): ½ EI τ κ̇² once the
// element is bent (κ ≫ κ_ε), so that a bent element in rigid rotation (k̇ = ω × k, k·k̇ = 0)
// dissipates next to nothing, and ½ EI τ |k̇|² near straight, where the direction of κ̇ is
// undefined. Its force ∂D/∂ė = Jᵀ m_v with m_v = EI τ ((k·k̇) k + κ_ε² k̇) / (κ² + κ_ε²).
// Derivatives in docs/theory.md, "Bending".
void AddBendingTerms(const CableElementParameters& p, const Matrix34d& e, const Matrix34d& e_dot,
                     const Vector4d& ds, const Vector4d& dds, double weight,
                     const CableForceOutputs& out) {
  const Vector3d a = e * ds;
  const Vector3d b = e * dds;
  const double g = a.squaredNorm();
  const double h = 1.0 / (g * std::sqrt(g));  // g^{-3/2}
  const Vector3d c = a.cross(b);
  const Vector3d k = h * c;
  const Vector12d da = DistributeForce(ds, a);   // ∂g/∂e / 2
  const Vector12d grad_h = (-3.0 * h / g) * da;  // ∂h/∂e
  // Jᵀ x = h (∂c/∂e)ᵀ x + ∇h (c·x), with block j of (∂c/∂e)ᵀ x equal to S′_j (b × x) − S″_j (a ×
  // x): the force path needs no 12×3 matrix.
  const auto apply_jt = [&](const Vector3d& x) -> Vector12d {
    return h * (DistributeForce(ds, b.cross(x)) - DistributeForce(dds, a.cross(x))) +
           c.dot(x) * grad_h;
  };

  const double ei = p.bending_stiffness;
  const double ei_tau = ei * p.bending_damping_time;
  const bool damped = ei_tau > 0.0;
  const double g52 = h / g;  // g^{-5/2}
  const Vector3d a_dot = e_dot * ds;
  const Vector3d b_dot = e_dot * dds;
  const double a_adot = a.dot(a_dot);
  const double h_dot = -3.0 * g52 * a_adot;
  const Vector3d c_dot = a_dot.cross(b) + a.cross(b_dot);
  const Vector3d k_dot = damped ? Vector3d(h * c_dot + h_dot * c) : Vector3d::Zero();  // J ė
  const double kappa_eps = kCurvatureBlend / p.length;
  const double eps2 = kappa_eps * kappa_eps;
  const double d = k.squaredNorm() + eps2;
  const double s = k.dot(k_dot);  // κ κ̇
  const Vector3d m_viscous = (ei_tau / d) * (s * k + eps2 * k_dot);
  const Vector3d m = ei * k + m_viscous;  // moment vector conjugate to k

  if (out.force) out.force->noalias() += weight * apply_jt(m);
  if (out.viscous_force && damped) out.viscous_force->noalias() += weight * apply_jt(m_viscous);
  if (!out.stiffness && !(out.damping && damped)) return;

  const Matrix12x3d dc_t = StackBlocks(ds, Skew(b), dds, -Skew(a));  // (∂c/∂e)ᵀ
  const Matrix12x3d jk_t = h * dc_t + grad_h * c.transpose();        // Jᵀ = (∂k/∂e)ᵀ
  const Vector12d jk = apply_jt(k);                                  // Jᵀ k = κ ∂κ/∂e
  if (out.damping && damped)
    out.damping->noalias() +=
        (weight * ei_tau / d) * (jk * jk.transpose() + eps2 * jk_t * jk_t.transpose());
  if (!out.stiffness) return;

  Matrix12d& kt = *out.stiffness;
  kt.noalias() += (weight * ei) * jk_t * jk_t.transpose();
  // Σ_i m_i ∂²k_i/∂e² = h Σ m_i ∂²c_i + (∂cᵀm) ∇hᵀ + ∇h (∂cᵀm)ᵀ + (m·c) ∂²h.
  const Matrix3d m_skew = Skew(m);
  AddKronecker(dds, ds, m_skew, weight * h, kt);
  AddKronecker(ds, dds, m_skew, -weight * h, kt);
  const Vector12d dc_m = dc_t * m;
  kt.noalias() += weight * (dc_m * grad_h.transpose() + grad_h * dc_m.transpose());
  const double mc = weight * m.dot(c);
  kt.noalias() += (mc * 15.0 * g52 / g) * da * da.transpose();
  AddKroneckerIdentity(ds, ds, -3.0 * mc * g52, kt);
  if (!damped) return;
  // m_v depends on e through k, k̇ = J ė and d: Jᵀ ∂m_v/∂e = EI τ/d (Jᵀk ∇sᵀ + s JᵀJ
  // + κ_ε² Jᵀ ∂k̇/∂e) − (2/d) Jᵀm_v (Jᵀk)ᵀ, with ∇s = Jᵀ k̇ + (∂k̇/∂e)ᵀ k, where column i of
  // (∂k̇/∂e)ᵀ is (∂²k_i/∂e²) ė = h ∂²c_i ė + ∇c_i ḣ + ∇h ċ_i + c_i ∂²h ė.
  const Vector12d hess_h_edot =
      (15.0 * g52 / g * a_adot) * da - 3.0 * g52 * DistributeForce(ds, a_dot);
  const Matrix12x3d hess_c_edot = StackBlocks(dds, -Skew(a_dot), ds, Skew(b_dot));
  const Matrix12x3d dk_dot_t =
      h * hess_c_edot + h_dot * dc_t + grad_h * c_dot.transpose() + hess_h_edot * c.transpose();
  const Vector12d grad_s = jk_t * k_dot + dk_dot_t * k;
  const double scale = weight * ei_tau / d;
  kt.noalias() += scale * (jk * grad_s.transpose() + s * jk_t * jk_t.transpose() +
                           eps2 * jk_t * dk_dot_t.transpose());
  kt.noalias() -= (2.0 * weight / d) * (jk_t * m_viscous) * jk.transpose();
}

// Simple bending at one Gauss point: U_b = ½ EI |r''|², Q = EI S''ᵀ r'' (Berzeri & Shabana 2000),
// with Kelvin–Voigt damping EI τ S''ᵀ ṙ''. Constant, symmetric Jacobians EI (S'' S''ᵀ ⊗ I).
void AddSecondDerivativeBendingTerms(const CableElementParameters& p, const Matrix34d& e,
                                     const Matrix34d& e_dot, const Vector4d& dds, double weight,
                                     const CableForceOutputs& out) {
  const double ei = weight * p.bending_stiffness;
  const double ei_tau = ei * p.bending_damping_time;
  const Vector3d b_dot = e_dot * dds;
  if (out.force) out.force->noalias() += DistributeForce(dds, ei * (e * dds) + ei_tau * b_dot);
  if (out.viscous_force && ei_tau > 0.0)
    out.viscous_force->noalias() += DistributeForce(dds, ei_tau * b_dot);
  if (out.stiffness) AddKroneckerIdentity(dds, dds, ei, *out.stiffness);
  if (out.damping && ei_tau > 0.0) AddKroneckerIdentity(dds, dds, ei_tau, *out.damping);
}

}  // namespace

void CalcCableInternalForce(const CableElementParameters& p, const Vector12d& e,
                            const Vector12d& e_dot, const CableForceOutputs& out) {
  if (out.force) out.force->setZero();
  if (out.viscous_force) out.viscous_force->setZero();
  if (out.stiffness) out.stiffness->setZero();
  if (out.damping) out.damping->setZero();
  const Eigen::Map<const Matrix34d> e_mat(e.data());
  const Eigen::Map<const Matrix34d> e_dot_mat(e_dot.data());

  const GaussRule& axial = GetGaussRule(p.axial_gauss_points);
  for (int i = 0; i < axial.size; ++i) {
    const HermiteShape shape = CalcHermiteShape(axial.points[i], p.length);
    AddAxialTerms(p, e_mat, e_dot_mat, shape.ds, axial.weights[i] * p.length, out);
  }
  if (p.bending_stiffness == 0.0) return;
  const GaussRule& bending = GetGaussRule(p.bending_gauss_points);
  for (int i = 0; i < bending.size; ++i) {
    const HermiteShape shape = CalcHermiteShape(bending.points[i], p.length);
    const double weight = bending.weights[i] * p.length;
    if (p.bending_model == BendingModel::kSecondDerivative)
      AddSecondDerivativeBendingTerms(p, e_mat, e_dot_mat, shape.dds, weight, out);
    else
      AddBendingTerms(p, e_mat, e_dot_mat, shape.ds, shape.dds, weight, out);
  }
}

CableStrain CalcCableStrain(const CableElementParameters& p, const Vector12d& e, double xi) {
  const HermiteShape shape = CalcHermiteShape(xi, p.length);
  const Eigen::Map<const Matrix34d> e_mat(e.data());
  const Vector3d a = e_mat * shape.ds;
  const Vector3d b = e_mat * shape.dds;
  CableStrain strain;
  strain.axial = 0.5 * (a.squaredNorm() - 1.0);
  const double g = a.squaredNorm();
  strain.curvature = a.cross(b).norm() / (g * std::sqrt(g));
  return strain;
}

double CalcCableAxialForce(const CableElementParameters& p, double strain) {
  if (!p.tension_only) return p.axial_stiffness * strain;
  if (p.rope_smoothing_strain > 0.0)
    return p.axial_stiffness * CalcSmoothRopeLaw(strain, p.rope_smoothing_strain).force;
  return p.axial_stiffness * std::max(strain, 0.0);
}

double CalcCableAxialEnergyDensity(const CableElementParameters& p, double strain) {
  const double ea = p.axial_stiffness;
  if (!p.tension_only) return 0.5 * ea * strain * strain;
  if (p.rope_smoothing_strain > 0.0)
    return ea * CalcSmoothRopeLaw(strain, p.rope_smoothing_strain).energy;
  const double stretch = std::max(strain, 0.0);
  return 0.5 * ea * stretch * stretch;
}

double CalcCableStrainEnergy(const CableElementParameters& p, const Vector12d& e) {
  double energy = 0.0;
  const GaussRule& axial = GetGaussRule(p.axial_gauss_points);
  for (int i = 0; i < axial.size; ++i) {
    const double eps = CalcCableStrain(p, e, axial.points[i]).axial;
    energy += axial.weights[i] * p.length * CalcCableAxialEnergyDensity(p, eps);
  }
  const GaussRule& bending = GetGaussRule(p.bending_gauss_points);
  for (int i = 0; i < bending.size; ++i) {
    double measure = 0.0;  // κ², or |r''|² for the simple model
    if (p.bending_model == BendingModel::kSecondDerivative) {
      const HermiteShape shape = CalcHermiteShape(bending.points[i], p.length);
      measure = (Eigen::Map<const Matrix34d>(e.data()) * shape.dds).squaredNorm();
    } else {
      const double kappa = CalcCableStrain(p, e, bending.points[i]).curvature;
      measure = kappa * kappa;
    }
    energy += 0.5 * bending.weights[i] * p.length * p.bending_stiffness * measure;
  }
  return energy;
}

Matrix12d CalcCableMassMatrix(const CableElementParameters& p) {
  const GaussRule& rule = GetGaussRule(4);  // S_i S_j is of degree 6: exact with 4 points
  Matrix4d m = Matrix4d::Zero();
  for (int i = 0; i < rule.size; ++i) {
    const HermiteShape shape = CalcHermiteShape(rule.points[i], p.length);
    m.noalias() += (rule.weights[i] * p.length * p.mass_per_length) * shape.s * shape.s.transpose();
  }
  Matrix12d mass = Matrix12d::Zero();
  for (int j = 0; j < 4; ++j)
    for (int l = 0; l < 4; ++l) mass.block<3, 3>(3 * j, 3 * l).diagonal().setConstant(m(j, l));
  return mass;
}

Vector12d CalcCableDistributedForce(const CableElementParameters& p, const Vector3d& w) {
  const double L = p.length;
  Vector4d integral_s;  // ∫₀ᴸ S dx, exact
  integral_s << L / 2.0, L * L / 12.0, L / 2.0, -L * L / 12.0;
  return DistributeForce(integral_s, w);
}

}  // namespace ancfnet
