// hydrocoef export: a stored gridded surface as a file another tool loads
// (CSV, JSON, a C99 header, MATLAB/Simulink .mat, JSBSim XML, VTK, DAVE-ML),
// or the selected runs as OpenFOAM forceCoeffs files (--format
// openfoam-forcecoeffs). The work and the printing are the library's
// (hydrocoef::export_surface, hydrocoef::export_forcecoeffs).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/exports.hpp"

namespace hydrocoef::cli {
namespace {

struct ExportArgs {
  hydrocoef::TableExportOptions options;
  hydrocoef::ForceCoeffsExportOptions runs;  // --format openfoam-forcecoeffs
  bool json = false;
};

void run_export(ExportArgs& args, const GlobalOptions& global) {
  const bool runs = args.options.format == "openfoam-forcecoeffs";
  const auto& r = args.runs;
  if (!runs && (!r.body.empty() || !r.where.empty() || !r.exclude_runs.empty() || !r.area.empty() || !r.axes.empty() ||
                r.precision != 16 || r.mean_only))
    throw hydrocoef::InputError(
        "--body, --where, --exclude-run, --area, --axes, --precision and --mean-only apply to --format "
        "openfoam-forcecoeffs only (got --format " +
        args.options.format + ")");
  if (runs) {
    if (args.options.single_precision || !args.options.identifier.empty() || !args.options.surfaces.empty() ||
        !args.options.vehicle.empty())
      throw hydrocoef::InputError(
          "--float, --identifier, --surface and --vehicle do not apply to --format openfoam-forcecoeffs");
    if (!args.options.name.empty())
      throw hydrocoef::InputError(
          "--format openfoam-forcecoeffs writes runs, not a surface, and takes no NAME; select runs with --body, "
          "--where and --exclude-run");
    args.runs.output = args.options.output;
    const auto db = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
    const auto result = hydrocoef::export_forcecoeffs(db, args.runs);
    std::cout << (args.json ? result.json() : result.text());
    return;
  }
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
      "(libhydrocoef_runtime's file: the surfaces as hydrocoef evaluates them, with their standard deviation); "
      "or, with no NAME, openfoam-forcecoeffs (the selected runs as OpenFOAM forceCoeffs files, one per run in "
      "the folder -o, in the case's axes)");
  command->add_option("name", options.name, "Surface name (with --vehicle: the body; none with openfoam-forcecoeffs)");
  command
      ->add_option("--format", options.format,
                   "csv, csv-wide, json, c, mat, jsbsim, vtk, daveml, runtime or openfoam-forcecoeffs")
      ->required();
  command
      ->add_option("-o,--output", options.output,
                   "File to write (written whole or not at all); openfoam-forcecoeffs: the folder")
      ->required();
  command->add_flag("--float", options.single_precision, "C header: float tables and arithmetic (microcontrollers)");
  command->add_option("--identifier", options.identifier,
                      "C header: prefix of its names (default from the surface name)");
  command->add_option("--surface", options.surfaces,
                      "runtime: a further surface of the same body in the file (repeat for more)");
  auto& runs = args->runs;
  command->add_option("--body", runs.body, "openfoam-forcecoeffs: only this body's runs");
  command->add_option("--where", runs.where, "openfoam-forcecoeffs: select runs (as runs --where)");
  command->add_option("--exclude-run", runs.exclude_runs, "openfoam-forcecoeffs: leave a run out (repeat)");
  command->add_option("--area", runs.area, "openfoam-forcecoeffs: the body's area used as Aref (default its default)");
  command->add_option("--axes", runs.axes,
                      "openfoam-forcecoeffs: the case's axes, CFD to body as import takes them (default: each "
                      "run's, as imported)");
  command->add_option("--precision", runs.precision,
                      "openfoam-forcecoeffs: digits after the point (16: exact; OpenFOAM's writePrecision)");
  command->add_flag("--mean-only", runs.mean_only, "openfoam-forcecoeffs: one row of the stored forces per run");
  command->add_option("--vehicle", options.vehicle,
                      "runtime: a vehicle file (as simulate's); NAME is then its body, and the file holds its "
                      "whole dynamics model and the surfaces its damping reads");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_export(*args, global); });
}

}  // namespace hydrocoef::cli
