#pragma once
/// @file The penalty stiffness the model gives a body attachment declared "fixed"
/// (ModelBuilder::AddBodyAttachment); the attachment's force is forces/body_attachment.hpp.

namespace ancfnet {

/// Penalty stiffness of a "fixed" attachment, k = max(m_eff (10/h)², 100 k_held):
/// - m_eff (10/h)²: the pair's relative vibration then has ω h ≥ 10, far above what the step
///   resolves, so generalised-α (ρ∞ < 1) and the default critical damping 2 √(k m_eff) remove
///   it, while a load F opens the joint only by F h² / (100 m_eff);
/// - 100 k_held: at least a hundred times the stiffness k_held of what holds the point (EA/L_e of
///   a cable point's element), so that in series with it the attachment adds at most 1 % of one
///   element's compliance. Without it a stiff rope of light elements was softer by up to a third
///   (docs/theory.md, "Body attachments").
/// m_eff (kg) is the reduced mass of the point and the body (the point's alone on a fixed or
/// prescribed body; half its element's mass for a cable point), h (s) the time step, k_held (N/m)
/// ≥ 0 (0 for a point mass).
double CalcFixedAttachmentStiffness(double reduced_mass, double time_step, double held_stiffness);

}  // namespace ancfnet
