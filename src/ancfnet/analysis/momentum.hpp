#pragma once
/// @file Linear and angular momentum of the whole system. For a cable element r = Σ_i S_i e_i
/// over its four blocks and M_e = M₄ ⊗ I₃ with (M₄)_ij = ∫ ρA S_i S_j, so, exactly,
///   p = ∫ ρA ṙ = Σ_j (M₄,₁j + M₄,₃j) ė_j   (S₁ + S₃ = 1),   L = ∫ ρA r × ṙ = Σ_ij (M₄)_ij e_i ×
///   ė_j;
/// point masses add m ṙ and m r × ṙ, rigid bodies m ẋ and m x × ẋ + R_WB J_B ω_B (with the
/// reference orientations in ws.body_rotation). A beam element's material points are
/// r + y d₂ + z d₃ with centroidal principal axes, so its sections add no linear momentum but
/// the angular momentum of their spin, ∫∫ ρ (y d₂ + z d₃) × (y ḋ₂ + z ḋ₃) dA dx =
/// ∫ (ρI_z d₂ × ḋ₂ + ρI_y d₃ × ḋ₃) dx = Σ_ij (M_rot)_ij e_i × ė_j over its eight blocks, with the
/// rotary mass matrix M_rot = Workspace::beam_rotary_mass (its centre line is a cable element).

#include "ancfnet/model/model.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// Linear momentum Σ ∫ ρA ṙ dx + Σ m ṙ (kg m/s).
Vector3d CalcLinearMomentum(const Model& model, const Workspace& ws, const VectorXd& v);

/// Angular momentum about the origin Σ ∫ ρA r × ṙ dx + Σ m r × ṙ (kg m²/s), with the spin of
/// beam sections and rigid bodies.
Vector3d CalcAngularMomentum(const Model& model, const Workspace& ws, const VectorXd& q,
                             const VectorXd& v);

}  // namespace ancfnet
