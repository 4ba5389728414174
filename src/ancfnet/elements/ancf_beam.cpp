#include "ancfnet/elements/ancf_beam.hpp"

#include <array>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/beam_strain_jet.hpp"

namespace ancfnet {
namespace {

// Gauss points of the shear, torsion and bending strains (two: the assumed shear strain).
constexpr int kSectionPoints = 2;

// Strains sampled at one of the two section points, in this order.
constexpr int kRawPerPoint = 7;
constexpr int kRawSize = kSectionPoints * kRawPerPoint;
enum RawStrain : int { kG2 = 0, kG3, kG2x, kG3x, kK1, kK2, kK3 };
// Generalised strains at one section point: Γ₂, Γ₃, K₁, K₂, K₃, δ₂, δ₃.
constexpr int kGeneralisedPerPoint = 7;

using RawMatrix = Eigen::Matrix<double, kRawSize, kRawSize>;

// Γ₁ = r'·(d₂ × d₃) / (|d₂| |d₃|) − 1 (eq. B4).
StrainJet AxialStrain(const BeamLocalVector& u, bool h) {
  StrainJet j = TripleJet(u, kSlope, kD2, kD3, h) * InverseNormPowerJet(u, kD2, 1, h) *
                InverseNormPowerJet(u, kD3, 1, h);
  j.value -= 1.0;
  return j;
}

// The seven strains at a section point (eq. B5–B9):
//   Γ₂ = r'·d₂/|d₂|, Γ₃ = r'·d₃/|d₃| and their derivatives along the axis,
//   K₁ = ½ (d₃·d₂' − d₂·d₃') / (|d₂||d₃|), K₂ = [d₂, d₃, d₃'] / (|d₂||d₃|²),
//   K₃ = −[d₂, d₃, d₂'] / (|d₂|²|d₃|).
std::array<StrainJet, kRawPerPoint> SectionStrains(const BeamLocalVector& u, bool h) {
  const StrainJet c2 = InverseNormPowerJet(u, kD2, 1, h);
  const StrainJet c3 = InverseNormPowerJet(u, kD3, 1, h);
  const StrainJet c2_sq = InverseNormPowerJet(u, kD2, 2, h);
  const StrainJet c3_sq = InverseNormPowerJet(u, kD3, 2, h);
  std::array<StrainJet, kRawPerPoint> s;
  const auto shear_and_rate = [&](int d, int dx, const StrainJet& c, StrainJet& g, StrainJet& g_x) {
    const StrainJet t_d = DotJet(u, kSlope, d, h);
    g = t_d * c;
    // (r'·d/|d|)' = (r''·d + r'·d') /|d| − (r'·d)(d·d') /|d|³
    const StrainJet rate =
        Combine(1.0, DotJet(u, kCurvatureVector, d, h), 1.0, DotJet(u, kSlope, dx, h));
    g_x = Combine(1.0, rate * c, -1.0, t_d * DotJet(u, d, dx, h) * InverseNormPowerJet(u, d, 3, h));
  };
  shear_and_rate(kD2, kD2x, c2, s[kG2], s[kG2x]);
  shear_and_rate(kD3, kD3x, c3, s[kG3], s[kG3x]);
  s[kK1] = Combine(0.5, DotJet(u, kD3, kD2x, h), -0.5, DotJet(u, kD2, kD3x, h)) * c2 * c3;
  s[kK2] = TripleJet(u, kD2, kD3, kD3x, h) * c2 * c3_sq;
  s[kK3] = TripleJet(u, kD3, kD2, kD2x, h) * c2_sq * c3;  // [d₃, d₂, d₂'] = −[d₂, d₃, d₂']
  return s;
}

// Cross-section penalties at a node (ξ = 0 or 1), where the directors are nodal coordinates, so
// that the chord of a linearly interpolated, turning director is not penalised (eq. B11):
// π₁ = ½(|d₂|² − 1), π₂ = ½(|d₃|² − 1), π₃ = d₂·d₃.
std::array<StrainJet, 3> SectionPenaltyStrains(const BeamLocalVector& u, bool h) {
  return {HalfStretchJet(u, kD2, h), HalfStretchJet(u, kD3, h), DotJet(u, kD2, kD3, h)};
}

// The energy of the section points is ½ Rᵀ C R in the raw strains R of both points, with
// C = Aᵀ W D A: A maps R to the generalised strains Γ₂, Γ₃, K₁, K₂, K₃ and the shear remainders
// δ₂ = −Γ₃' + ΔΓ₃/Δx, δ₃ = Γ₂' − ΔΓ₂/Δx (eq. B10); D is the section stiffness (EI_y, EI_z for
// the remainders) and W the Gauss weights. The force strains Γ₂, Γ₃ are scaled by
// `force_scale`, the moment strains by `moment_scale`: (1, 1) gives C, (τ_ε, τ_κ) the
// Kelvin–Voigt matrix C_v of the rates (eq. B14).
RawMatrix SectionEnergyMatrix(const BeamElementParameters& p, double force_scale,
                              double moment_scale) {
  const GaussRule& rule = GetGaussRule(kSectionPoints);
  const double dx = p.length * (rule.points[1] - rule.points[0]);
  Eigen::Matrix<double, kSectionPoints * kGeneralisedPerPoint, kRawSize> a;
  a.setZero();
  Eigen::Matrix<double, kSectionPoints * kGeneralisedPerPoint, 1> wd;
  for (int k = 0; k < kSectionPoints; ++k) {
    const int row = kGeneralisedPerPoint * k;
    const int col = kRawPerPoint * k;
    a(row + 0, col + kG2) = 1.0;
    a(row + 1, col + kG3) = 1.0;
    a(row + 2, col + kK1) = 1.0;
    a(row + 3, col + kK2) = 1.0;
    a(row + 4, col + kK3) = 1.0;
    a(row + 5, col + kG3x) = -1.0;  // δ₂
    a(row + 5, kG3) = -1.0 / dx;
    a(row + 5, kRawPerPoint + kG3) = 1.0 / dx;
    a(row + 6, col + kG2x) = 1.0;  // δ₃
    a(row + 6, kG2) = 1.0 / dx;
    a(row + 6, kRawPerPoint + kG2) = -1.0 / dx;
    wd.segment<kGeneralisedPerPoint>(row) << force_scale * p.shear_stiffness_y,
        force_scale * p.shear_stiffness_z, moment_scale * p.torsional_stiffness,
        moment_scale * p.bending_stiffness_y, moment_scale * p.bending_stiffness_z,
        moment_scale * p.bending_stiffness_y, moment_scale * p.bending_stiffness_z;
    wd.segment<kGeneralisedPerPoint>(row) *= rule.weights[k] * p.length;
  }
  return a.transpose() * wd.asDiagonal() * a;
}

// Strains sampled at `kPoints` points of the axis, `kPerPoint` at each, with the maps of the
// points.
template <int kPoints, int kPerPoint>
struct StrainSet {
  static constexpr int kSize = kPoints * kPerPoint;
  using Matrix = Eigen::Matrix<double, kSize, kSize>;
  std::array<BeamLocalMap, kPoints> maps;
  std::array<std::array<StrainJet, kPerPoint>, kPoints> strains;
};

// For strains s with the energy ½ sᵀ C s and the Kelvin–Voigt stresses C_v ṡ (c_visc null:
// undamped), adds to `out` the force Σ σᵢ ∇sᵢ with σ = C s + C_v ṡ, its viscous part, the
// stiffness Σ σᵢ ∇²sᵢ + G C Gᵀ + G C_v Ṡᵀ and the damping G C_v Gᵀ, where G = [∇sᵢ] and
// Ṡ = [∇ṡᵢ], ∇ṡᵢ = ∇²sᵢ ė (eq. B14, B15); returns ½ sᵀ C s.
template <int kPoints, int kPerPoint>
double AddStrainTerms(const StrainSet<kPoints, kPerPoint>& set,
                      const typename StrainSet<kPoints, kPerPoint>::Matrix& c,
                      const typename StrainSet<kPoints, kPerPoint>::Matrix* c_visc,
                      const Vector24d& e_dot, const BeamForceOutputs& out) {
  constexpr int n = StrainSet<kPoints, kPerPoint>::kSize;
  using Vector = Eigen::Matrix<double, n, 1>;
  using Gradients = Eigen::Matrix<double, kBeamElementDofs, n>;
  const bool gradients = out.stiffness || (out.damping && c_visc);
  std::array<BeamLocalVector, kPoints> u_dot;
  Vector raw, rate = Vector::Zero();
  for (int k = 0; k < kPoints; ++k) {
    if (c_visc) u_dot[k] = MapToLocal(set.maps[k], e_dot);
    for (int i = 0; i < kPerPoint; ++i) {
      const StrainJet& s = set.strains[k][i];
      raw[kPerPoint * k + i] = s.value;
      if (c_visc) rate[kPerPoint * k + i] = s.grad.dot(u_dot[k]);
    }
  }
  const Vector sigma_elastic = c * raw;
  const Vector sigma_visc = c_visc ? Vector(*c_visc * rate) : Vector::Zero();
  const Vector sigma = sigma_elastic + sigma_visc;
  Gradients grads, rate_grads;
  for (int k = 0; k < kPoints; ++k) {
    const BeamLocalMap& map = set.maps[k];
    BeamLocalVector g_u = BeamLocalVector::Zero();
    BeamLocalVector g_visc_u = BeamLocalVector::Zero();
    BeamLocalMatrix h_u;
    if (out.stiffness) h_u.setZero();
    for (int i = 0; i < kPerPoint; ++i) {
      const StrainJet& s = set.strains[k][i];
      const int j = kPerPoint * k + i;
      g_u += sigma[j] * s.grad;
      if (c_visc) g_visc_u += sigma_visc[j] * s.grad;
      if (gradients) grads.col(j) = MapToNodal(map, s.grad);
      if (out.stiffness) {
        h_u += sigma[j] * s.hess;
        if (c_visc) rate_grads.col(j) = MapToNodal(map, s.hess * u_dot[k]);
      }
    }
    if (out.force) *out.force += MapToNodal(map, g_u);
    if (out.viscous_force && c_visc) *out.viscous_force += MapToNodal(map, g_visc_u);
    if (out.stiffness) AddMappedHessian(map, h_u, *out.stiffness);
  }
  if (out.stiffness) {
    out.stiffness->noalias() += grads * c * grads.transpose();
    if (c_visc) out.stiffness->noalias() += grads * (*c_visc) * rate_grads.transpose();
  }
  if (out.damping && c_visc) out.damping->noalias() += grads * (*c_visc) * grads.transpose();
  return 0.5 * raw.dot(sigma_elastic);
}

// The strain energy and, as `out` asks, the force and its Jacobians at (e, ė).
double EvaluateBeam(const BeamElementParameters& p, const Vector24d& e, const Vector24d& e_dot,
                    const BeamForceOutputs& out) {
  for (Vector24d* v : {out.force, out.viscous_force})
    if (v) v->setZero();
  for (Matrix24d* m : {out.stiffness, out.damping})
    if (m) m->setZero();
  const bool h = out.stiffness != nullptr;
  const bool damped = p.axial_damping_time > 0.0 || p.bending_damping_time > 0.0;
  double energy = 0.0;

  const GaussRule& axial = GetGaussRule(kBeamAxialGaussPoints);
  for (int k = 0; k < axial.size; ++k) {
    const BeamLocalMap map = MakeBeamLocalMap(axial.points[k], p.length);
    const StrainSet<1, 1> set{{map}, {{{AxialStrain(MapToLocal(map, e), h)}}}};
    const Eigen::Matrix<double, 1, 1> c(axial.weights[k] * p.length * p.axial_stiffness);
    const Eigen::Matrix<double, 1, 1> c_visc(p.axial_damping_time * c(0, 0));
    energy += AddStrainTerms(set, c, damped ? &c_visc : nullptr, e_dot, out);
  }

  const std::array<BeamLocalMap, 2> nodes = {MakeBeamLocalMap(0.0, p.length),
                                             MakeBeamLocalMap(1.0, p.length)};
  const StrainSet<2, 3> penalties{nodes,
                                  {SectionPenaltyStrains(MapToLocal(nodes[0], e), h),
                                   SectionPenaltyStrains(MapToLocal(nodes[1], e), h)}};
  const double w = 0.5 * p.length;
  const Eigen::Matrix<double, 6, 1> penalty_stiffness =
      (Eigen::Matrix<double, 6, 1>() << p.section_normal_stiffness, p.section_normal_stiffness,
       p.section_shear_stiffness, p.section_normal_stiffness, p.section_normal_stiffness,
       p.section_shear_stiffness)
          .finished();
  energy += AddStrainTerms(penalties, StrainSet<2, 3>::Matrix((w * penalty_stiffness).asDiagonal()),
                           nullptr, e_dot, out);

  const GaussRule& section = GetGaussRule(kSectionPoints);
  static_assert(kSectionPoints == 2);
  const std::array<BeamLocalMap, kSectionPoints> points = {
      MakeBeamLocalMap(section.points[0], p.length), MakeBeamLocalMap(section.points[1], p.length)};
  // Built in place: a strain jet holds an 18 × 18 Hessian, too big to copy around.
  const StrainSet<kSectionPoints, kRawPerPoint> sections{
      points,
      {SectionStrains(MapToLocal(points[0], e), h), SectionStrains(MapToLocal(points[1], e), h)}};
  const RawMatrix c = SectionEnergyMatrix(p, 1.0, 1.0);
  if (!damped) return energy + AddStrainTerms(sections, c, nullptr, e_dot, out);
  const RawMatrix c_visc = SectionEnergyMatrix(p, p.axial_damping_time, p.bending_damping_time);
  return energy + AddStrainTerms(sections, c, &c_visc, e_dot, out);
}

}  // namespace

void CalcBeamInternalForce(const BeamElementParameters& p, const Vector24d& e,
                           const Vector24d& e_dot, const BeamForceOutputs& out) {
  EvaluateBeam(p, e, e_dot, out);
}

double CalcBeamAxialStrain(const BeamElementParameters& p, const Vector24d& e, double xi) {
  return AxialStrain(MapToLocal(MakeBeamLocalMap(xi, p.length), e), false).value;
}

double CalcBeamStrainEnergy(const BeamElementParameters& p, const Vector24d& e) {
  return EvaluateBeam(p, e, Vector24d::Zero(), {});
}

Matrix24d CalcBeamMassMatrix(const BeamElementParameters& p) {
  // Scalar mass matrix over the eight 3-vector blocks; M = m ⊗ I₃.
  Eigen::Matrix<double, kBeamElementBlocks, kBeamElementBlocks> m;
  m.setZero();
  const GaussRule& rule = GetGaussRule(4);  // Hermite products are of degree 6: exact
  for (int k = 0; k < rule.size; ++k) {
    const BeamLocalMap map = MakeBeamLocalMap(rule.points[k], p.length);
    const double w = rule.weights[k] * p.length;
    m.noalias() += (w * p.mass_per_length) * map.position * map.position.transpose();
    m.noalias() += (w * p.rotary_inertia_z) * map.b.row(kD2).transpose() * map.b.row(kD2);
    m.noalias() += (w * p.rotary_inertia_y) * map.b.row(kD3).transpose() * map.b.row(kD3);
  }
  Matrix24d mass = Matrix24d::Zero();
  for (int j = 0; j < kBeamElementBlocks; ++j)
    for (int l = 0; l < kBeamElementBlocks; ++l)
      mass.block<3, 3>(3 * j, 3 * l).diagonal().setConstant(m(j, l));
  return mass;
}

}  // namespace ancfnet
