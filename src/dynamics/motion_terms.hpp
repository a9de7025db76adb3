// The rigid-body arithmetic of the equations of motion (vehicle_model.hpp),
// written once over a number type T: double for one vehicle, Lanes for
// kLanes vehicles that differ only in their damping (the drawn models of an
// ensemble), integrated in lock-step so that each operation serves every lane
// (SIMD) and the lanes' independent chains of operations overlap.
//
// Element by element over plain arrays: the integrators' hot path, where
// Eigen's 3-element halves of 6-vectors and 4-element segments of the 13-
// element state made the compiler store and reload sums in pieces. Each lane
// does exactly the operations of the scalar code, in the same order, so a
// lane's numbers are the single vehicle's.
//
// Frames and signs as in vehicle_model.hpp: body axes, forces on the body.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <type_traits>

namespace hydrocoef::motion {

/// Number of vehicles integrated in lock-step.
inline constexpr int kLanes = 8;
/// One number per lane.
using Lanes = Eigen::Array<double, kLanes, 1>;

/// v in every lane of T.
template <class T>
inline T splat(double v) {
  if constexpr (std::is_same_v<T, double>)
    return v;
  else
    return T::Constant(v);
}

/// The terms of the equation of motion at one state (vehicle_model.hpp's
/// ForceBreakdown without the control force), each a generalized force on
/// the body [N, N m], and the rotation they were computed with.
template <class T>
struct Terms {
  T rotation[9];     ///< body to NED, row-major
  T nu_r[6];         ///< velocity relative to the water
  T hydrostatic[6];  ///< -g(eta)
  T damping[6];      ///< -D(nu_r) nu_r
  T coriolis[6];     ///< -C_RB(nu) nu - C_A(nu_r) nu_r + M_A nu_c'
};

/// Body-to-NED rotation R (row-major, 9 numbers) of the quaternion q =
/// (eta, eps1, eps2, eps3) of any non-zero norm: the rotation of q / |q|
/// (kinematics.hpp, rotation_body_to_ned_any_norm).
template <class T>
inline void rotation_any_norm(const T* q, T* r) {
  const T e = q[0], x = q[1], y = q[2], z = q[3];
  const T s = 2.0 / (e * e + x * x + y * y + z * z);
  r[0] = 1.0 - s * (y * y + z * z);
  r[1] = s * (x * y - z * e);
  r[2] = s * (x * z + y * e);
  r[3] = s * (x * y + z * e);
  r[4] = 1.0 - s * (x * x + z * z);
  r[5] = s * (y * z - x * e);
  r[6] = s * (x * z - y * e);
  r[7] = s * (y * z + x * e);
  r[8] = 1.0 - s * (x * x + y * y);
}

/// out = R v (3 numbers each; R row-major).
template <class T>
inline void rotate(const T* r, const T* v, T* out) {
  for (int i = 0; i < 3; ++i) out[i] = r[3 * i] * v[0] + r[3 * i + 1] * v[1] + r[3 * i + 2] * v[2];
}

/// out = R^T v.
template <class T>
inline void rotate_back(const T* r, const T* v, T* out) {
  for (int i = 0; i < 3; ++i) out[i] = r[i] * v[0] + r[3 + i] * v[1] + r[6 + i] * v[2];
}

/// out (6) = A v (6).
template <class T>
inline void multiply(const Eigen::Matrix<double, 6, 6>& a, const T* v, T* out) {
  for (int i = 0; i < 6; ++i) {
    T sum = a(i, 0) * v[0];
    for (int j = 1; j < 6; ++j) sum += a(i, j) * v[j];
    out[i] = sum;
  }
}

/// out (6) = A (v, 0, 0, 0) for v (3): multiply() of a vector whose angular
/// part is zero, without the three columns that multiply zeros (the same
/// numbers, but for the sign of a zero sum).
template <class T>
inline void multiply_linear(const Eigen::Matrix<double, 6, 6>& a, const T* v, T* out) {
  for (int i = 0; i < 6; ++i) out[i] = (a(i, 0) * v[0] + a(i, 1) * v[1]) + a(i, 2) * v[2];
}

/// tau (6) += -g(eta): weight W [N] down at the CG r_g, buoyancy B [N] up at
/// the CB r_b (body axes [m]), with the NED down direction in body axes read
/// from the third row of R: (W + B, r_g x W + r_b x B).
template <class T>
inline void add_hydrostatic(const T* r, double weight_N, double buoyancy_N, const double* r_g, const double* r_b,
                            T* tau) {
  const T wx = weight_N * r[6], wy = weight_N * r[7], wz = weight_N * r[8];
  const T bx = -buoyancy_N * r[6], by = -buoyancy_N * r[7], bz = -buoyancy_N * r[8];
  tau[0] += wx + bx;
  tau[1] += wy + by;
  tau[2] += wz + bz;
  tau[3] += (r_g[1] * wz - r_g[2] * wy) + (r_b[1] * bz - r_b[2] * by);
  tau[4] += (r_g[2] * wx - r_g[0] * wz) + (r_b[2] * bx - r_b[0] * bz);
  tau[5] += (r_g[0] * wy - r_g[1] * wx) + (r_b[0] * by - r_b[1] * bx);
}

/// out (6) -= C(nu) nu for a symmetric mass matrix M, without forming C
/// (rigid_body.hpp): with (a, b) = M nu, C(nu) nu = (-a x nu2, -a x nu1 - b x nu2).
template <class T>
inline void subtract_coriolis(const Eigen::Matrix<double, 6, 6>& mass, const T* nu, T* out) {
  T m[6];
  multiply(mass, nu, m);
  out[0] -= m[2] * nu[4] - m[1] * nu[5];
  out[1] -= m[0] * nu[5] - m[2] * nu[3];
  out[2] -= m[1] * nu[3] - m[0] * nu[4];
  out[3] -= (m[2] * nu[1] - m[1] * nu[2]) + (m[5] * nu[4] - m[4] * nu[5]);
  out[4] -= (m[0] * nu[2] - m[2] * nu[0]) + (m[3] * nu[5] - m[5] * nu[3]);
  out[5] -= (m[1] * nu[0] - m[0] * nu[1]) + (m[4] * nu[3] - m[3] * nu[4]);
}

/// q (4) /= |q|: the attitude projected back onto the unit sphere.
template <class T>
inline void normalize(T* q) {
  const T squared = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  T norm;
  if constexpr (std::is_same_v<T, double>)
    norm = std::sqrt(squared);
  else
    norm = squared.sqrt();
  for (int i = 0; i < 4; ++i) q[i] /= norm;
}

/// Fossen eq. 2.82 with the norm feedback of eq. 2.93 (kinematics.hpp):
/// q' (4) = 1/2 T(q) omega_b + gain/2 (1 - q^T q) q.
template <class T>
inline void quaternion_rate(const T* q, const T* omega_b, double gain, T* q_dot) {
  const T e = q[0], x = q[1], y = q[2], z = q[3];
  const T p = omega_b[0], qq = omega_b[1], r = omega_b[2];
  const T k = 0.5 * gain * (1.0 - (e * e + x * x + y * y + z * z));
  q_dot[0] = 0.5 * (-x * p - y * qq - z * r) + k * e;
  q_dot[1] = 0.5 * (e * p - z * qq + y * r) + k * x;
  q_dot[2] = 0.5 * (z * p + e * qq - x * r) + k * y;
  q_dot[3] = 0.5 * (-y * p + x * qq + e * r) + k * z;
}

}  // namespace hydrocoef::motion
