// Steady state of the dynamics model under a constant generalized force: the
// body velocity nu_b at which every term of the equation of motion balances,
//   tau + tau_damping(nu_r) + tau_hydrostatic(q) - C_RB(nu) nu - C_A(nu_r) nu_r + M_A nu_c' = 0,
// with the attitude held (kinematics frozen: the answer is the velocity the
// body settles at in the body frame, e.g. the steady yaw rate of the ASR-V
// pool test). Solved by Levenberg–Marquardt on the six equations with a
// central-difference Jacobian, continued until the residual stops falling, so
// the root is found to machine precision where the laws are smooth.
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
};

struct EquilibriumResult {
  Vector6 nu_b = Vector6::Zero();        ///< steady velocity [m/s, rad/s]
  Vector6 residual_b = Vector6::Zero();  ///< M nu' left at nu_b [N, N m]
  ForceBreakdown forces;                 ///< the terms at nu_b
  bool converged = false;
  std::size_t iterations = 0;
};

/// Finds the steady velocity; converged == false when the residual could not
/// be brought below residual_tolerance (e.g. a force in a DOF without
/// damping has no steady state). InputError when the disturbance count is
/// wrong, or from a surface left outside its range under policy "error".
EquilibriumResult solve_equilibrium(const VehicleModel& model, const EquilibriumInputs& inputs);

}  // namespace hydrocoef
