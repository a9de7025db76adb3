// hydrocoef simulate: run a scenario on a vehicle with the 6-DOF lookup-table
// model, write the trajectory, compare with a measured one, draw the damping's
// uncertainty. The work is hydrocoef::simulate (include/hydrocoef/simulation.hpp);
// this file parses the options and prints the outcome.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/sampling_options.hpp"
#include "hydrocoef/simulation.hpp"

namespace hydrocoef::cli {
namespace {

struct SimulateArgs {
  SimulateOptions options;
  std::optional<std::string> out;
  std::optional<std::string> experiment;
  bool json = false;
};

void run_simulate(SimulateArgs& args, const GlobalOptions& global) {
  SimulateOptions& options = args.options;
  options.database = global.database;
  options.trajectory_csv = args.out.value_or("");
  options.experiment = args.experiment.value_or("");
  TerminalProgress progress("simulating");
  options.progress = progress.time_callback();
  options.sampling.progress = draw_progress();
  const SimulationOutcome outcome = simulate(options);
  progress.finish();
  std::cout << (args.json ? outcome.json() : outcome.text());
}

}  // namespace

void add_simulate_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<SimulateArgs>();
  auto* command = app.add_subcommand(
      "simulate", "Run a scenario on a vehicle with the 6-DOF lookup-table model (RK4 or Dormand-Prince)");
  command->add_option("--vehicle", args->options.vehicle, "Vehicle description (JSON)")->required();
  command->add_option("--scenario", args->options.scenario, "Scenario (JSON): inputs over time, duration, output rate")
      ->required();
  command->add_option("--out", args->out, "Write the trajectory (time, pose, velocity, forces) to this CSV");
  command->add_option("--experiment", args->experiment,
                      "Measured trajectory CSV (t and velocity columns) to compare with: RMS, steady error, 63 % time");
  command
      ->add_option("--steady-fraction", args->options.steady_fraction,
                   "Fraction of the compared record at its end taken as steady state")
      ->capture_default_str();
  add_sampling_options(command, args->options.sampling, "5,50,95; with --out, their bands are columns such as r_p5");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_simulate(*args, global); });
}

}  // namespace hydrocoef::cli
