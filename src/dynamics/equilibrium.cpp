#include "src/dynamics/equilibrium.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "src/core/error.hpp"
#include "src/dynamics/integrators.hpp"

namespace hydrocoef {
namespace {

/// The residual M nu' = total force at nu (attitude held) and its Jacobian.
class Balance {
 public:
  Balance(const VehicleModel& model, const ModelInputs& inputs, const Quaternion4& q)
      : model_(model), inputs_(inputs), q_(q) {}

  Vector6 residual(const Vector6& nu) const { return forces(nu).total(); }
  ForceBreakdown forces(const Vector6& nu) const { return model_.forces(make_state(Vector3::Zero(), q_, nu), inputs_); }
  ForceBreakdown undamped(const Vector6& nu) const {
    return model_.undamped_forces(make_state(Vector3::Zero(), q_, nu), inputs_);
  }

  /// d residual / d nu: the damping's from the laws' derivatives and the
  /// surfaces' gradients (nu_r = nu - nu_c, so d nu_r / d nu = I); the
  /// Coriolis and current terms, quadratic in nu, by central differences,
  /// which are exact for a quadratic up to round-off.
  Matrix6 jacobian(const Vector6& nu) const {
    Matrix6 damping;
    (void)model_.damping().evaluate_with_jacobian(undamped(nu).nu_r_b, inputs_.disturbances, damping);
    Matrix6 inertial;
    for (Eigen::Index i = 0; i < 6; ++i) {
      const double h = 1e-4 * std::max(1.0, std::abs(nu[i]));
      Vector6 plus = nu, minus = nu;
      plus[i] += h;
      minus[i] -= h;
      inertial.col(i) = (undamped(plus).coriolis_b - undamped(minus).coriolis_b) / (2.0 * h);
    }
    return damping + inertial;
  }

 private:
  const VehicleModel& model_;
  const ModelInputs& inputs_;
  Quaternion4 q_;
};

struct Solve {
  Vector6 nu;
  Vector6 r;
  std::size_t iterations = 0;
};

/// Levenberg–Marquardt from nu on the six equations, continued until the
/// residual stops falling. A trial step that takes a surface out of its
/// range (policy "error") is a step too long.
Solve levenberg_marquardt(const Balance& balance, Vector6 nu, std::size_t max_iterations) {
  Solve s{nu, balance.residual(nu), 0};
  double cost = s.r.squaredNorm();
  double lambda = 1e-3;
  for (; s.iterations < max_iterations; ++s.iterations) {
    if (cost == 0.0) break;
    const Matrix6 jacobian = balance.jacobian(s.nu);
    const Matrix6 a = jacobian.transpose() * jacobian;
    const Vector6 g = jacobian.transpose() * s.r;
    const double floor = 1e-12 * std::max(a.diagonal().maxCoeff(), 1e-300);
    bool improved = false;
    while (lambda < 1e12) {
      Matrix6 damped = a;
      damped.diagonal() += lambda * (a.diagonal().array() + floor).matrix();
      const Vector6 step = -damped.ldlt().solve(g);
      const Vector6 candidate = s.nu + step;
      Vector6 r_candidate;
      try {
        r_candidate = balance.residual(candidate);
      } catch (const InputError&) {
        lambda *= 10.0;
        continue;
      }
      const double candidate_cost = r_candidate.squaredNorm();
      if (std::isfinite(candidate_cost) && candidate_cost < cost) {
        const bool tiny = step.cwiseAbs().maxCoeff() <= 1e-15 * (1.0 + s.nu.cwiseAbs().maxCoeff());
        s.nu = candidate;
        s.r = r_candidate;
        cost = candidate_cost;
        lambda = std::max(lambda / 10.0, 1e-12);
        improved = !tiny;
        break;
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  return s;
}

bool balanced(const Solve& s, double tolerance) { return s.r.allFinite() && s.r.cwiseAbs().maxCoeff() <= tolerance; }

}  // namespace

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
  const Balance balance(model, model_inputs, unit_attitude(inputs.q_nb));

  EquilibriumResult result;
  Solve best = levenberg_marquardt(balance, inputs.initial_guess_b, inputs.max_iterations);
  result.iterations = best.iterations;
  if (!balanced(best, inputs.residual_tolerance) && inputs.continuation_s > 0.0) {
    // Continuation: follow the motion from the starting point, attitude
    // held (M nu' = residual), over spans of 1, 2, 4, ... s, and solve again
    // from where it has got to; a stable steady state, the one a simulation
    // settles at, draws the motion in until Newton's method converges there.
    const Matrix6 m_inverse = model.mass_matrix_inverse();
    auto rates = [&](double, const Vector6& nu, Vector6& nu_dot) { nu_dot = m_inverse * balance.residual(nu); };
    AdaptiveOptions options;
    options.relative_tolerance = 1e-6;
    options.absolute_tolerance = 1e-9;
    // A budget of steps: a motion that only settles after more (stiff and
    // slow at once) or that spins up ever faster is given up on.
    constexpr std::size_t kStepBudget = 50'000;
    options.max_steps = kStepBudget;
    DormandPrince45<Vector6> integrator(options);
    Vector6 nu = inputs.initial_guess_b;
    double t = 0.0;
    for (double span = 1.0; t < inputs.continuation_s; span *= 2.0) {
      const Vector6 before = nu;
      const double t_end = std::min(t + span, inputs.continuation_s);
      try {
        integrator.advance(rates, t, t_end, nu);
      } catch (const InputError&) {
        break;  // the motion blows up (no steady state) or leaves a surface's range
      }
      if (!nu.allFinite() || integrator.stats().accepted + integrator.stats().rejected > kStepBudget) break;
      // Newton again once the state changes slowly: by under a thousandth of
      // itself over the span (a motion that keeps growing, a force in a DOF
      // without damping, never does).
      const double change = (nu - before).cwiseAbs().maxCoeff();
      if (!(change <= 1e-3 * nu.cwiseAbs().maxCoeff() + 1e-12)) continue;
      const Solve attempt = levenberg_marquardt(balance, nu, inputs.max_iterations);
      result.iterations += attempt.iterations;
      if (attempt.r.allFinite() && (!best.r.allFinite() || attempt.r.squaredNorm() < best.r.squaredNorm()))
        best = attempt;
      if (balanced(attempt, inputs.residual_tolerance)) {
        result.continuation_s = t;
        break;
      }
    }
  }
  result.nu_b = best.nu;
  result.residual_b = best.r;
  result.forces = balance.forces(best.nu);
  result.converged = balanced(best, inputs.residual_tolerance);
  return result;
}

}  // namespace hydrocoef
