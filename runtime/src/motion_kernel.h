/* The rigid-body arithmetic of the 6-DOF equations of motion (Fossen 2011,
 * eq. 6.1 with current, section 10.3), ONE source for the C++ library
 * (src/dynamics/motion_terms.hpp, VehicleModel) and libhydrocoef_runtime
 * (runtime_vehicle.c): the rotation of a quaternion, the hydrostatic force,
 * the Coriolis terms without forming C, the mass-matrix products, the
 * quaternion rate with its norm feedback, and the order in which a
 * derivative puts them together.
 *
 * Written in the common subset of C11 and C++20 over a number type
 * HC_MOTION_T with two operations, HC_MOTION_SPLAT(v) (a double in every
 * lane) and HC_MOTION_SQRT(x). C includes this file once, for double (the
 * defaults below); the C++ library includes it twice, for double and for 8
 * lanes of an Eigen array (the vehicles of a Monte Carlo ensemble, each lane
 * doing exactly the scalar operations in the same order). Both compile with
 * -ffp-contract=off, so the three give the same numbers bit for bit.
 *
 * No include guard: each inclusion defines the functions for the current
 * HC_MOTION_T (overloads in C++), then undefines the macros it was given.
 *
 * Frames and signs: body axes x forward, y starboard, z down; NED; forces
 * and moments on the body [N, N m]. A 6x6 matrix is 36 doubles column by
 * column (Eigen's order): element (i, j) at [i + 6 j]. A state is 13
 * numbers: position in NED [m] (3), the body-to-NED quaternion, scalar first
 * (4), the body velocity over ground u, v, w [m/s], p, q, r [rad/s] (6). */

#ifndef HC_MOTION_T
#include <math.h>
#define HC_MOTION_T double
#define HC_MOTION_SPLAT(v) (v)
#define HC_MOTION_SQRT(x) sqrt(x)
#endif

#ifndef HC_MOTION_ONCE
#define HC_MOTION_ONCE
/* A current smaller than this in every NED component is none (Eigen's
 * isZero, which the model used before: |c| <= 1e-12). */
#define HC_MOTION_ZERO_CURRENT 1e-12
static inline int hc_motion_current_is_zero(const double* current_n) {
  return fabs(current_n[0]) <= HC_MOTION_ZERO_CURRENT && fabs(current_n[1]) <= HC_MOTION_ZERO_CURRENT &&
         fabs(current_n[2]) <= HC_MOTION_ZERO_CURRENT;
}
#endif

/* Body-to-NED rotation R (row-major, 9 numbers) of the quaternion q =
 * (eta, eps1, eps2, eps3) of any non-zero norm: the rotation of q / |q|. */
