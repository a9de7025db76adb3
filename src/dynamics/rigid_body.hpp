// Rigid-body and added-mass inertia of a marine vehicle in body axes, and the
// Coriolis–centripetal forces they imply (Fossen 2011, "Handbook of Marine
// Craft Hydrodynamics and Motion Control", sections 3.3 and 6.3).
//
// Frames and units: body axes b after SNAME (x forward, y starboard, z down),
// origin CO at the vehicle's reference point (for the ASR-V the centre of the
// sphere); nu_b = (u, v, w [m/s], p, q, r [rad/s]); generalized forces
// (X, Y, Z [N], K, M, N [N m]) about CO; masses in kg, inertia in kg m^2.
//
// Every Coriolis–centripetal matrix here comes from one formula in the mass
// matrix M (Fossen eq. 3.46 and 6.43, Theorem 3.2): with M = [M11 M12; M21 M22]
// (3x3 blocks) and nu = (nu1, nu2),
//   C(nu) = [ 0                       -S(M11 nu1 + M12 nu2) ]
//           [ -S(M11 nu1 + M12 nu2)   -S(M21 nu1 + M22 nu2) ],
// which is skew-symmetric for every nu, so nu^T C(nu) nu = 0: C does no work
// and the kinetic energy 1/2 nu^T M nu of an unforced body is conserved.
// Applied to M_RB it gives C_RB (eq. 3.56-3.57, with the lever arm r_g inside
// M_RB's off-diagonal blocks); applied to the added mass M_A it gives C_A
// (eq. 6.43).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>

#include "src/core/matrix6.hpp"
#include "src/dynamics/motion_terms.hpp"

namespace hydrocoef {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

/// The cross-product matrix: skew(a) * b == a.cross(b).
Matrix3 skew(const Vector3& a);

/// Fossen eq. 3.44: the rigid-body mass matrix about CO,
///   M_RB = [ m I3        -m S(r_g) ]
///          [ m S(r_g)    I_o       ],  I_o = I_g - m S(r_g)^2 (parallel axes).
/// mass_kg: m > 0; inertia_cg_b: the inertia tensor about the centre of gravity
/// in body axes [kg m^2] (symmetric); r_g_b: CG position from CO [m].
Matrix6 rigid_body_mass_matrix(double mass_kg, const Matrix3& inertia_cg_b, const Vector3& r_g_b);

/// The added mass of a sphere about its centre, as the positive matrix
/// M_A = -diag(X_udot, Y_vdot, Z_wdot, K_pdot, M_qdot, N_rdot):
///   rho_kg_m3:      density of the fluid [kg/m^3], finite and > 0;
///   radius_m:       radius of the sphere [m], finite and > 0;
///   rotation_kg_m2: the rotational entries (-K_pdot, -M_qdot, -N_rdot)
///                   [kg m^2] as given; none by default.
/// In each translation it is half the displaced fluid mass, (2/3) pi rho R^3
/// [kg] (an unbounded ideal fluid). Potential flow gives a sphere no
/// rotational added mass (it displaces no fluid when it turns about its
/// centre), so without rotation_kg_m2 M_A is singular in p, q, r; give
/// entries from experiment or CFD when a consumer needs them. Throws
/// InputError for a radius or density that is not finite and > 0.
Matrix6 sphere_added_mass(double rho_kg_m3, double radius_m,
                          const std::optional<Vector3>& rotation_kg_m2 = std::nullopt);

/// C(nu) of the file comment for a symmetric mass matrix M (M_RB, M_A or their sum).
Matrix6 coriolis_matrix(const Matrix6& mass, const Vector6& nu_b);

/// C(nu) nu without forming C: the Coriolis–centripetal term of the equations
/// of motion M nu' + C(nu) nu = tau, with a = M11 nu1 + M12 nu2 and
/// b = M21 nu1 + M22 nu2:  C(nu) nu = ( -a x nu2,  -a x nu1 - b x nu2 ).
inline Vector6 coriolis_force(const Matrix6& mass, const Vector6& nu_b) {
  Vector6 minus = Vector6::Zero();
  motion::subtract_coriolis(mass, nu_b.data(), minus.data());
  return -minus;
}

/// True when `matrix` is symmetric to `relative_tolerance` of its largest
/// entry and positive definite (Cholesky succeeds with positive pivots).
bool symmetric_positive_definite(const Matrix6& matrix, double relative_tolerance = 1e-9);

}  // namespace hydrocoef
