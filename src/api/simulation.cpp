// simulate (include/hydrocoef/simulation.hpp): `hydrocoef simulate` as a
// library call: the vehicle model with its surfaces from a database
// (src/api/vehicle_inputs), the nominal run, the comparison with a measured
// record and the Monte Carlo bands, reported as the command reports them
// (src/api/simulation_report).
#include "src/api/internal.hpp"

#include <chrono>
#include <optional>
#include <stdexcept>

#include "src/api/simulation_report.hpp"
#include "src/api/vehicle_inputs.hpp"
#include "src/core/numbers.hpp"
#include "src/dynamics/experiment.hpp"
#include "src/dynamics/trajectory.hpp"

namespace hydrocoef {
inline namespace api {

struct SimulationOutcome::Access {
  static void set_reports(SimulationOutcome& outcome, std::string text, std::string json) {
    outcome.text_ = std::move(text);
    outcome.json_ = std::move(json);
  }
};

namespace {

const std::vector<double> kDefaultPercentiles = {5.0, 50.0, 95.0};

/// The CSV header's columns split into names and units ("u [m s^-1]" -> "u", "m s^-1").
void split_header(std::vector<std::string>& names, std::vector<std::string>& units) {
  const std::string header = trajectory_csv_header();
  for (std::size_t start = 0; start <= header.size();) {
    const auto comma = header.find(',', start);
    const std::string cell = header.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto bracket = cell.find(" [");
    names.push_back(cell.substr(0, bracket));
    units.push_back(bracket == std::string::npos ? std::string() : cell.substr(bracket + 2, cell.size() - bracket - 3));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}

/// The samples as the trajectory CSV's columns.
Trajectory trajectory_of(const SimulationResult& result) {
  Trajectory out;
  split_header(out.columns, out.units);
  out.rows = result.samples.size();
  out.notes = result.notes;
  out.values.resize(out.columns.size() * out.rows);
  // In the order write_trajectory_csv writes a row (src/dynamics/trajectory.cpp);
  // tests/api/api_test.cpp checks the two agree column by column.
  for (std::size_t r = 0; r < out.rows; ++r) {
    const TrajectorySample& s = result.samples[r];
    std::size_t c = 0;
    const auto put = [&](double value) { out.values[c++ * out.rows + r] = value; };
    const auto put_all = [&](const auto& vector) {
      for (Eigen::Index i = 0; i < vector.size(); ++i) put(vector[i]);
    };
    put(s.t_s);
    put_all(s.p_n);
    put_all(s.euler_rad);
    put_all(s.q_nb);
    put_all(s.nu_b);
    put_all(s.forces.nu_r_b);
    put_all(s.forces.control_b);
    put_all(s.forces.damping_b);
    put_all(s.forces.hydrostatic_b);
    put_all(s.forces.coriolis_b);
    if (c != out.columns.size())
      throw std::logic_error("hydrocoef::simulate: " + std::to_string(c) + " values per sample for " +
                             std::to_string(out.columns.size()) + " columns");
  }
  return out;
}

/// How a report names an input given as a file or as JSON text.
std::string input_label(const std::string& text, const char* what) {
  return is_json_text(text) ? std::string(what) + " JSON" : text;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

const double* Trajectory::column(std::string_view name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return values.data() + c * rows;
  throw std::out_of_range("hydrocoef::Trajectory: no column '" + std::string(name) + "'");
}

void SimulateOptions::validate() const {
  if (!(steady_fraction > 0.0 && steady_fraction <= 1.0))
    throw InputError("--steady-fraction " + shortest_number(steady_fraction) + ": expected a number in (0, 1]");
  if (sampling.samples > 0) ensemble_options(sampling, kDefaultPercentiles);
}

std::string SimulationOutcome::text() const { return text_; }
std::string SimulationOutcome::json() const { return json_; }

SimulationOutcome simulate(const SimulateOptions& options) {
  options.validate();
  const VehicleModel model = load_vehicle_model(options.vehicle, options.database);
  const Scenario scenario = load_scenario_text(options.scenario);
  std::optional<DampingDraws> draws;
  EnsembleOptions ensemble;
  if (options.sampling.samples > 0) {
    ensemble = ensemble_options(options.sampling, kDefaultPercentiles);
    draws.emplace(model_draws(model));
  }
  std::optional<MeasuredTrajectory> measured;
  if (!options.experiment.empty()) measured = read_measured_trajectory(options.experiment);

  const auto started = std::chrono::steady_clock::now();
  const SimulationResult result = simulate_model(model, scenario, SimulationProgress(options.progress));
  const double wall_s = seconds_since(started);
  std::optional<TrajectoryBands> bands;
  double samples_wall_s = 0.0;
  if (draws) {
    const auto sampling_started = std::chrono::steady_clock::now();
    bands = simulate_samples(model, *draws, scenario, ensemble, EnsembleProgress(options.sampling.progress));
    samples_wall_s = seconds_since(sampling_started);
  }
  const std::optional<std::string> out =
      options.trajectory_csv.empty() ? std::nullopt : std::optional<std::string>(options.trajectory_csv);
  if (out) write_trajectory_csv(*out, result.samples, bands ? &*bands : nullptr);
  std::vector<ComponentComparison> comparison;
  if (measured) {
    ComparisonOptions compare;
    compare.steady_fraction = options.steady_fraction;
    comparison = compare_with_experiment(*measured, result.samples, compare);
  }

  SimulationOutcome outcome;
  outcome.trajectory = trajectory_of(result);
  outcome.steps = result.steps;
  outcome.rejected_steps = result.rejected_steps;
  outcome.evaluations = result.evaluations;
  outcome.wall_time_s = wall_s;
  for (const auto& c : comparison)
    outcome.comparison.push_back({c.component, c.samples, c.rms_error, c.steady_measured, c.steady_simulated,
                                  c.steady_error, c.t63_measured_s, c.t63_simulated_s});
  if (bands) {
    outcome.sampled = true;
    outcome.monte_carlo = monte_carlo_summary(*draws, ensemble, bands->samples, bands->failures, samples_wall_s);
    outcome.band_t_s = bands->t_s;
    outcome.band_quantities = bands->quantities;
    outcome.band_units = bands->units;
    outcome.band_values = bands->values;
    if (measured && bands->percentiles.size() >= 2)
      for (std::size_t i = 0; i < 6; ++i)
        if (!measured->nu_b[i].empty())
          outcome.measured_inside_band[std::string(kVelocityNames[i])] =
              share_inside_band(*bands, kVelocityNames[i], measured->t_s, measured->nu_b[i]);
  }

  const std::string vehicle = input_label(options.vehicle, "vehicle");
  const std::string scenario_label = input_label(options.scenario, "scenario");
  const std::optional<std::string> experiment =
      options.experiment.empty() ? std::nullopt : std::optional<std::string>(options.experiment);
  SimulationReport report{vehicle,    model.description().name, scenario_label, scenario, result, wall_s, out,
                          experiment, options.steady_fraction,  comparison};
  if (bands) {
    report.bands = &*bands;
    report.draws = &*draws;
    report.seed = ensemble.seed;
    report.samples_wall_s = samples_wall_s;
    report.measured = measured ? &*measured : nullptr;
  }
  SimulationOutcome::Access::set_reports(outcome, simulation_text(report), simulation_json(report));
  return outcome;
}

Trajectory simulate(const std::string& vehicle_json, const std::string& scenario_json, const std::string& database) {
  SimulateOptions options;
  options.vehicle = vehicle_json;
  options.scenario = scenario_json;
  options.database = database;
  return simulate(options).trajectory;
}

}  // namespace api
}  // namespace hydrocoef
