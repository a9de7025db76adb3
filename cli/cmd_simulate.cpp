// hydrocoef simulate: run a scenario on a vehicle with the 6-DOF lookup-table
// model, write the trajectory, compare with a measured one;
// hydrocoef equilibrium: the steady velocity under a constant force.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numbers>

#include "cli/common.hpp"
#include "cli/simulate_output.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/dynamics/damping_draws.hpp"
#include "src/dynamics/ensemble.hpp"
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/experiment.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/surface_source.hpp"

namespace hydrocoef::cli {
namespace {

// ---- Monte Carlo options -----------------------------------------------------

struct SampleArgs {
  std::size_t samples = 0;  // 0: no Monte Carlo
  std::uint64_t seed = 1;
  std::vector<double> percentiles;
  unsigned threads = 0;
};

void add_sample_options(CLI::App* command, SampleArgs& args, const char* default_percentiles) {
  command->add_option("--samples", args.samples,
                      "Monte Carlo: draw the uncertain damping N times (laws from their covariance, GP surfaces from "
                      "their posterior; one draw per run, not per step) and report percentiles");
  command->add_option("--seed", args.seed, "Seed of the draws (the same seed gives the same draws)")
      ->capture_default_str();
  command
      ->add_option(
          "--percentiles", args.percentiles,
          std::string("Percentiles to report, comma-separated, increasing (default ") + default_percentiles + ")")
      ->delimiter(',');
  command->add_option("--threads", args.threads, "Threads for the draws (0: one per core)")->capture_default_str();
}

/// The draws of a model's damping, or InputError when nothing in it is uncertain.
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

EnsembleOptions ensemble_options(const SampleArgs& args, std::vector<double> default_percentiles) {
  EnsembleOptions options;
  options.samples = args.samples;
  options.seed = args.seed;
  options.percentiles = args.percentiles.empty() ? std::move(default_percentiles) : args.percentiles;
  options.threads = args.threads;
  check_ensemble_options(options);
  return options;
}

/// "sampling: 350 of 1000 draws" on a terminal, at most five times a second.
EnsembleProgress draw_progress() {
  if (isatty(STDERR_FILENO) == 0) return {};
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [last](std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (now - *last < std::chrono::milliseconds(200) && done < total) return;
    *last = now;
    std::fprintf(stderr, "\rsampling: %zu of %zu draws%s", done, total, done == total ? "\n" : "");
  };
}

/// The vehicle with its stored fits filled in, as a model.
VehicleModel load_model(const std::string& vehicle, const GlobalOptions& global) {
  VehicleDescription description = load_vehicle(vehicle);
  resolve_stored_records(description, global.database);
  return VehicleModel(std::move(description), database_surface_resolver(global.database));
}

// ---- simulate ---------------------------------------------------------------

struct SimulateArgs {
  std::string vehicle;
  std::string scenario;
  std::optional<std::string> out;
  std::optional<std::string> experiment;
  double steady_fraction = 0.2;
  SampleArgs sampling;
  bool json = false;
};

void run_simulate(const SimulateArgs& args, const GlobalOptions& global) {
  const VehicleModel model = load_model(args.vehicle, global);
  const Scenario scenario = load_scenario(args.scenario);
  std::optional<DampingDraws> draws;
  EnsembleOptions options;
  if (args.sampling.samples > 0) {
    options = ensemble_options(args.sampling, {5.0, 50.0, 95.0});
    draws.emplace(model_draws(model));
  }
  std::optional<MeasuredTrajectory> measured;
  if (args.experiment) measured = read_measured_trajectory(*args.experiment);
  if (!(args.steady_fraction > 0.0 && args.steady_fraction <= 1.0))
    throw InputError("--steady-fraction " + shortest_number(args.steady_fraction) + ": expected a number in (0, 1]");

  // A progress line on a terminal, at most five times a second.
  const bool tty = isatty(STDERR_FILENO) != 0;
  const auto started = std::chrono::steady_clock::now();
  auto last_print = started;
  SimulationProgress progress;
  if (tty)
    progress = [&](double t, double duration) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_print < std::chrono::milliseconds(200) && t < duration) return;
      last_print = now;
      std::fprintf(stderr, "\rsimulating: t = %.1f of %.1f s (%3.0f %%)", t, duration, 100.0 * t / duration);
    };
  const SimulationResult result = simulate(model, scenario, progress);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (tty && std::chrono::duration<double>(last_print - started).count() > 0.0) std::fprintf(stderr, "\n");
  std::optional<TrajectoryBands> bands;
  double samples_wall_s = 0.0;
  if (draws) {
    const auto sampling_started = std::chrono::steady_clock::now();
    bands = simulate_samples(model, *draws, scenario, options, draw_progress());
    samples_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - sampling_started).count();
  }
  if (args.out) write_trajectory_csv(*args.out, result.samples, bands ? &*bands : nullptr);
  std::vector<ComponentComparison> comparison;
  if (measured) {
    ComparisonOptions compare;
    compare.steady_fraction = args.steady_fraction;
    comparison = compare_with_experiment(*measured, result.samples, compare);
  }
  SimulationReport report{args.vehicle, model.description().name, args.scenario,        scenario,  result, wall_s,
                          args.out,     args.experiment,          args.steady_fraction, comparison};
  if (bands) {
    report.bands = &*bands;
    report.draws = &*draws;
    report.seed = options.seed;
    report.samples_wall_s = samples_wall_s;
    report.measured = measured ? &*measured : nullptr;
  }
  print_simulation(report, args.json);
}

