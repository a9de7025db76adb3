// hydrocoef gci: numerical uncertainty from mesh studies (Celik et al. 2008),
// printed and stored with the key it applies to. The command parses its
// options into hydrocoef::GciOptions and prints what
// hydrocoef::grid_convergence (include/hydrocoef/analysis.hpp) returns.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/analysis.hpp"

namespace hydrocoef::cli {
namespace {

struct GciArgs {
  GciOptions options;
  bool json = false;
};

}  // namespace

void add_gci_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<GciArgs>();
  auto* command = app.add_subcommand(
      "gci",
      "Numerical uncertainty from mesh studies: for each key with runs at 3 or more mesh levels (disturbance "
      "parameter mesh=LEVEL with cells=N or cell_size=H), the observed order, Richardson extrapolation and "
      "grid-convergence index of each force component by Celik et al. (2008), oscillatory convergence included, "
      "on the three finest levels; stored and applied as GCI_fine |phi1| / 2 to the runs of the key's finest mesh");
  command->add_option("--body", args->options.body, "Body whose runs to study")->required();
  command->add_option("--mesh-param", args->options.mesh_parameter, "The disturbance parameter of the mesh level")
      ->capture_default_str();
  command->add_option("--volume", args->options.volume,
                      "Domain volume (m^D) for h = (V/N)^(1/D) from cells=N (default 1: h relative; ratios, order, "
                      "extrapolation and GCI are the same)");
  command->add_option("--dimension", args->options.dimension, "D of h = (V/N)^(1/D): 1, 2 or 3")->capture_default_str();
  command->add_flag("--allow-unconverged", args->options.allow_unconverged,
                    "Run the study although a value did not converge or its iterative error is not below a tenth of "
                    "the change to the adjacent mesh (noted per component); refused by default, as Celik et al. "
                    "require converged values");
  command->add_flag("--store,!--no-store", args->options.store, "Store the result and apply it to the runs (default)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    auto database = Database::open(global.database, args->options.store ? OpenMode::ReadWrite : OpenMode::ReadOnly);
    const GciStudy study = grid_convergence(database, args->options);
    std::cout << (args->json ? study.json() + "\n" : study.text());
  });
}

}  // namespace hydrocoef::cli
