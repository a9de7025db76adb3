// hydrocoef gci: numerical uncertainty from mesh studies (Celik et al. 2008),
// printed and stored with the key it applies to. The logic is in
// src/pipeline/grid_convergence_runs, the output in cli/gci_output.
#include <memory>
#include <optional>

#include "cli/common.hpp"
#include "cli/gci_output.hpp"
#include "src/pipeline/grid_convergence_runs.hpp"

namespace hydrocoef::cli {
namespace {

struct GciArgs {
  GridConvergenceRequest request;
  bool json = false;
  bool store = true;
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
  command->add_option("--body", args->request.body, "Body whose runs to study")->required();
  command->add_option("--mesh-param", args->request.mesh_parameter, "The disturbance parameter of the mesh level")
      ->capture_default_str();
  command->add_option("--volume", args->request.volume,
                      "Domain volume (m^D) for h = (V/N)^(1/D) from cells=N (default 1: h relative; ratios, order, "
                      "extrapolation and GCI are the same)");
  command->add_option("--dimension", args->request.dimension, "D of h = (V/N)^(1/D): 1, 2 or 3")->capture_default_str();
  command->add_flag("--allow-unconverged", args->request.allow_unconverged,
                    "Run the study although a value did not converge or its iterative error is not below a tenth of "
                    "the change to the adjacent mesh (noted per component); refused by default, as Celik et al. "
                    "require converged values");
  command->add_flag("--store,!--no-store", args->store, "Store the result and apply it to the runs (default)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    RunDatabase database(global.database,
                         args->store ? RunDatabase::OpenMode::MustExist : RunDatabase::OpenMode::ReadOnly);
    const GridConvergenceStudy study = grid_convergence_of_runs(database, args->request);
    std::optional<StoredStudy> stored;
    if (args->store) stored = store_grid_convergence(database, study);
    print_gci(study, args->request, stored, args->json);
  });
}

}  // namespace hydrocoef::cli
