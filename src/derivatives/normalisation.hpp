// The non-dimensional systems naval architects exchange hydrodynamic
// derivatives in, and the conversions between them and SI, both ways.
//
// A system scales each kind of quantity by a product of reference values,
// the quantity's "unit" in that system: X' = X / (1/2 rho U^2 L^2) for a
// force in the prime system. A derivative such as Y_vr (the coefficient of
// v*r in Y) is scaled by its output's unit divided by the product of its
// variables' units to their powers, so that the term Y_vr v r has the unit of
// Y in every system. Three systems:
//
//   quantity               prime (SNAME 1950)   bis (Norrbin 1971)   MMG (Yasukawa and Yoshimura 2015)
//   force                  1/2 rho U^2 L^2      m g                  1/2 rho U^2 L d
//   moment                 1/2 rho U^2 L^3      m g L                1/2 rho U^2 L^2 d
//   linear velocity        U                    sqrt(L g)            U
//   angular velocity       U / L                sqrt(g / L)          U / L
//   linear acceleration    U^2 / L              g                    U^2 / L
//   angular acceleration   U^2 / L^2            g / L                U^2 / L^2
//   mass                   1/2 rho L^3          m                    1/2 rho L^2 d
//   moment of inertia      1/2 rho L^5          m L^2                1/2 rho L^4 d
//   length, position       L                    L                    L
//   time                   L / U                sqrt(L / g)          L / U
//   angle                  1                    1                    1
//
// L is the reference length (length between perpendiculars for a ship), U
// the reference speed, rho the water density, d the draft, g the
// acceleration of gravity and m the body's mass (for a floating ship the
// displaced mass rho * volume). Sources (Fossen's appendix D was not at hand;
// its factors are checked through the MSS toolbox files that apply it,
// github.com/cybergalactic/MSS, commit 6bca7942):
// - prime: Fossen (2021), Handbook of Marine Craft Hydrodynamics and Motion
//   Control, 2nd ed., appendix D. CRAFT/SHIP/models/clarke83.m: added mass
//   MA = 1/2 rho L^3 Tinv^2 (T MA' Tinv), damping N = 1/2 rho L^2 U Tinv^2
//   (T N' Tinv), T = diag(1, 1, 1/L); CRAFT/AUV/models/npsauv.m: "prime-
//   scaling variables (Fossen 2021, Appendix D.2)" 1/2 rho L^2 ... 1/2 rho L^5,
//   m' = m / (1/2 rho L^3); CRAFT/SHIP/models/mariner.m: u' = u/U, r' = r L/U,
//   linear accelerations X' (U^2/L) / m', angular ones times U^2/L^2.
// - bis: Norrbin (1971), SSPA Publication No. 68, as Fossen (2021) appendix D
//   lists it. CRAFT/SHIP/models/supply.m (the bis matrices of Fossen, Sagatun
//   and Sorensen 1996): M = m Tinv^2 (T M'' Tinv), D = m sqrt(g/L) Tinv^2
//   (T D'' Tinv). The bis mass unit is the body's mass m; for a floating ship
//   that is rho times the displaced volume, which is used when no mass is
//   given.
// - MMG: Yasukawa and Yoshimura (2015), "Introduction of MMG standard method
//   for ship maneuvering predictions", J. Mar. Sci. Technol. 20:37-52
//   (doi:10.1007/s00773-014-0293-y): X_H = 1/2 rho L d U^2 X_H'(v', r'),
//   N_H = 1/2 rho L^2 d U^2 N_H', v' = v/U, r' = r L/U, m_x = 1/2 rho L^2 d m_x',
//   J_z = 1/2 rho L^4 d J_z' (as github.com/nikpau/mmgdynamics, dynamics.py,
//   implements them). The accelerations and time follow from these (force /
//   mass, moment / inertia) and are the prime ones.
//
// Angles are radians in every system (unscaled). g defaults to the standard
// acceleration of gravity, 9.80665 m/s^2 (3rd CGPM, 1901); set it to the
// value a source used (MSS's supply.m uses 9.81).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef {

