// hydrocoef derivatives pmm BODY: the sway and yaw derivatives (Y_v, Y_vdot,
// N_v, N_vdot, Y_r, Y_rdot, N_r, N_rdot) of a body from its stored pure sway
// and pure yaw forced-oscillation runs (hydrocoef pmm). The command parses
// its options into hydrocoef::PmmDerivativeOptions and prints what
// hydrocoef::pmm_derivatives (include/hydrocoef/pmm_derivatives.hpp) returns.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/pmm_derivatives.hpp"

namespace hydrocoef::cli {
namespace {

struct PmmDerivativesArgs {
  PmmDerivativeOptions options;
  bool json = false;
};

}  // namespace

void add_derivatives_pmm_command(CLI::App& derivatives, const GlobalOptions& global) {
  auto args = std::make_shared<PmmDerivativesArgs>();
  auto& o = args->options;
  auto* command = derivatives.add_subcommand(
      "pmm",
      "Sway and yaw derivatives from a body's stored pure sway and pure yaw forced-oscillation runs (hydrocoef "
      "pmm): the part of Y and N in phase with v (r) gives Y_v, N_v (Y_r, N_r), the part in phase with vdot "
      "(rdot) gives Y_vdot, N_vdot (Y_rdot, N_rdot); SNAME body axes, forces on the body, hydrodynamic part only "
      "(Y_vdot = -M_A[sway][sway] at zero speed). Per motion, speed and frequency, runs of several amplitudes "
      "combined, with standard errors, omega' = omega L / U, and the prime form when L, rho and U are known");
  command->add_option("body", o.body, "Body name")->required();
  command->add_option("--run", o.runs, "Only these pmm run ids (hydrocoef pmm-runs; repeatable or comma-separated)")
      ->delimiter(',');
  command->add_option("--speed", o.speed, "Forward speed U [m/s] of every run (default: each run's u key)");
  command->add_option("--length", o.length, "Reference length L [m] (default: the body's, hydrocoef body set)");
  command->add_option("--density", o.density, "Water density rho [kg/m^3] (default: the runs')");
  command->add_flag("--prime", o.prime,
                    "Require omega' and the prime form (SNAME 1950) of every derivative: refused, naming what is "
                    "missing, unless L, rho and U > 0 are known");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    args->options.validate();
    const auto database = Database::open(global.database, OpenMode::ReadOnly);
    const PmmDerivatives result = pmm_derivatives(database, args->options);
    std::cout << (args->json ? result.json() + "\n" : result.text());
  });
}

}  // namespace hydrocoef::cli
