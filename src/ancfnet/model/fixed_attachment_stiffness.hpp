#pragma once
/// @file The penalty stiffness the model gives a body attachment declared "fixed"
/// (ModelBuilder::AddBodyAttachment); the attachment's force is forces/body_attachment.hpp.

namespace ancfnet {

/// Penalty stiffness of a "fixed" attachment, k = m_eff (10/h)²: the pair's relative vibration
/// then has ω h = 10, far above what the step resolves, so generalised-α (ρ∞ < 1) and the default
/// critical damping 2 √(k m_eff) remove it, while a load F opens the joint only by
/// F h² / (100 m_eff). m_eff (kg) is the reduced mass of the point and the body (the point's alone
/// on a fixed or prescribed body; half its element's mass for a cable point), h (s) the time step.
double CalcFixedAttachmentStiffness(double reduced_mass, double time_step);

}  // namespace ancfnet