enum class NormalisationSystem {
  Prime,  ///< SNAME 1950 / ITTC: L, U, rho
  Bis,    ///< Norrbin 1971: L, g, m
  Mmg     ///< Yasukawa and Yoshimura 2015: L, d, U, rho
};

/// "prime", "bis" or "mmg": the name parse_normalisation_system reads.
std::string_view to_string(NormalisationSystem system);
/// The system and its source for people: "prime (SNAME 1950)", "bis (Norrbin
/// 1971)", "MMG (Yasukawa and Yoshimura 2015)".
std::string_view normalisation_system_title(NormalisationSystem system);
/// The reference values a system's units use, for help texts: "reference
/// length L, reference speed U, water density rho" for prime. A conversion
/// asks only for those its unit uses (a prime velocity needs U alone).
std::string_view normalisation_system_needs(NormalisationSystem system);
/// Parses "prime", "bis" or "mmg" (as to_string writes them, any case);
/// throws InputError naming the text and the accepted names otherwise.
NormalisationSystem parse_normalisation_system(std::string_view text);

/// The reference values the systems are built from, SI units. A value that
/// is not given is nullopt; a conversion that needs it throws InputError
/// naming it. Every given value must be finite and positive.
struct NormalisationReference {
  std::optional<double> length;            ///< L [m]: every system
  std::optional<double> speed;             ///< U [m/s]: prime, MMG
  std::optional<double> density;           ///< rho [kg/m^3]: prime, MMG (bis when m comes from the volume)
  std::optional<double> draft;             ///< d [m]: MMG
  std::optional<double> mass;              ///< m [kg]: bis; when absent, m = density * displaced_volume
  std::optional<double> displaced_volume;  ///< [m^3]: bis without a mass (m = rho * volume)
  double gravity = 9.80665;                ///< g [m/s^2]: bis; standard gravity unless set
};

/// The kinds of quantity a system scales (see the table in the file comment).
enum class QuantityKind {
  Force,                ///< N
  Moment,               ///< N m
  LinearVelocity,       ///< m/s: u, v, w
  AngularVelocity,      ///< rad/s: p, q, r
  LinearAcceleration,   ///< m/s^2
  AngularAcceleration,  ///< rad/s^2
  Mass,                 ///< kg: m, and added masses stated as masses
  Inertia,              ///< kg m^2: I_z, and added inertias stated as inertias
  Length,               ///< m: positions such as x_G
  Time,                 ///< s
  Angle                 ///< rad: control and disturbance angles (rudder delta, drift beta)
};

inline constexpr std::array kAllQuantityKinds{QuantityKind::Force,
                                              QuantityKind::Moment,
                                              QuantityKind::LinearVelocity,
                                              QuantityKind::AngularVelocity,
                                              QuantityKind::LinearAcceleration,
                                              QuantityKind::AngularAcceleration,
                                              QuantityKind::Mass,
                                              QuantityKind::Inertia,
                                              QuantityKind::Length,
                                              QuantityKind::Time,
                                              QuantityKind::Angle};
inline constexpr std::array kAllNormalisationSystems{NormalisationSystem::Prime, NormalisationSystem::Bis,
                                                     NormalisationSystem::Mmg};

/// "force", "linear velocity", ...
std::string_view to_string(QuantityKind quantity);

/// One variable of a derivative and its power: for Y_vvr the factors are
/// (linear velocity, 2) and (angular velocity, 1). |x| counts as x (power 1):
/// N_u|u| is (linear velocity, 2).
struct DerivativeFactor {
  QuantityKind variable = QuantityKind::LinearVelocity;
  int power = 1;  ///< 1 to kMaxDerivativePower
};
inline constexpr int kMaxDerivativePower = 16;

/// What a derivative is the coefficient of: output / product of factors. An
/// added-mass derivative Y_vdot is a force per linear acceleration; N_rdot a
/// moment per angular acceleration; a constant term (Y_0) has no factors.
struct DerivativeKind {
  QuantityKind output = QuantityKind::Force;
  std::vector<DerivativeFactor> factors;
};

