#include "src/dynamics/equilibrium.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {

EquilibriumResult solve_equilibrium(const VehicleModel& model, const EquilibriumInputs& inputs) {
  std::vector<double> disturbances = inputs.disturbances;
  if (disturbances.empty()) disturbances.assign(model.disturbance_names().size(), 0.0);
  if (disturbances.size() != model.disturbance_names().size())
    throw InputError("equilibrium: found " + std::to_string(disturbances.size()) + " disturbance values, expected " +
                     std::to_string(model.disturbance_names().size()));
  ModelInputs model_inputs;
  model_inputs.tau_b = inputs.tau_b;
  model_inputs.current_n = inputs.current_n;
  model_inputs.disturbances = disturbances;
  const Quaternion4 q = inputs.q_nb.normalized();
  auto residual = [&](const Vector6& nu) {
    return model.forces(make_state(Vector3::Zero(), q, nu), model_inputs).total();
  };

  EquilibriumResult result;
  Vector6 nu = inputs.initial_guess_b;
  Vector6 r = residual(nu);
  double cost = r.squaredNorm();
  double lambda = 1e-3;
  for (result.iterations = 0; result.iterations < inputs.max_iterations; ++result.iterations) {
    if (cost == 0.0) break;
    Matrix6 jacobian;
    for (Eigen::Index i = 0; i < 6; ++i) {
      const double h = 1e-6 * std::max(1.0, std::abs(nu[i]));
      Vector6 plus = nu, minus = nu;
      plus[i] += h;
      minus[i] -= h;
      jacobian.col(i) = (residual(plus) - residual(minus)) / (2.0 * h);
    }
    const Matrix6 a = jacobian.transpose() * jacobian;
    const Vector6 g = jacobian.transpose() * r;
    const double floor = 1e-12 * std::max(a.diagonal().maxCoeff(), 1e-300);
    bool improved = false;
    while (lambda < 1e12) {
      Matrix6 damped = a;
      damped.diagonal() += lambda * (a.diagonal().array() + floor).matrix();
      const Vector6 step = -damped.ldlt().solve(g);
      const Vector6 candidate = nu + step;
      const Vector6 r_candidate = residual(candidate);
      const double candidate_cost = r_candidate.squaredNorm();
      if (std::isfinite(candidate_cost) && candidate_cost < cost) {
        const bool tiny = step.cwiseAbs().maxCoeff() <= 1e-15 * (1.0 + nu.cwiseAbs().maxCoeff());
        nu = candidate;
        r = r_candidate;
        cost = candidate_cost;
        lambda = std::max(lambda / 10.0, 1e-12);
        improved = !tiny;
        break;
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  result.nu_b = nu;
  result.residual_b = r;
  result.forces = model.forces(make_state(Vector3::Zero(), q, nu), model_inputs);
  result.converged = r.cwiseAbs().maxCoeff() <= inputs.residual_tolerance;
  return result;
}

}  // namespace hydrocoef
