// hydrocoef export-fmu: a stored gridded surface, or a vehicle, as an FMI
// 2.0 Co-Simulation FMU (docs/fmu.md). The work and the printing are the
// library's (hydrocoef::export_fmu).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/fmu.hpp"

namespace hydrocoef::cli {
namespace {

struct FmuArgs {
  hydrocoef::FmuExportOptions options;
  bool json = false;
};

void run_export_fmu(const FmuArgs& args, const GlobalOptions& global) {
  args.options.validate();
  const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto result = hydrocoef::export_fmu(db, args.options);
  std::cout << (args.json ? result.json() : result.text());
}

}  // namespace

void add_export_fmu_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<FmuArgs>();
  auto& o = args->options;
  auto* command = app.add_subcommand(
      "export-fmu",
      "Write a stored gridded surface (--surface) or a vehicle (--vehicle) as an FMI 2.0 Co-Simulation FMU "
      "(modelDescription.xml, binaries/linux64 built on libhydrocoef_runtime, resources/model.hcr): a surface's "
      "inputs are its axes, its outputs its outputs and their standard deviations, as hydrocoef query evaluates "
      "them; a vehicle's inputs are tau_b, the current and the disturbances, its outputs the pose, velocities and "
      "damping, stepped as hydrocoef simulate steps (RK4); SI, FRD body axes, NED, on-body signs; a refused export "
      "writes nothing");
  command->add_option("body", o.body, "Body whose surface (or vehicle) the FMU evaluates")->required();
  command->add_option("--surface", o.surface, "The stored gridded surface (of BODY)");
  command->add_option("--vehicle", o.vehicle,
                      "A vehicle file (JSON, as hydrocoef simulate --vehicle) whose damping surfaces are BODY's");
  command->add_option("-o,--output", o.output, "The .fmu file to write (written whole or not at all)")->required();
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_export_fmu(*args, global); });
}

}  // namespace hydrocoef::cli
