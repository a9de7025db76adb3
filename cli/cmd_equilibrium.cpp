// hydrocoef equilibrium: the steady body velocity under a constant force, the
// attitude held, and its distribution over the damping's uncertainty. The
// work is hydrocoef::equilibrium (include/hydrocoef/simulation.hpp); this file
// parses the options and prints the outcome.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "cli/sampling_options.hpp"
#include "hydrocoef/simulation.hpp"

namespace hydrocoef::cli {
namespace {

struct EquilibriumArgs {
  EquilibriumOptions options;
  std::vector<std::string> tau;
  std::vector<std::string> current;
  std::vector<std::string> disturbance;
  std::string attitude = "0,0,0";
  bool json = false;
};

/// "NAME=VALUE" entries into a map (the later of two of one name wins).
std::map<std::string, double> assignments(const std::vector<std::string>& texts, const std::string& option) {
  std::map<std::string, double> out;
  for (const auto& text : texts) {
    const auto [name, value] = parse_assignment(text, option);
    out[name] = value;
  }
  return out;
}

void run_equilibrium(EquilibriumArgs& args, const GlobalOptions& global) {
  EquilibriumOptions& options = args.options;
  options.database = global.database;
  options.tau = assignments(args.tau, "--tau");
  options.current = assignments(args.current, "--current");
  options.disturbances = assignments(args.disturbance, "--disturbance");
  options.attitude_deg = parse_triple(args.attitude, "--attitude-deg");
  options.sampling.progress = draw_progress();
  const EquilibriumOutcome outcome = equilibrium(options);
  std::cout << (args.json ? outcome.json() : outcome.text());
}

}  // namespace

void add_equilibrium_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<EquilibriumArgs>();
  auto* command = app.add_subcommand("equilibrium", "Steady body velocity under a constant force (attitude held)");
  command->add_option("--vehicle", args->options.vehicle, "Vehicle description (JSON)")->required();
  command->add_option("--tau", args->tau,
                      "Force on the body NAME=VALUE, NAME one of X Y Z [N], K M N [N m] (repeatable)");
  command->add_option("--current", args->current, "Water velocity u|v|w=VALUE in body axes [m/s] (repeatable)");
  command->add_option("--disturbance", args->disturbance,
                      "Disturbance parameter NAME=VALUE read by surfaces (repeatable)");
  command->add_option("--attitude-deg", args->attitude, "Attitude held: roll,pitch,yaw [deg]")->capture_default_str();
  add_sampling_options(command, args->options.sampling, "2.5,50,97.5: the 95 % interval");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_equilibrium(*args, global); });
}

}  // namespace hydrocoef::cli
