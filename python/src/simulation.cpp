// simulate's and equilibrium's compiled part (hydrocoef.simulate and
// hydrocoef.equilibrium in python/hydrocoef/__init__.py make the vehicle and
// scenario texts): the outcomes of include/hydrocoef/simulation.hpp with the
// trajectory and the Monte Carlo bands as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "python/src/bindings.hpp"

namespace hydrocoef_python {
namespace {

using namespace pybind11::literals;

constexpr const char* kForceNames[] = {"X", "Y", "Z", "K", "M", "N"};

py::dict trajectory_dict(const hydrocoef::Trajectory& trajectory) {
  py::dict out;
  for (std::size_t c = 0; c < trajectory.columns.size(); ++c) {
    py::array_t<double> column(static_cast<py::ssize_t>(trajectory.rows));
    std::copy_n(trajectory.values.data() + c * trajectory.rows, trajectory.rows, column.mutable_data());
    out[py::str(trajectory.columns[c])] = column;
  }
  return out;
}

py::dict named(const std::array<double, 6>& values, const char* const (&names)[6]) {
  py::dict out;
  for (std::size_t i = 0; i < 6; ++i) out[names[i]] = values[i];
  return out;
}

py::dict monte_carlo_dict(const hydrocoef::MonteCarloSummary& m) {
  py::dict out;
  out["requested"] = m.requested;
  out["used"] = m.used;
  out["failed"] = m.failed;
  out["first_failures"] = m.first_failures;
  out["seed"] = m.seed;
  out["percentiles"] = m.percentiles;
  out["drawn"] = m.drawn;
  out["held"] = m.held;
  out["notes"] = m.notes;
  out["wall_time_s"] = m.wall_time_s;
  return out;
}

/// Each quantity's band as an array [percentile, time].
py::dict bands_dict(const hydrocoef::SimulationOutcome& o) {
  py::dict out;
  const std::size_t times = o.band_t_s.size(), percentiles = o.monte_carlo.percentiles.size();
  for (std::size_t q = 0; q < o.band_quantities.size(); ++q) {
    py::array_t<double> band({static_cast<py::ssize_t>(percentiles), static_cast<py::ssize_t>(times)});
    std::copy_n(o.band_values.data() + q * percentiles * times, percentiles * times, band.mutable_data());
    out[py::str(o.band_quantities[q])] = band;
  }
  return out;
}

py::dict simulation_dict(const hydrocoef::SimulationOutcome& o) {
  py::dict out;
  out["columns"] = trajectory_dict(o.trajectory);
  py::dict units;
  for (std::size_t c = 0; c < o.trajectory.columns.size(); ++c)
    units[py::str(o.trajectory.columns[c])] = o.trajectory.units[c];
  out["units"] = units;
  out["notes"] = o.trajectory.notes;
  out["steps"] = o.steps;
  out["rejected_steps"] = o.rejected_steps;
  out["evaluations"] = o.evaluations;
  out["wall_time_s"] = o.wall_time_s;
  py::list comparison;
  for (const auto& c : o.comparison)
    comparison.append(py::dict("component"_a = c.component, "samples"_a = c.samples, "rms_error"_a = c.rms_error,
                               "steady_measured"_a = c.steady_measured, "steady_simulated"_a = c.steady_simulated,
                               "steady_error"_a = c.steady_error, "t63_measured_s"_a = c.t63_measured_s,
                               "t63_simulated_s"_a = c.t63_simulated_s));
  out["comparison"] = comparison;
  if (o.sampled) {
    out["monte_carlo"] = monte_carlo_dict(o.monte_carlo);
    py::array_t<double> t(static_cast<py::ssize_t>(o.band_t_s.size()));
    std::copy(o.band_t_s.begin(), o.band_t_s.end(), t.mutable_data());
    out["band_t"] = t;
    out["bands"] = bands_dict(o);
    py::dict units_of_bands;
    for (std::size_t q = 0; q < o.band_quantities.size(); ++q)
      units_of_bands[py::str(o.band_quantities[q])] = o.band_units[q];
    out["band_units"] = units_of_bands;
    out["measured_inside_band"] = o.measured_inside_band;
  }
  out["text"] = o.text();
  out["json"] = o.json();
  return out;
}

py::dict equilibrium_dict(const hydrocoef::EquilibriumOutcome& o) {
  py::dict out;
  out["tau"] = named(o.tau, kForceNames);
  out["velocity"] = named(o.velocity, kVelocityNames);
  out["relative_velocity"] = named(o.relative_velocity, kVelocityNames);
  out["damping"] = named(o.damping, kForceNames);
  out["residual"] = named(o.residual, kForceNames);
  out["iterations"] = o.iterations;
  out["continuation_s"] = o.continuation_s;
  if (o.sampled) {
    out["monte_carlo"] = monte_carlo_dict(o.monte_carlo);
    out["mean"] = named(o.mean, kVelocityNames);
    out["standard_deviation"] = named(o.standard_deviation, kVelocityNames);
    py::dict percentiles;
    for (std::size_t j = 0; j < o.velocity_percentiles.size(); ++j)
      percentiles[py::float_(o.monte_carlo.percentiles[j])] = named(o.velocity_percentiles[j], kVelocityNames);
    out["velocity_percentiles"] = percentiles;
  }
  out["text"] = o.text();
  out["json"] = o.json();
  return out;
}

hydrocoef::SamplingOptions sampling_options(std::size_t samples, std::uint64_t seed,
                                            const std::vector<double>& percentiles, unsigned threads) {
  hydrocoef::SamplingOptions sampling;
  sampling.samples = samples;
  sampling.seed = seed;
  sampling.percentiles = percentiles;
  sampling.threads = threads;
  return sampling;
}

}  // namespace

void bind_simulation(py::module_& m) {
  m.def(
      "_simulate",
      [](const std::string& vehicle, const std::string& scenario, const std::string& database, const std::string& out,
         const std::string& experiment, double steady_fraction, std::size_t samples, std::uint64_t seed,
         const std::vector<double>& percentiles, unsigned threads) {
        hydrocoef::SimulateOptions options;
        options.vehicle = vehicle;
        options.scenario = scenario;
        options.database = database;
        options.trajectory_csv = out;
        options.experiment = experiment;
        options.steady_fraction = steady_fraction;
        options.sampling = sampling_options(samples, seed, percentiles, threads);
        hydrocoef::SimulationOutcome outcome;
        {
          py::gil_scoped_release release;
          outcome = hydrocoef::simulate(options);
        }
        return simulation_dict(outcome);
      },
      "vehicle"_a, "scenario"_a, "database"_a, "out"_a, "experiment"_a, "steady_fraction"_a, "samples"_a, "seed"_a,
      "percentiles"_a, "threads"_a, "simulate's compiled part: a dict of the outcome. Use hydrocoef.simulate.");
  m.def(
      "_equilibrium",
      [](const std::string& vehicle, const std::string& database, const std::map<std::string, double>& tau,
         const std::map<std::string, double>& current, const std::map<std::string, double>& disturbances,
         const std::array<double, 3>& attitude_deg, std::size_t samples, std::uint64_t seed,
         const std::vector<double>& percentiles, unsigned threads) {
        hydrocoef::EquilibriumOptions options;
        options.vehicle = vehicle;
        options.database = database;
        options.tau = tau;
        options.current = current;
        options.disturbances = disturbances;
        options.attitude_deg = attitude_deg;
        options.sampling = sampling_options(samples, seed, percentiles, threads);
        hydrocoef::EquilibriumOutcome outcome;
        {
          py::gil_scoped_release release;
          outcome = hydrocoef::equilibrium(options);
        }
        return equilibrium_dict(outcome);
      },
      "vehicle"_a, "database"_a, "tau"_a, "current"_a, "disturbances"_a, "attitude_deg"_a, "samples"_a, "seed"_a,
      "percentiles"_a, "threads"_a, "equilibrium's compiled part: a dict of the outcome. Use hydrocoef.equilibrium.");
}

}  // namespace hydrocoef_python