/// "force / (linear velocity^2 * angular velocity)", "force" (no factors).
std::string describe(const DerivativeKind& kind);

/// The reference symbols a scale is a product of, in the order of
/// NormalisationScale::doubled_exponents and of scale_text.
enum class ReferenceSymbol { Density, Mass, Speed, Gravity, Length, Draft };
inline constexpr std::size_t kReferenceSymbolCount = 6;

/// A scale as a formula: (1/2)^one_half_power * rho^a m^b U^c g^e L^f d^h,
/// each exponent stored doubled (the bis system has square roots). Exact, so
/// that a derivative's scale is formed and printed without rounding, and so
/// that its SI dimension can be checked.
struct NormalisationScale {
  int one_half_power = 0;
  std::array<int, kReferenceSymbolCount> doubled_exponents{};  ///< indexed by ReferenceSymbol
  bool operator==(const NormalisationScale&) const = default;
};

/// The scale of a quantity in a system (the table in the file comment).
NormalisationScale quantity_scale(QuantityKind quantity, NormalisationSystem system);
/// The scale of a derivative: its output's scale divided by each factor's
/// scale to its power. Throws InputError for a power outside 1..kMaxDerivativePower.
NormalisationScale derivative_scale(const DerivativeKind& kind, NormalisationSystem system);

/// The formula as text: "1/2 rho U^2 L^2", "m sqrt(g/L)", "U / L", "1".
std::string scale_text(const NormalisationScale& scale);

/// The value of a scale in SI units for a reference. Throws InputError when
/// the reference lacks a value the scale uses (naming it, the system and how
/// to give it) or holds a value that is not finite and positive (naming the
/// field). `what` names the quantity in the message, e.g. "a force".
double scale_value(const NormalisationScale& scale, NormalisationSystem system, const NormalisationReference& reference,
                   std::string_view what);

/// Throws InputError naming the first given field that is not finite and
/// positive (every conversion checks this).
void check_normalisation_reference(const NormalisationReference& reference);

/// SI value from a non-dimensional one: value * scale.
double to_dimensional(double value, QuantityKind quantity, NormalisationSystem system,
                      const NormalisationReference& reference);
/// Non-dimensional value from an SI one: value / scale.
double to_nondimensional(double value, QuantityKind quantity, NormalisationSystem system,
                         const NormalisationReference& reference);
/// A derivative's SI value from its non-dimensional one (SI: the output's
/// unit per the product of the variables' units, e.g. N s^2 m^-2 for Y_v|v|).
double to_dimensional(double value, const DerivativeKind& kind, NormalisationSystem system,
                      const NormalisationReference& reference);
/// A derivative's non-dimensional value from its SI one.
double to_nondimensional(double value, const DerivativeKind& kind, NormalisationSystem system,
                         const NormalisationReference& reference);

/// A non-dimensional value in system `from` restated in system `to`, through
/// its dimensional value (both systems' references come from `reference`).
double convert_between_systems(double value, QuantityKind quantity, NormalisationSystem from, NormalisationSystem to,
                               const NormalisationReference& reference);
double convert_between_systems(double value, const DerivativeKind& kind, NormalisationSystem from,
                               NormalisationSystem to, const NormalisationReference& reference);

/// The normalisation named for an output, one line: the system, the
/// definition of the non-dimensional symbol and the reference values the
/// scale uses, e.g. "prime (SNAME 1950): X' = X / (1/2 rho U^2 L^2), L =
/// 160.93 m, U = 7.7175 m/s, rho = 1025 kg/m^3". `symbol` is the quantity's
/// name ("X", "Y_vr"); the bis system marks it with two primes (X''). Throws
/// as scale_value does when a value the scale uses is missing.
std::string normalisation_text(const NormalisationScale& scale, NormalisationSystem system,
                               const NormalisationReference& reference, std::string_view symbol);

}  // namespace hydrocoef
