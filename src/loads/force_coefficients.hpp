// Non-dimensional force and moment coefficients, Reynolds and Froude numbers
// of a run, as naval architects and AUV modellers exchange them:
//   C_F = F / (1/2 rho U^2 A)        (X, Y, Z)
//   C_M = M / (1/2 rho U^2 A L)      (K, M, N)
//   Re = U L / nu,  Fn = U / sqrt(g L),  g = 9.80665 m/s^2 (standard gravity)
// U is the speed through the water, |(u, v, w)|; the coefficients keep the
// force's axes and sign (body axes, forces on the body). Nothing here
// guesses: each function takes what it needs, and a speed of zero has no
// coefficient (there is no dynamic pressure to divide by).
#pragma once

#include <array>

namespace hydrocoef {

/// Standard gravity [m/s^2] (CGPM 1901), the g of the Froude number.
inline constexpr double kStandardGravity = 9.80665;

/// The speed through the water |(u, v, w)| [m/s].
double speed_through_water(const std::array<double, 6>& nu_b);

/// 1/2 rho U^2 [Pa].
double dynamic_pressure(double density, double speed);

/// F / (1/2 rho U^2 A); NaN when U = 0.
double force_coefficient(double force, double density, double speed, double area);

/// M / (1/2 rho U^2 A L); NaN when U = 0.
double moment_coefficient(double moment, double density, double speed, double area, double length);

/// U L / nu.
double reynolds_number(double speed, double length, double kinematic_viscosity);

/// U / sqrt(g L).
double froude_number(double speed, double length, double gravity = kStandardGravity);

/// The moment about point p of a force system whose moment about point o is
/// moment_o and whose resultant is force: M_p = M_o + (o - p) x F. All in one
/// frame (body axes) [N m, N, m]. A term whose lever arm is zero adds
/// nothing, even when its force component is unknown (NaN): a point moved
/// along x needs only Y and Z.
std::array<double, 3> moment_about(const std::array<double, 3>& moment_o, const std::array<double, 3>& force,
                                   const std::array<double, 3>& o, const std::array<double, 3>& p);

}  // namespace hydrocoef
