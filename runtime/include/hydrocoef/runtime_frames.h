/* Frame conversions between hydrocoef's axes and a simulator's, for plugins
 * built on libhydrocoef_runtime (docs/plugin-guide.md).
 *
 * hydrocoef (and PX4, ArduSub, Fossen's texts, SNAME):
 *   world NED: x north, y east, z down;
 *   body FRD: x forward, y starboard (right), z down;
 *   attitude q_nb = (eta, eps1, eps2, eps3), scalar first, the rotation from
 *   body FRD to world NED (v_ned = R(q_nb) v_frd).
 * gz-sim, ROS (REP 103) and most game-engine simulators:
 *   world ENU: x east, y north, z up;
 *   body FLU: x forward, y left (port), z up;
 *   attitude q_enu_flu, the rotation from body FLU to world ENU (gz-sim's
 *   gz::math::Quaterniond(w, x, y, z) takes the scalar first too).
 *
 * Both changes of axes are proper rotations by half a turn (determinant +1):
 *   NED -> ENU: (n, e, d) -> (e, n, -d), half a turn about (1, 1, 0)/sqrt(2);
 *   FRD -> FLU: (x, y, z) -> (x, -y, -z), half a turn about x.
 * So vectors and pseudo-vectors (angular velocities, moments) change alike,
 * and every function here is its own inverse. A moment keeps its reference
 * point (only its axes change); positions change axes about the same origin.
 *
 * Header only (static inline, C99 and C++): no symbol, no allocation, no
 * state. Each output may not alias its input. Exact: only permutations and
 * sign changes but for the two functions with a quaternion, which multiply
 * by 1/sqrt(2) (and rotate, for the world/body pair). */
#ifndef HYDROCOEF_RUNTIME_FRAMES_H
#define HYDROCOEF_RUNTIME_FRAMES_H

#ifdef __cplusplus
extern "C" {
#endif

/* A world vector NED -> ENU, or ENU -> NED: (a, b, c) -> (b, a, -c). */
static inline void hc_frames_ned_enu_vector(const double in[3], double out[3]) {
  out[0] = in[1];
  out[1] = in[0];
  out[2] = -in[2];
}

/* A body vector FRD -> FLU, or FLU -> FRD: (a, b, c) -> (a, -b, -c). Forces,
 * moments, linear and angular velocities alike. */
static inline void hc_frames_frd_flu_vector(const double in[3], double out[3]) {
  out[0] = in[0];
  out[1] = -in[1];
  out[2] = -in[2];
}

/* A body twist (u, v, w, p, q, r) or wrench (X, Y, Z, K, M, N), linear part
 * first, FRD -> FLU or FLU -> FRD. */
static inline void hc_frames_frd_flu_6(const double in[6], double out[6]) {
  hc_frames_frd_flu_vector(in, out);
  hc_frames_frd_flu_vector(in + 3, out + 3);
}

/* An attitude q_nb (body FRD to world NED) -> q_enu_flu (body FLU to world
 * ENU), or back; scalar first. q_enu_flu = q_a (x) q_nb (x) q_b with q_a =
 * (0, 1, 1, 0)/sqrt(2) (NED -> ENU) and q_b = (0, 1, 0, 0) (FLU -> FRD),
 * multiplied out and negated (q and -q are one attitude): a vehicle level and
 * heading north (q_nb = (1, 0, 0, 0)) is yawed a quarter turn left of east in
 * ENU, ((1, 0, 0, 1)/sqrt(2)). */
static inline void hc_frames_ned_enu_attitude(const double in[4], double out[4]) {
  const double s = 0.70710678118654752440; /* 1/sqrt(2) */
  out[0] = s * (in[0] + in[3]);
  out[1] = s * (in[1] + in[2]);
  out[2] = s * (in[1] - in[2]);
  out[3] = s * (in[0] - in[3]);
}

/* v_out = R(q) v_in for a unit quaternion q (scalar first): the rotation the
 * attitude describes, body axes to world axes. */
static inline void hc_frames_rotate(const double q[4], const double in[3], double out[3]) {
  const double e = q[0], x = q[1], y = q[2], z = q[3];
  out[0] = (1.0 - 2.0 * (y * y + z * z)) * in[0] + 2.0 * (x * y - z * e) * in[1] + 2.0 * (x * z + y * e) * in[2];
  out[1] = 2.0 * (x * y + z * e) * in[0] + (1.0 - 2.0 * (x * x + z * z)) * in[1] + 2.0 * (y * z - x * e) * in[2];
  out[2] = 2.0 * (x * z - y * e) * in[0] + 2.0 * (y * z + x * e) * in[1] + (1.0 - 2.0 * (x * x + y * y)) * in[2];
}

/* v_out = R(q)^T v_in: world axes to body axes. */
static inline void hc_frames_rotate_back(const double q[4], const double in[3], double out[3]) {
  const double e = q[0], x = q[1], y = q[2], z = q[3];
  out[0] = (1.0 - 2.0 * (y * y + z * z)) * in[0] + 2.0 * (x * y + z * e) * in[1] + 2.0 * (x * z - y * e) * in[2];
  out[1] = 2.0 * (x * y - z * e) * in[0] + (1.0 - 2.0 * (x * x + z * z)) * in[1] + 2.0 * (y * z + x * e) * in[2];
  out[2] = 2.0 * (x * z + y * e) * in[0] + 2.0 * (y * z - x * e) * in[1] + (1.0 - 2.0 * (x * x + y * y)) * in[2];
}

/* A force (or moment) in hydrocoef's body axes FRD -> the same force in a
 * simulator's world axes ENU, for a body whose attitude the simulator gives
 * as q_enu_flu (what gz-sim's Link::AddWorldWrench takes). */
static inline void hc_frames_body_frd_to_world_enu(const double q_enu_flu[4], const double frd[3], double enu[3]) {
  double flu[3];
  hc_frames_frd_flu_vector(frd, flu);
  hc_frames_rotate(q_enu_flu, flu, enu);
}

/* A velocity (or any vector) in the simulator's world axes ENU -> hydrocoef's
 * body axes FRD, for a body whose attitude the simulator gives as q_enu_flu
 * (a link's world linear velocity -> (u, v, w)). */
static inline void hc_frames_world_enu_to_body_frd(const double q_enu_flu[4], const double enu[3], double frd[3]) {
  double flu[3];
  hc_frames_rotate_back(q_enu_flu, enu, flu);
  hc_frames_frd_flu_vector(flu, frd);
}

#ifdef __cplusplus
}
#endif

#endif /* HYDROCOEF_RUNTIME_FRAMES_H */
