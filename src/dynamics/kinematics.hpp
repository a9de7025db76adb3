// Attitude kinematics with unit quaternions (Fossen 2011, section 2.2.2):
// no gimbal lock in the state; Euler angles only for output and input files.
//
// A quaternion q_nb = (eta, eps1, eps2, eps3) (scalar first) rotates body
// axes b into the NED frame n: v_n = R(q_nb) v_b. Euler angles are the zyx
// convention (phi roll, theta pitch, psi yaw, rad): R = Rz(psi) Ry(theta) Rx(phi).
#pragma once

#include <Eigen/Core>

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
/// = (e^2 + x^2 - y^2 - z^2) / q^T q). The dynamics model's hot path.
inline Matrix3 rotation_body_to_ned_any_norm(const Quaternion4& q) {
  const double e = q[0], x = q[1], y = q[2], z = q[3];
  const double s = 2.0 / (e * e + x * x + y * y + z * z);
  Matrix3 r;
  r << 1.0 - s * (y * y + z * z), s * (x * y - z * e), s * (x * z + y * e),  //
      s * (x * y + z * e), 1.0 - s * (x * x + z * z), s * (y * z - x * e),   //
      s * (x * z - y * e), s * (y * z + x * e), 1.0 - s * (x * x + y * y);
  return r;
}

/// Fossen eq. 2.82 with the normalisation feedback of eq. 2.93:
///   q' = 1/2 T(q) omega_b + gain/2 (1 - q^T q) q,
/// omega_b = (p, q, r) [rad/s]. The feedback term (gain [1/s], >= 0) pulls a
/// drifting norm back to 1 without changing the rotation; with gain 0 this is
/// the plain kinematic equation. Pointers to the 4 numbers of q and q' and
/// the 3 of omega_b (the integrators' hot path, element by element).
inline void quaternion_rate(const double* q, const double* omega_b, double gain, double* q_dot) {
  const double e = q[0], x = q[1], y = q[2], z = q[3];
  const double p = omega_b[0], qq = omega_b[1], r = omega_b[2];
  const double k = 0.5 * gain * (1.0 - (e * e + x * x + y * y + z * z));
  q_dot[0] = 0.5 * (-x * p - y * qq - z * r) + k * e;
  q_dot[1] = 0.5 * (e * p - z * qq + y * r) + k * x;
  q_dot[2] = 0.5 * (z * p + e * qq - x * r) + k * y;
  q_dot[3] = 0.5 * (-y * p + x * qq + e * r) + k * z;
}
/// The same for Eigen vectors.
inline Quaternion4 quaternion_rate(const Quaternion4& q, const Vector3& omega_b, double gain) {
  Quaternion4 q_dot;
  quaternion_rate(q.data(), omega_b.data(), gain, q_dot.data());
  return q_dot;
}

/// zyx Euler angles (phi, theta, psi) [rad] of a (normalised) quaternion; phi
/// and psi in (-pi, pi], theta in [-pi/2, pi/2].
Vector3 euler_from_quaternion(const Quaternion4& q);

/// The unit quaternion of zyx Euler angles (phi, theta, psi) [rad], with eta >= 0.
Quaternion4 quaternion_from_euler(const Vector3& euler_rad);

}  // namespace hydrocoef
