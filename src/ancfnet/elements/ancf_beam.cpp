#include "ancfnet/elements/ancf_beam.hpp"

#include <array>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/beam_strain_jet.hpp"

namespace ancfnet {
namespace {

// Gauss points of the axial strain (Γ₁ of a cubic axis is quadratic in ξ: three points leave no
// zero-energy mode) and of the shear, torsion and bending strains (two: the assumed shear strain).
constexpr int kAxialPoints = 3;
constexpr int kSectionPoints = 2;

// Strains sampled at one of the two section points, in this order.
constexpr int kRawPerPoint = 7;
constexpr int kRawSize = kSectionPoints * kRawPerPoint;
enum RawStrain : int { kG2 = 0, kG3, kG2x, kG3x, kK1, kK2, kK3 };
// Generalised strains at one section point: Γ₂, Γ₃, K₁, K₂, K₃, δ₂, δ₃.
constexpr int kGeneralisedPerPoint = 7;

using RawVector = Eigen::Matrix<double, kRawSize, 1>;
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
// the remainders) and W the Gauss weights.
RawMatrix SectionEnergyMatrix(const BeamElementParameters& p) {
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
    wd.segment<kGeneralisedPerPoint>(row) << p.shear_stiffness_y, p.shear_stiffness_z,
        p.torsional_stiffness, p.bending_stiffness_y, p.bending_stiffness_z, p.bending_stiffness_y,
        p.bending_stiffness_z;
    wd.segment<kGeneralisedPerPoint>(row) *= rule.weights[k] * p.length;
  }
  return a.transpose() * wd.asDiagonal() * a;
}

// Adds to `out` the force Σᵢ σᵢ ∇sᵢ and the stress part Σᵢ σᵢ ∇²sᵢ of the stiffness of strains
// sᵢ sampled at one point, given their energy conjugates σᵢ; returns the gradients ∇sᵢ with
// respect to e (columns) when the stiffness is asked for.
template <int kCount>
Eigen::Matrix<double, kBeamElementDofs, kCount> AddStressTerms(
    const BeamLocalMap& map, const std::array<StrainJet, kCount>& s, const double* sigma,
    const BeamForceOutputs& out) {
  BeamLocalVector g_u = BeamLocalVector::Zero();
  BeamLocalMatrix h_u = BeamLocalMatrix::Zero();
  Eigen::Matrix<double, kBeamElementDofs, kCount> grads =
      Eigen::Matrix<double, kBeamElementDofs, kCount>::Zero();
  for (int i = 0; i < kCount; ++i) {
    g_u += sigma[i] * s[i].grad;
    if (out.stiffness) {
      h_u += sigma[i] * s[i].hess;
      grads.col(i) = MapToNodal(map, s[i].grad);
    }
  }
  if (out.force) *out.force += MapToNodal(map, g_u);
  if (out.stiffness) AddMappedHessian(map, h_u, *out.stiffness);
  return grads;
}

// Strains with a diagonal stiffness at one point: U += ½ Σ kᵢ sᵢ², with the material part
// Σ kᵢ ∇sᵢ ∇sᵢᵀ of the stiffness.
template <int kCount>
double AddDiagonalTerms(const BeamLocalMap& map, const std::array<StrainJet, kCount>& s,
                        const std::array<double, kCount>& k, const BeamForceOutputs& out) {
  std::array<double, kCount> sigma;
  double energy = 0.0;
  for (int i = 0; i < kCount; ++i) {
    sigma[i] = k[i] * s[i].value;
    energy += 0.5 * sigma[i] * s[i].value;
  }
  const auto grads = AddStressTerms<kCount>(map, s, sigma.data(), out);
  if (out.stiffness)
    for (int i = 0; i < kCount; ++i)
      out.stiffness->noalias() += k[i] * grads.col(i) * grads.col(i).transpose();
  return energy;
}

// The strain energy and, as `out` asks, its gradient and Hessian.
double EvaluateBeam(const BeamElementParameters& p, const Vector24d& e,
                    const BeamForceOutputs& out) {
  if (out.force) out.force->setZero();
  if (out.stiffness) out.stiffness->setZero();
  const bool h = out.stiffness != nullptr;
  double energy = 0.0;

  const GaussRule& axial = GetGaussRule(kAxialPoints);
  for (int k = 0; k < axial.size; ++k) {
    const BeamLocalMap map = MakeBeamLocalMap(axial.points[k], p.length);
    energy += AddDiagonalTerms<1>(map, {AxialStrain(MapToLocal(map, e), h)},
                                  {axial.weights[k] * p.length * p.axial_stiffness}, out);
  }

  for (const double xi : {0.0, 1.0}) {
    const BeamLocalMap map = MakeBeamLocalMap(xi, p.length);
    const double w = 0.5 * p.length;
    energy += AddDiagonalTerms<3>(map, SectionPenaltyStrains(MapToLocal(map, e), h),
                                  {w * p.section_normal_stiffness, w * p.section_normal_stiffness,
                                   w * p.section_shear_stiffness},
                                  out);
  }

  const GaussRule& section = GetGaussRule(kSectionPoints);
  std::array<std::array<StrainJet, kRawPerPoint>, kSectionPoints> strains;
  std::array<BeamLocalMap, kSectionPoints> maps;
  RawVector raw;
  for (int k = 0; k < kSectionPoints; ++k) {
    maps[k] = MakeBeamLocalMap(section.points[k], p.length);
    strains[k] = SectionStrains(MapToLocal(maps[k], e), h);
    for (int i = 0; i < kRawPerPoint; ++i) raw[kRawPerPoint * k + i] = strains[k][i].value;
  }
  const RawMatrix c = SectionEnergyMatrix(p);
  const RawVector sigma = c * raw;
  Eigen::Matrix<double, kBeamElementDofs, kRawSize> grads;
  for (int k = 0; k < kSectionPoints; ++k) {
    const auto g =
        AddStressTerms<kRawPerPoint>(maps[k], strains[k], sigma.data() + kRawPerPoint * k, out);
    if (h) grads.middleCols<kRawPerPoint>(kRawPerPoint * k) = g;
  }
  if (h) out.stiffness->noalias() += grads * c * grads.transpose();
  return energy + 0.5 * raw.dot(sigma);
}

}  // namespace

void CalcBeamInternalForce(const BeamElementParameters& p, const Vector24d& e,
                           const BeamForceOutputs& out) {
  EvaluateBeam(p, e, out);
}

double CalcBeamStrainEnergy(const BeamElementParameters& p, const Vector24d& e) {
  return EvaluateBeam(p, e, {});
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
