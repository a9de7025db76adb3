// hydrocoef export: a stored gridded surface as a file another tool loads
// (CSV, JSON, a C99 header, MATLAB/Simulink .mat, JSBSim XML, VTK, DAVE-ML).
// The work and the printing are the library's (hydrocoef::export_surface).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/exports.hpp"

namespace hydrocoef::cli {
namespace {

struct ExportArgs {
  hydrocoef::TableExportOptions options;
  bool json = false;
};

void run_export(const ExportArgs& args, const GlobalOptions& global) {
  args.options.validate();
  const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto result = hydrocoef::export_surface(db, args.options);
  std::cout << (args.json ? result.json() : result.text());
}

}  // namespace

void add_export_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ExportArgs>();
  auto& options = args->options;
  auto* command = app.add_subcommand(
      "export",
      "Write a stored gridded surface for another tool: csv, csv-wide, json, c (C99 header), mat "
      "(MATLAB v5 + Simulink set-up script), jsbsim (XML tables), vtk (ParaView) or daveml (DAVE-ML, "
      "AIAA S-119; with each node's standard deviation when the surface states one) or runtime "
      "(libhydrocoef_runtime's file: the surfaces as hydrocoef evaluates them, with their standard deviation)");
  command->add_option("name", options.name, "Surface name (with --vehicle: the body)")->required();
  command->add_option("--format", options.format, "csv, csv-wide, json, c, mat, jsbsim, vtk, daveml or runtime")
      ->required();
  command->add_option("-o,--output", options.output, "File to write (written whole or not at all)")->required();
  command->add_flag("--float", options.single_precision, "C header: float tables and arithmetic (microcontrollers)");
  command->add_option("--identifier", options.identifier,
                      "C header: prefix of its names (default from the surface name)");
  command->add_option("--surface", options.surfaces,
                      "runtime: a further surface of the same body in the file (repeat for more)");
  command->add_option("--vehicle", options.vehicle,
                      "runtime: a vehicle file (as simulate's); NAME is then its body, and the file holds its "
                      "whole dynamics model and the surfaces its damping reads");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_export(*args, global); });
}

}  // namespace hydrocoef::cli
