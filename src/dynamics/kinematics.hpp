// Attitude kinematics with unit quaternions (Fossen 2011, section 2.2.2):
// no gimbal lock in the state; Euler angles only for output and input files.
//
// A quaternion q_nb = (eta, eps1, eps2, eps3) (scalar first) rotates body
// axes b into the NED frame n: v_n = R(q_nb) v_b. Euler angles are the zyx
// convention (phi roll, theta pitch, psi yaw, rad): R = Rz(psi) Ry(theta) Rx(phi).
#pragma once

#include <Eigen/Core>

#include "src/dynamics/motion_terms.hpp"
#include "src/dynamics/rigid_body.hpp"

namespace hydrocoef {

using Quaternion4 = Eigen::Vector4d;  ///< (eta, eps1, eps2, eps3), scalar first

/// Fossen eq. 2.72: the rotation matrix R(q) from body to NED. q is used as
/// given: normalise it first if it may have drifted.
inline Matrix3 rotation_body_to_ned(const Quaternion4& q) {
  const double e = q[0], x = q[1], y = q[2], z = q[3];
  Matrix3 r;
  r << 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * e), 2.0 * (x * z + y * e),  //
      2.0 * (x * y + z * e), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * e),   //
      2.0 * (x * z - y * e), 2.0 * (y * z + x * e), 1.0 - 2.0 * (x * x + y * y);
  return r;
}

/// The rotation of q / |q| for any nonzero q, without a square root: the
/// homogeneous form of the formula above, 2 replaced by 2 / (q^T q), which
/// is exact because every entry is quadratic in q (1 - 2 (y^2 + z^2) / q^T q
/// = (e^2 + x^2 - y^2 - z^2) / q^T q). (motion::rotation_any_norm is the
/// dynamics model's element-by-element form.)
inline Matrix3 rotation_body_to_ned_any_norm(const Quaternion4& q) {
  double r[9];
  motion::rotation_any_norm(q.data(), r);
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r);
}

/// Fossen eq. 2.82 with the normalisation feedback of eq. 2.93:
///   q' = 1/2 T(q) omega_b + gain/2 (1 - q^T q) q,
/// omega_b = (p, q, r) [rad/s]. The feedback term (gain [1/s], >= 0) pulls a
/// drifting norm back to 1 without changing the rotation; with gain 0 this is
/// the plain kinematic equation.
inline Quaternion4 quaternion_rate(const Quaternion4& q, const Vector3& omega_b, double gain) {
  Quaternion4 q_dot;
  motion::quaternion_rate(q.data(), omega_b.data(), gain, q_dot.data());
  return q_dot;
}

/// q / |q|: an attitude projected back onto the unit sphere, in the shared
/// kernel's order of operations (hc_motion_normalize), which the runtime
/// library and the vehicle FMU use too: every normalised attitude hydrocoef
/// states (the initial state, the samples, the equilibrium's) is this one.
inline Quaternion4 unit_attitude(Quaternion4 q) {
  motion::kernel::hc_motion_normalize(q.data());
  return q;
}

/// zyx Euler angles (phi, theta, psi) [rad] of a (normalised) quaternion; phi
/// and psi in (-pi, pi], theta in [-pi/2, pi/2].
Vector3 euler_from_quaternion(const Quaternion4& q);

/// The unit quaternion of zyx Euler angles (phi, theta, psi) [rad], with eta >= 0.
Quaternion4 quaternion_from_euler(const Vector3& euler_rad);

}  // namespace hydrocoef
