// The rigid-body arithmetic of the equations of motion (vehicle_model.hpp),
// written once over a number type T: double for one vehicle, Lanes for
// kLanes vehicles that differ only in their damping (the drawn models of an
// ensemble), integrated in lock-step so that each operation serves every lane
// (SIMD) and the lanes' independent chains of operations overlap.
//
// The arithmetic itself is runtime/src/motion_kernel.h, the one source that
// libhydrocoef_runtime (C11) compiles too: included here for double and for
// Lanes (its number type and its two operations given as macros), so that
// the C runtime's vehicle derivative is the library's bit for bit. The
// templates below name those functions as the library calls them.
//
// Element by element over plain arrays: the integrators' hot path, where
// Eigen's 3-element halves of 6-vectors and 4-element segments of the 13-
// element state made the compiler store and reload sums in pieces. Each lane
// does exactly the operations of the scalar code, in the same order, so a
// lane's numbers are the single vehicle's.
//
// Frames and signs as in vehicle_model.hpp: body axes, forces on the body.
#pragma once

#include <math.h>
#include <Eigen/Core>
#include <cmath>
#include <type_traits>

namespace hydrocoef::motion {

/// Number of vehicles integrated in lock-step.
inline constexpr int kLanes = 8;
/// One number per lane.
using Lanes = Eigen::Array<double, kLanes, 1>;

/// The shared kernel's functions, overloaded for double and Lanes.
namespace kernel {
#define HC_MOTION_T double
#define HC_MOTION_SPLAT(v) (v)
#define HC_MOTION_SQRT(x) std::sqrt(x)
#include "runtime/src/motion_kernel.h"
#define HC_MOTION_T ::hydrocoef::motion::Lanes
#define HC_MOTION_SPLAT(v) ::hydrocoef::motion::Lanes::Constant(v)
#define HC_MOTION_SQRT(x) (x).sqrt()
#include "runtime/src/motion_kernel.h"
}  // namespace kernel

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
  T current_b[3];    ///< the current in body axes (when there is one)
};

/// Body-to-NED rotation R (row-major, 9 numbers) of the quaternion q =
/// (eta, eps1, eps2, eps3) of any non-zero norm: the rotation of q / |q|
/// (kinematics.hpp, rotation_body_to_ned_any_norm).
template <class T>
inline void rotation_any_norm(const T* q, T* r) {
  kernel::hc_motion_rotation_any_norm(q, r);
}

/// out = R v (3 numbers each; R row-major).
template <class T>
inline void rotate(const T* r, const T* v, T* out) {
  kernel::hc_motion_rotate(r, v, out);
}

/// out = R^T v.
template <class T>
inline void rotate_back(const T* r, const T* v, T* out) {
  kernel::hc_motion_rotate_back(r, v, out);
}

/// out (6) = A v (6).
template <class T>
inline void multiply(const Eigen::Matrix<double, 6, 6>& a, const T* v, T* out) {
  kernel::hc_motion_multiply(a.data(), v, out);
}

/// out (6) = A (v, 0, 0, 0) for v (3): multiply() of a vector whose angular
/// part is zero, without the three columns that multiply zeros (the same
/// numbers, but for the sign of a zero sum).
template <class T>
inline void multiply_linear(const Eigen::Matrix<double, 6, 6>& a, const T* v, T* out) {
  kernel::hc_motion_multiply_linear(a.data(), v, out);
}

/// tau (6) += -g(eta): weight W [N] down at the CG r_g, buoyancy B [N] up at
/// the CB r_b (body axes [m]), with the NED down direction in body axes read
/// from the third row of R: (W + B, r_g x W + r_b x B).
template <class T>
inline void add_hydrostatic(const T* r, double weight_N, double buoyancy_N, const double* r_g, const double* r_b,
                            T* tau) {
  kernel::hc_motion_add_hydrostatic(r, weight_N, buoyancy_N, r_g, r_b, tau);
}

/// out (6) -= C(nu) nu for a symmetric mass matrix M, without forming C
/// (rigid_body.hpp): with (a, b) = M nu, C(nu) nu = (-a x nu2, -a x nu1 - b x nu2).
template <class T>
inline void subtract_coriolis(const Eigen::Matrix<double, 6, 6>& mass, const T* nu, T* out) {
  kernel::hc_motion_subtract_coriolis(mass.data(), nu, out);
}

/// q (4) /= |q|: the attitude projected back onto the unit sphere.
template <class T>
inline void normalize(T* q) {
  kernel::hc_motion_normalize(q);
}

/// Fossen eq. 2.82 with the norm feedback of eq. 2.93 (kinematics.hpp):
/// q' (4) = 1/2 T(q) omega_b + gain/2 (1 - q^T q) q.
template <class T>
inline void quaternion_rate(const T* q, const T* omega_b, double gain, T* q_dot) {
  kernel::hc_motion_quaternion_rate(q, omega_b, gain, q_dot);
}

}  // namespace hydrocoef::motion
