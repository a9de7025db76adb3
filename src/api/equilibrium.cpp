// equilibrium (include/hydrocoef/simulation.hpp): `hydrocoef equilibrium` as
// a library call: the steady body velocity under a constant force with the
// attitude held (src/dynamics/equilibrium), its Monte Carlo distribution over
// the damping's uncertainty, reported as the command reports them
// (src/api/simulation_report).
#include "src/api/internal.hpp"

#include <algorithm>
#include <chrono>
#include <numbers>
#include <optional>

#include "src/api/simulation_report.hpp"
#include "src/api/vehicle_inputs.hpp"
#include "src/core/numbers.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/kinematics.hpp"

namespace hydrocoef {
inline namespace api {

struct EquilibriumOutcome::Access {
  static void set_reports(EquilibriumOutcome& outcome, std::string text, std::string json) {
    outcome.text_ = std::move(text);
    outcome.json_ = std::move(json);
  }
};

namespace {

const std::vector<double> kDefaultPercentiles = {2.5, 50.0, 97.5};

std::string assignment_text(const std::string& name, double value) { return name + "=" + shortest_number(value); }

std::array<double, 6> array_of(const Vector6& v) {
  std::array<double, 6> out{};
  for (std::size_t i = 0; i < 6; ++i) out[i] = v[static_cast<Eigen::Index>(i)];
  return out;
}

/// The model's disturbance values in its order; InputError for a name its surfaces do not read.
std::vector<double> disturbance_values(const VehicleModel& model, const std::map<std::string, double>& given) {
  const auto& names = model.disturbance_names();
  std::vector<double> values(names.size(), 0.0);
  for (const auto& [name, value] : given) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError("--disturbance '" + assignment_text(name, value) + "': the vehicle's surfaces read " +
                       (list.empty() ? "none" : list));
    }
    values[static_cast<std::size_t>(it - names.begin())] = value;
  }
  return values;
}

}  // namespace

void EquilibriumOptions::validate() const {
  for (const auto& [name, value] : tau) {
    if (!force_index(name))
      throw InputError("--tau '" + assignment_text(name, value) + "': expected X, Y, Z, K, M or N =VALUE [N or N m]");
    if (!std::isfinite(value))
      throw InputError("--tau '" + assignment_text(name, value) + "': expected a finite value");
  }
  for (const auto& [name, value] : current) {
    const auto component = velocity_index(name);
    if (!component || *component > 2)
      throw InputError("--current '" + assignment_text(name, value) + "': expected u, v or w =VALUE [m/s]");
    if (!std::isfinite(value))
      throw InputError("--current '" + assignment_text(name, value) + "': expected a finite value");
  }
  for (const auto& [name, value] : disturbances)
    if (!std::isfinite(value))
      throw InputError("--disturbance '" + assignment_text(name, value) + "': expected a finite value");
  for (const double angle : attitude_deg)
    if (!std::isfinite(angle))
      throw InputError("--attitude-deg: found " + shortest_number(angle) + ", expected finite angles [deg]");
  if (sampling.samples > 0) ensemble_options(sampling, kDefaultPercentiles);
}

std::string EquilibriumOutcome::text() const { return text_; }
std::string EquilibriumOutcome::json() const { return json_; }

EquilibriumOutcome equilibrium(const EquilibriumOptions& options) {
  options.validate();
  const VehicleModel model = load_vehicle_model(options.vehicle, options.database);
  std::optional<DampingDraws> draws;
  EnsembleOptions ensemble;
  if (options.sampling.samples > 0) {
    ensemble = ensemble_options(options.sampling, kDefaultPercentiles);
    draws.emplace(model_draws(model));
  }
  EquilibriumInputs in;
  for (const auto& [name, value] : options.tau) in.tau_b[static_cast<Eigen::Index>(*force_index(name))] = value;
  const std::array<double, 3>& attitude = options.attitude_deg;
  in.q_nb = quaternion_from_euler(Vector3(attitude[0], attitude[1], attitude[2]) * (std::numbers::pi / 180.0));
  Vector3 current_b = Vector3::Zero();
  for (const auto& [name, value] : options.current) current_b[static_cast<Eigen::Index>(*velocity_index(name))] = value;
  in.current_n = rotation_body_to_ned(in.q_nb) * current_b;
  in.disturbances = disturbance_values(model, options.disturbances);

  const EquilibriumResult eq = solve_equilibrium(model, in);
  if (!eq.converged) {
    std::size_t worst = 0;
    eq.residual_b.cwiseAbs().maxCoeff(&worst);
    throw InputError(
        "no steady state for this force: the residual stays at " +
        significant(eq.residual_b[static_cast<Eigen::Index>(worst)], 3) + " " + force_unit(worst) + " in " +
        std::string(kForceNames[worst]) +
        ", from the start and from where a simulation with the attitude held got to (a DOF with a force but no "
        "damping, or a coupling that only a change of attitude could balance)");
  }
  const std::string vehicle = is_json_text(options.vehicle) ? "vehicle JSON" : options.vehicle;
  EquilibriumReport report{vehicle, model.description().name, in, eq, attitude};
  EquilibriumOutcome outcome;
  outcome.tau = array_of(in.tau_b);
  outcome.velocity = array_of(eq.nu_b);
  outcome.relative_velocity = array_of(eq.forces.nu_r_b);
  outcome.damping = array_of(eq.forces.damping_b);
  outcome.residual = array_of(eq.residual_b);
  outcome.iterations = eq.iterations;
  outcome.continuation_s = eq.continuation_s;
  std::optional<EquilibriumSamples> samples;
  if (draws) {
    const auto started = std::chrono::steady_clock::now();
    in.initial_guess_b = eq.nu_b;  // each draw starts from the nominal equilibrium
    samples = solve_equilibrium_samples(model, *draws, in, ensemble, EnsembleProgress(options.sampling.progress));
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    report.samples = &*samples;
    report.draws = &*draws;
    report.seed = ensemble.seed;
    report.samples_wall_s = wall_s;
    outcome.sampled = true;
    outcome.monte_carlo = monte_carlo_summary(*draws, ensemble, samples->samples, samples->failures, wall_s);
    outcome.mean = array_of(samples->mean);
    outcome.standard_deviation = array_of(samples->standard_deviation);
    for (const auto& values : samples->percentile_values) outcome.velocity_percentiles.push_back(array_of(values));
  }
  EquilibriumOutcome::Access::set_reports(outcome, equilibrium_text(report), equilibrium_json(report));
  return outcome;
}

}  // namespace api
}  // namespace hydrocoef
