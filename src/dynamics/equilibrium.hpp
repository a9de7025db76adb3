// Steady state of the dynamics model under a constant generalized force: the
// body velocity nu_b at which every term of the equation of motion balances,
//   tau + tau_damping(nu_r) + tau_hydrostatic(q) - C_RB(nu) nu - C_A(nu_r) nu_r + M_A nu_c' = 0,
// with the attitude held (kinematics frozen: the answer is the velocity the
// body settles at in the body frame, e.g. the steady yaw rate of the ASR-V
// pool test). Solved by Levenberg–Marquardt on the six equations, continued
// until the residual stops falling, so the root is found to machine
// precision where the damping is smooth. The Jacobian's damping part comes
// from the laws' derivatives and the surfaces' own gradients (exact for a
// grid, RBF or GP surface of any number of axes, where differences across a
// cell edge or over a GP's bumps mislead); the Coriolis part, quadratic in
// nu, from central differences.
//
// When Newton's method from the initial guess does not converge (a damping
// surface whose slope vanishes or turns over between the guess and the root
// can hold it in a local minimum of the residual), the solver continues from
// a simulation: it integrates M nu' = residual(nu) with the attitude held
// (Dormand–Prince) from the initial guess over 1, 2, 4, ... s and solves
// again from where the motion has got to, until a solve converges or
// continuation_s have been simulated. A stable steady state, the one
// `simulate` settles at, draws the motion in; a DOF with a force and no
// damping runs away and is reported as no steady state.
#pragma once

#include <cstddef>
#include <vector>

#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {

struct EquilibriumInputs {
  Vector6 tau_b = Vector6::Zero();                     ///< constant force on the body [N, N m]
  Vector3 current_n = Vector3::Zero();                 ///< [m/s] NED
  std::vector<double> disturbances;                    ///< model's disturbance order; empty = all 0
  Quaternion4 q_nb = Quaternion4(1.0, 0.0, 0.0, 0.0);  ///< attitude held
  Vector6 initial_guess_b = Vector6::Zero();
  /// The solve counts as converged when every residual component is at most this [N, N m].
  double residual_tolerance = 1e-10;
  std::size_t max_iterations = 200;
  /// The longest the continuation may simulate [s]; 0: Newton's method alone.
  double continuation_s = 65536.0;
};

struct EquilibriumResult {
  Vector6 nu_b = Vector6::Zero();        ///< steady velocity [m/s, rad/s]
  Vector6 residual_b = Vector6::Zero();  ///< M nu' left at nu_b [N, N m]
  ForceBreakdown forces;                 ///< the terms at nu_b
  bool converged = false;
  std::size_t iterations = 0;   ///< Levenberg–Marquardt iterations, over every solve
  double continuation_s = 0.0;  ///< time simulated before the solve that converged [s]; 0: none needed
};

/// Finds the steady velocity; converged == false when the residual could not
/// be brought below residual_tolerance (e.g. a force in a DOF without
/// damping has no steady state). InputError when the disturbance count is
/// wrong, or from a surface left outside its range under policy "error".
EquilibriumResult solve_equilibrium(const VehicleModel& model, const EquilibriumInputs& inputs);

}  // namespace hydrocoef
