#pragma once
/// @file Connection laws: the axial force of a connection (a net knot's thread end, a point-to-
/// point spring-damper) as a function of its elongation e and elongation rate ė,
///   T(e, ė) = T_s(e) + b(e) ė   (N, tension positive),
/// the nonlinear spring-damper K(δ) δ + b δ̇ of the seed paper (Ma et al., "Cable nodes and their
/// connecting dynamics attribute modeling"). One law object serves any point-to-point connection;
/// the vector form is in forces/spring_damper.hpp, the derivation in docs/theory-connections.md.
/// A law is built once (through the Make… factories, which validate it) and is then evaluated
/// without allocating.

#include <vector>

namespace ancfnet {

/// The spring part T_s(e) of a connection law.
enum class SpringKind {
  kLinear,           ///< T_s = k1 e
  kTensionOnly,      ///< T_s = k1 (e − g) for e > g, 0 for e ≤ g (a slack thread with a gap g)
  kPolynomial,       ///< T_s = k1 e + k3 e³ (hardening, k3 ≥ 0)
  kPiecewiseLinear,  ///< T_s interpolated linearly in a measured (elongation, force) table
};

/// The damping coefficient b(e) of a connection law.
enum class DampingKind {
  kConstant,               ///< b = b0 (N s/m)
  kStiffnessProportional,  ///< b = β max(dT_s/de, 0), β in s
};

/// One row of a measured force–elongation table.
struct ForceTablePoint {
  double elongation = 0.0;  ///< e (m)
  double force = 0.0;       ///< T_s(e) (N), tension positive
};

/// The spring part at one elongation.
struct SpringTerms {
  double force = 0.0;      ///< T_s(e) (N)
  double stiffness = 0.0;  ///< dT_s/de (N/m)
  double curvature = 0.0;  ///< d²T_s/de² (N/m²); 0 on piecewise-linear laws (kinks ignored)
};

/// The damping coefficient at one elongation.
struct DampingTerms {
  double coefficient = 0.0;      ///< b(e) (N s/m), ≥ 0
  double dcoefficient_de = 0.0;  ///< db/de (N s/m²)
};

/// The axial force and its partial derivatives.
struct ConnectionForce {
  double force = 0.0;         ///< T(e, ė) (N), tension positive
  double dforce_de = 0.0;     ///< ∂T/∂e = dT_s/de + (db/de) ė (N/m)
  double dforce_dedot = 0.0;  ///< ∂T/∂ė = b (N s/m)
};

/// A connection law T(e, ė) = T_s(e) + b(e) ė. Build it with the Make… factories and the
/// With…Damping decorators below, which validate the parameters; a law filled by hand should be
/// passed to ValidateConnectionLaw before use.
///
/// Tension-only laws transmit no compression: T = max(T_s + b ė, 0) while taut (e > g) and T = 0
/// while slack (e ≤ g), where damping acts neither (the rope law of the cable element,
/// docs/theory.md "Tension-only (rope) law"). Stiffness-proportional damping uses
/// b = β max(dT_s/de, 0): never negative, even on a falling segment of a measured table.
struct ConnectionLaw {
  SpringKind spring = SpringKind::kLinear;
  double k1 = 0.0;   ///< linear stiffness (N/m): kLinear, kTensionOnly, kPolynomial
  double k3 = 0.0;   ///< cubic coefficient (N/m³): kPolynomial
  double gap = 0.0;  ///< slack length g (m) before a tension-only law takes load
  /// kPiecewiseLinear: strictly increasing elongations, at least two rows.
  std::vector<ForceTablePoint> table;
  DampingKind damping = DampingKind::kConstant;
  /// b0 (N s/m) for kConstant, β (s) for kStiffnessProportional; ≥ 0.
  double damping_coefficient = 0.0;

  /// Spring part T_s(e) and its first two derivatives at elongation e (m). On a piecewise-linear
  /// law the slope at a table point is that of the segment to its right (of the last segment at
  /// the last point); outside the table the end segments extend linearly.
  SpringTerms CalcSpring(double e) const;

  /// Damping coefficient b(e) and db/de at elongation e (m).
  DampingTerms CalcDamping(double e) const;

  /// T(e, ė) (N) and its partial derivatives at elongation e (m) and rate ė (m/s).
  ConnectionForce Evaluate(double e, double e_dot) const;

  /// Stored energy U(e) = ∫₀ᵉ T_s(s) ds (J), in closed form (exact for the table too). For a
  /// table with T_s(0) ≠ 0 (a pretension at zero elongation) U is still measured from e = 0.
  double CalcEnergy(double e) const;
};

/// T_s = k1 e. Throws InputError unless 0 < k1 < ∞ (N/m).
ConnectionLaw MakeLinearLaw(double k1);

/// T_s = k1 (e − g) for e > g, else 0. Throws InputError unless 0 < k1 < ∞ (N/m) and
/// 0 ≤ gap < ∞ (m).
ConnectionLaw MakeTensionOnlyLaw(double k1, double gap);

/// T_s = k1 e + k3 e³. Throws InputError unless 0 < k1 < ∞ (N/m) and 0 ≤ k3 < ∞ (N/m³): a
/// softening cubic (k3 < 0) has negative stiffness for |e| > √(k1 / 3|k3|) and a force that
/// reverses beyond √(k1/|k3|), with energy unbounded below; give a measured softening curve as
/// a table over its measured range instead.
ConnectionLaw MakePolynomialLaw(double k1, double k3);

/// T_s interpolated linearly in `table` (elongation m, force N) as measured on a test rig, with
/// linear extrapolation by the end segments' slopes. Throws InputError unless the table has at
/// least two rows, all finite, with strictly increasing elongations. The table need not contain
/// (0, 0): a force at zero elongation is a pretension (and is rejected by a zero-length
/// spring-damper). A non-monotonic force is allowed (a knot that slips), but a falling segment
/// has negative tangent stiffness, which can make a static problem unstable there.
ConnectionLaw MakePiecewiseLinearLaw(const std::vector<ForceTablePoint>& table);

/// `law` with constant damping b = b0. Throws InputError unless 0 ≤ b0 < ∞ (N s/m).
ConnectionLaw WithConstantDamping(ConnectionLaw law, double b0);

/// `law` with damping proportional to its stiffness, b = β max(dT_s/de, 0) (Rayleigh-like:
/// each connection then damps with the time constant β). Throws InputError unless 0 ≤ β < ∞ (s).
ConnectionLaw WithStiffnessProportionalDamping(ConnectionLaw law, double beta);

/// Throws InputError, with a one-line message naming the parameter, unless every parameter that
/// `law`'s kinds use satisfies the conditions listed on the factories above.
void ValidateConnectionLaw(const ConnectionLaw& law);

}  // namespace ancfnet
