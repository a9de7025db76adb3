// What simulate() and equilibrium() (src/api/simulation.cpp,
// src/api/equilibrium.cpp) share: a vehicle or scenario given as a file or as
// JSON text, the vehicle model with its stored fits and surfaces, and the
// Monte Carlo options checked and turned into the ensemble's.
#pragma once

#include <string>
#include <vector>

#include "hydrocoef/simulation.hpp"
#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/ensemble.hpp"
#include "src/dynamics/scenario.hpp"
#include "src/dynamics/vehicle_model.hpp"

namespace hydrocoef {

/// JSON text rather than a path: it starts with '{' (after blanks) or spans lines.
bool is_json_text(const std::string& text);

/// The vehicle (a file or JSON text) as a model, its stored fits and surfaces
/// read from `database` ("" : none; naming a stored record is then an InputError).
VehicleModel load_vehicle_model(const std::string& vehicle, const std::string& database);
/// The scenario (a file or JSON text).
Scenario load_scenario_text(const std::string& scenario);

/// The ensemble's options from the public ones, `default_percentiles` when
/// none are given; InputError naming --samples or --percentiles.
EnsembleOptions ensemble_options(const SamplingOptions& sampling, const std::vector<double>& default_percentiles);

/// The draws of a model's damping, or InputError when nothing in it is uncertain.
DampingDraws model_draws(const VehicleModel& model);

/// What a Monte Carlo run drew and how it went, for the public outcome.
MonteCarloSummary monte_carlo_summary(const DampingDraws& draws, const EnsembleOptions& options, std::size_t used,
                                      const EnsembleFailures& failures, double wall_time_s);

}  // namespace hydrocoef