// ---- equilibrium ------------------------------------------------------------

struct EquilibriumArgs {
  std::string vehicle;
  std::vector<std::string> tau;
  std::vector<std::string> current;
  std::vector<std::string> disturbance;
  std::string attitude = "0,0,0";
  SampleArgs sampling;
  bool json = false;
};

void run_equilibrium(const EquilibriumArgs& args, const GlobalOptions& global) {
  const VehicleModel model = load_model(args.vehicle, global);
  std::optional<DampingDraws> draws;
  EnsembleOptions options;
  if (args.sampling.samples > 0) {
    options = ensemble_options(args.sampling, {2.5, 50.0, 97.5});
    draws.emplace(model_draws(model));
  }
  EquilibriumInputs in;
  for (const auto& text : args.tau) {
    const auto [name, value] = parse_assignment(text, "--tau");
    const auto dof = force_index(name);
    if (!dof) throw InputError("--tau '" + text + "': expected X, Y, Z, K, M or N =VALUE [N or N m]");
    in.tau_b[static_cast<Eigen::Index>(*dof)] = value;
  }
  const auto attitude = parse_triple(args.attitude, "--attitude-deg");
  in.q_nb = quaternion_from_euler(Vector3(attitude[0], attitude[1], attitude[2]) * (std::numbers::pi / 180.0));
  Vector3 current_b = Vector3::Zero();
  for (const auto& text : args.current) {
    const auto [name, value] = parse_assignment(text, "--current");
    const auto component = velocity_index(name);
    if (!component || *component > 2) throw InputError("--current '" + text + "': expected u, v or w =VALUE [m/s]");
    current_b[static_cast<Eigen::Index>(*component)] = value;
  }
  in.current_n = rotation_body_to_ned(in.q_nb) * current_b;
  in.disturbances.assign(model.disturbance_names().size(), 0.0);
  for (const auto& text : args.disturbance) {
    const auto [name, value] = parse_assignment(text, "--disturbance");
    const auto& names = model.disturbance_names();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError("--disturbance '" + text + "': the vehicle's surfaces read " + (list.empty() ? "none" : list));
    }
    in.disturbances[static_cast<std::size_t>(it - names.begin())] = value;
  }

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
  EquilibriumReport report{args.vehicle, model.description().name, in, eq, attitude};
  std::optional<EquilibriumSamples> samples;
  if (draws) {
    const auto started = std::chrono::steady_clock::now();
    in.initial_guess_b = eq.nu_b;  // each draw starts from the nominal equilibrium
    samples = solve_equilibrium_samples(model, *draws, in, options, draw_progress());
    report.samples = &*samples;
    report.draws = &*draws;
    report.seed = options.seed;
    report.samples_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  print_equilibrium(report, args.json);
}

}  // namespace

void add_simulate_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<SimulateArgs>();
  auto* command = app.add_subcommand(
      "simulate", "Run a scenario on a vehicle with the 6-DOF lookup-table model (RK4 or Dormand-Prince)");
  command->add_option("--vehicle", args->vehicle, "Vehicle description (JSON)")->required();
  command->add_option("--scenario", args->scenario, "Scenario (JSON): inputs over time, duration, output rate")
      ->required();
  command->add_option("--out", args->out, "Write the trajectory (time, pose, velocity, forces) to this CSV");
  command->add_option("--experiment", args->experiment,
                      "Measured trajectory CSV (t and velocity columns) to compare with: RMS, steady error, 63 % time");
  command
      ->add_option("--steady-fraction", args->steady_fraction,
                   "Fraction of the compared record at its end taken as steady state")
      ->capture_default_str();
  add_sample_options(command, args->sampling, "5,50,95; with --out, their bands are columns such as r_p5");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_simulate(*args, global); });
}

void add_equilibrium_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<EquilibriumArgs>();
  auto* command = app.add_subcommand("equilibrium", "Steady body velocity under a constant force (attitude held)");
  command->add_option("--vehicle", args->vehicle, "Vehicle description (JSON)")->required();
  command->add_option("--tau", args->tau,
                      "Force on the body NAME=VALUE, NAME one of X Y Z [N], K M N [N m] (repeatable)");
  command->add_option("--current", args->current, "Water velocity u|v|w=VALUE in body axes [m/s] (repeatable)");
  command->add_option("--disturbance", args->disturbance,
                      "Disturbance parameter NAME=VALUE read by surfaces (repeatable)");
  command->add_option("--attitude-deg", args->attitude, "Attitude held: roll,pitch,yaw [deg]")->capture_default_str();
  add_sample_options(command, args->sampling, "2.5,50,97.5: the 95 % interval");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_equilibrium(*args, global); });
}

}  // namespace hydrocoef::cli
