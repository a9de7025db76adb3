// The vehicle, scenario and Monte Carlo inputs of simulate() and
// equilibrium() (src/api/vehicle_inputs.hpp).
#include "src/api/vehicle_inputs.hpp"

#include "src/core/error.hpp"
#include "src/dynamics/surface_source.hpp"
#include "src/dynamics/vehicle.hpp"
#include "src/dynamics/vehicle_stored_models.hpp"

namespace hydrocoef {

bool is_json_text(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  return (first != std::string::npos && text[first] == '{') || text.find('\n') != std::string::npos;
}

VehicleModel load_vehicle_model(const std::string& vehicle, const std::string& database) {
  VehicleDescription description =
      is_json_text(vehicle) ? parse_vehicle(vehicle, "vehicle JSON") : load_vehicle(vehicle);
  if (!database.empty()) resolve_stored_records(description, database);
  if (database.empty() && description.added_mass_from_database)
    throw InputError(SourceLocation{description.file},
                     "key 'added_mass.from_database': no database was given; expected one");
  if (database.empty() && names_derivative_models(description))
    throw InputError(SourceLocation{description.file},
                     "a damping's \"derivatives\": {\"model\": ...} names a stored model, but no database was "
                     "given; expected one");
  return VehicleModel(std::move(description),
                      database.empty() ? SurfaceResolver() : database_surface_resolver(database));
}

Scenario load_scenario_text(const std::string& scenario) {
  return is_json_text(scenario) ? parse_scenario(scenario, "scenario JSON") : load_scenario(scenario);
}

EnsembleOptions ensemble_options(const SamplingOptions& sampling, const std::vector<double>& default_percentiles) {
  EnsembleOptions options;
  options.samples = sampling.samples;
  options.seed = sampling.seed;
  options.percentiles = sampling.percentiles.empty() ? default_percentiles : sampling.percentiles;
  options.threads = sampling.threads;
  check_ensemble_options(options);
  return options;
}

DampingDraws model_draws(const VehicleModel& model) {
  DampingDraws draws(model.damping(), model.description().damping);
  if (!draws.any()) {
    std::string held;
    for (const auto& line : draws.held()) held += "; " + line;
    throw InputError("--samples: nothing in the vehicle's damping has an uncertainty to draw from" + held +
                     " (give a law a \"covariance\", name a stored fit with \"fit\", or use a GP surface)");
  }
  return draws;
}

MonteCarloSummary monte_carlo_summary(const DampingDraws& draws, const EnsembleOptions& options, std::size_t used,
                                      const EnsembleFailures& failures, double wall_time_s) {
  MonteCarloSummary summary;
  summary.requested = used + failures.count;
  summary.used = used;
  summary.failed = failures.count;
  summary.first_failures = failures.first;
  summary.seed = options.seed;
  summary.percentiles = options.percentiles;
  summary.drawn = draws.drawn();
  summary.held = draws.held();
  summary.notes = draws.notes();
  summary.wall_time_s = wall_time_s;
  return summary;
}

}  // namespace hydrocoef