static inline void hc_motion_rotation_any_norm(const HC_MOTION_T* q, HC_MOTION_T* r) {
  const HC_MOTION_T e = q[0], x = q[1], y = q[2], z = q[3];
  const HC_MOTION_T s = 2.0 / (e * e + x * x + y * y + z * z);
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

/* out = R v (3 numbers each; R row-major). */
static inline void hc_motion_rotate(const HC_MOTION_T* r, const HC_MOTION_T* v, HC_MOTION_T* out) {
  for (int i = 0; i < 3; ++i) out[i] = r[3 * i] * v[0] + r[3 * i + 1] * v[1] + r[3 * i + 2] * v[2];
}

/* out = R^T v. */
static inline void hc_motion_rotate_back(const HC_MOTION_T* r, const HC_MOTION_T* v, HC_MOTION_T* out) {
  for (int i = 0; i < 3; ++i) out[i] = r[i] * v[0] + r[3 + i] * v[1] + r[6 + i] * v[2];
}

/* out (6) = A v (6), A column by column. */
static inline void hc_motion_multiply(const double* a, const HC_MOTION_T* v, HC_MOTION_T* out) {
  for (int i = 0; i < 6; ++i) {
    HC_MOTION_T sum = a[i] * v[0];
    for (int j = 1; j < 6; ++j) sum += a[i + 6 * j] * v[j];
    out[i] = sum;
  }
}

/* out (6) = A (v, 0, 0, 0) for v (3): hc_motion_multiply of a vector whose
 * angular part is zero, without the three columns that multiply zeros (the
 * same numbers, but for the sign of a zero sum). */
static inline void hc_motion_multiply_linear(const double* a, const HC_MOTION_T* v, HC_MOTION_T* out) {
  for (int i = 0; i < 6; ++i) out[i] = (a[i] * v[0] + a[i + 6] * v[1]) + a[i + 12] * v[2];
}

/* tau (6) += -g(eta): weight W [N] down at the CG r_g, buoyancy B [N] up at
 * the CB r_b (body axes [m]), with the NED down direction in body axes read
 * from the third row of R: (W + B, r_g x W + r_b x B). */
static inline void hc_motion_add_hydrostatic(const HC_MOTION_T* r, double weight_N, double buoyancy_N,
                                             const double* r_g, const double* r_b, HC_MOTION_T* tau) {
  const HC_MOTION_T wx = weight_N * r[6], wy = weight_N * r[7], wz = weight_N * r[8];
  const HC_MOTION_T bx = -buoyancy_N * r[6], by = -buoyancy_N * r[7], bz = -buoyancy_N * r[8];
  tau[0] += wx + bx;
  tau[1] += wy + by;
  tau[2] += wz + bz;
  tau[3] += (r_g[1] * wz - r_g[2] * wy) + (r_b[1] * bz - r_b[2] * by);
  tau[4] += (r_g[2] * wx - r_g[0] * wz) + (r_b[2] * bx - r_b[0] * bz);
  tau[5] += (r_g[0] * wy - r_g[1] * wx) + (r_b[0] * by - r_b[1] * bx);
}

/* out (6) -= C(nu) nu for a symmetric mass matrix M, without forming C: with
 * (a, b) = M nu, C(nu) nu = (-a x nu2, -a x nu1 - b x nu2). */
static inline void hc_motion_subtract_coriolis(const double* mass, const HC_MOTION_T* nu, HC_MOTION_T* out) {
  HC_MOTION_T m[6];
  hc_motion_multiply(mass, nu, m);
  out[0] -= m[2] * nu[4] - m[1] * nu[5];
  out[1] -= m[0] * nu[5] - m[2] * nu[3];
  out[2] -= m[1] * nu[3] - m[0] * nu[4];
  out[3] -= (m[2] * nu[1] - m[1] * nu[2]) + (m[5] * nu[4] - m[4] * nu[5]);
  out[4] -= (m[0] * nu[2] - m[2] * nu[0]) + (m[3] * nu[5] - m[5] * nu[3]);
  out[5] -= (m[1] * nu[0] - m[0] * nu[1]) + (m[4] * nu[3] - m[3] * nu[4]);
}

/* q (4) /= |q|: the attitude projected back onto the unit sphere. */
static inline void hc_motion_normalize(HC_MOTION_T* q) {
  const HC_MOTION_T squared = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  const HC_MOTION_T norm = HC_MOTION_SQRT(squared);
  for (int i = 0; i < 4; ++i) q[i] /= norm;
}

/* Fossen eq. 2.82 with the norm feedback of eq. 2.93:
 * q' (4) = 1/2 T(q) omega_b + gain/2 (1 - q^T q) q. */
static inline void hc_motion_quaternion_rate(const HC_MOTION_T* q, const HC_MOTION_T* omega_b, double gain,
                                             HC_MOTION_T* q_dot) {
  const HC_MOTION_T e = q[0], x = q[1], y = q[2], z = q[3];
  const HC_MOTION_T p = omega_b[0], qq = omega_b[1], r = omega_b[2];
  const HC_MOTION_T k = 0.5 * gain * (1.0 - (e * e + x * x + y * y + z * z));
  q_dot[0] = 0.5 * (-x * p - y * qq - z * r) + k * e;
  q_dot[1] = 0.5 * (e * p - z * qq + y * r) + k * x;
  q_dot[2] = 0.5 * (z * p + e * qq - x * r) + k * y;
  q_dot[3] = 0.5 * (-y * p + x * qq + e * r) + k * z;
}

/* The derivative, part 1 of 3, at state x (13): the rotation R (9), the
 * velocity relative to the water nu_r (6), the hydrostatic force (6) and
 * zeros in damping (6) and coriolis (6); current_b (3) the current in body
 * axes R^T v_c when current_n (NED [m/s], 3) is not zero. Returns 1 when
 * there is a current, 0 when nu_r = nu. The caller then adds the damping
 * force at nu_r to damping, and calls hc_motion_finish. */
static inline int hc_motion_begin(const HC_MOTION_T* x, double weight_N, double buoyancy_N, const double* r_g,
                                  const double* r_b, const double* current_n, HC_MOTION_T* rotation, HC_MOTION_T* nu_r,
                                  HC_MOTION_T* hydrostatic, HC_MOTION_T* damping, HC_MOTION_T* coriolis,
                                  HC_MOTION_T* current_b) {
  const HC_MOTION_T* nu = x + 7;
  hc_motion_rotation_any_norm(x + 3, rotation);
  for (int i = 0; i < 6; ++i) {
    nu_r[i] = nu[i];
    hydrostatic[i] = damping[i] = coriolis[i] = HC_MOTION_SPLAT(0.0);
  }
  hc_motion_add_hydrostatic(rotation, weight_N, buoyancy_N, r_g, r_b, hydrostatic);
  if (hc_motion_current_is_zero(current_n)) return 0;
  const HC_MOTION_T c[3] = {HC_MOTION_SPLAT(current_n[0]), HC_MOTION_SPLAT(current_n[1]),
                            HC_MOTION_SPLAT(current_n[2])};
  hc_motion_rotate_back(rotation, c, current_b);
  for (int i = 0; i < 3; ++i) nu_r[i] -= current_b[i];
  return 1;
}

/* Part 2: coriolis (6) = -C_RB(nu) nu - C_A(nu_r) nu_r + M_A nu_c', with
 * nu_c' = (-nu2 x R^T v_c, 0) for a current constant in NED. Without a
 * current nu_r = nu and C(nu) is linear in M: C_RB(nu) nu + C_A(nu) nu =
 * C(M) nu, M = M_RB + M_A. */
static inline void hc_motion_finish(const HC_MOTION_T* x, int has_current, const double* m, const double* m_rb,
                                    const double* m_a, const HC_MOTION_T* nu_r, const HC_MOTION_T* current_b,
                                    HC_MOTION_T* coriolis) {
  const HC_MOTION_T* nu = x + 7;
  if (!has_current) {
    hc_motion_subtract_coriolis(m, nu, coriolis);
    return;
  }
  const HC_MOTION_T current_rate_b[3] = {-(nu[4] * current_b[2] - nu[5] * current_b[1]),
                                         -(nu[5] * current_b[0] - nu[3] * current_b[2]),
                                         -(nu[3] * current_b[1] - nu[4] * current_b[0])};
  HC_MOTION_T added[6];
  hc_motion_multiply_linear(m_a, current_rate_b, added);
  hc_motion_subtract_coriolis(m_rb, nu, coriolis);
  hc_motion_subtract_coriolis(m_a, nu_r, coriolis);
  for (int i = 0; i < 6; ++i) coriolis[i] += added[i];
}

/* Part 3: x' (13) from the terms: p_n' = R nu1, q' = 1/2 T(q) nu2 + norm
 * feedback, nu' = M^-1 (((tau + hydrostatic) + damping) + coriolis). */
static inline void hc_motion_rates(const HC_MOTION_T* x, const double* tau_b, double gain, const double* m_inv,
                                   const HC_MOTION_T* rotation, const HC_MOTION_T* hydrostatic,
                                   const HC_MOTION_T* damping, const HC_MOTION_T* coriolis, HC_MOTION_T* x_dot) {
  const HC_MOTION_T* nu = x + 7;
  HC_MOTION_T total[6];
  for (int i = 0; i < 6; ++i) total[i] = ((tau_b[i] + hydrostatic[i]) + damping[i]) + coriolis[i];
  hc_motion_rotate(rotation, nu, x_dot);
  hc_motion_quaternion_rate(x + 3, nu + 3, gain, x_dot + 3);
  hc_motion_multiply(m_inv, total, x_dot + 7);
}

#undef HC_MOTION_T
#undef HC_MOTION_SPLAT
#undef HC_MOTION_SQRT
