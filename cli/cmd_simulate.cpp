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
#include "src/dynamics/equilibrium.hpp"
#include "src/dynamics/experiment.hpp"
#include "src/dynamics/simulation.hpp"
#include "src/dynamics/surface_source.hpp"

namespace hydrocoef::cli {
namespace {

// ---- simulate ---------------------------------------------------------------

struct SimulateArgs {
  std::string vehicle;
  std::string scenario;
  std::optional<std::string> out;
  std::optional<std::string> experiment;
  double steady_fraction = 0.2;
  bool json = false;
};

void run_simulate(const SimulateArgs& args, const GlobalOptions& global) {
  const VehicleModel model(load_vehicle(args.vehicle), database_surface_resolver(global.database));
  const Scenario scenario = load_scenario(args.scenario);
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
  if (args.out) write_trajectory_csv(*args.out, result.samples);
  std::vector<ComponentComparison> comparison;
  if (measured) {
    ComparisonOptions options;
    options.steady_fraction = args.steady_fraction;
    comparison = compare_with_experiment(*measured, result.samples, options);
  }
  print_simulation(SimulationReport{args.vehicle, model.description().name, args.scenario, scenario, result, wall_s,
                                    args.out, args.experiment, args.steady_fraction, comparison},
                   args.json);
}

// ---- equilibrium ------------------------------------------------------------

struct EquilibriumArgs {
  std::string vehicle;
  std::vector<std::string> tau;
  std::vector<std::string> current;
  std::vector<std::string> disturbance;
  std::string attitude = "0,0,0";
  bool json = false;
};

void run_equilibrium(const EquilibriumArgs& args, const GlobalOptions& global) {
  const VehicleModel model(load_vehicle(args.vehicle), database_surface_resolver(global.database));
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
        " (a DOF with a force but no damping, or a coupling that only a change of attitude could balance)");
  }
  print_equilibrium(EquilibriumReport{args.vehicle, model.description().name, in, eq, attitude}, args.json);
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
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_equilibrium(*args, global); });
}

}  // namespace hydrocoef::cli
