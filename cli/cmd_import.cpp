// hydrocoef import: CFD results (files, folders, solver case folders) into
// the run database. The library reads every input, then stores the runs in one
// transaction (hydrocoef/records.hpp: prepare_import, import_prepared); this
// command parses the options, shows progress and prints what happened.
#include <unistd.h>

#include <iostream>
#include <map>
#include <memory>

#include "cli/common.hpp"
#include "cli/surface_options.hpp"
#include "hydrocoef/records.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"

namespace hydrocoef::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> inputs;
  hydrocoef::ImportOptions options;
  std::vector<std::string> columns, units, monitors;  ///< NAME=VALUE each
  bool json = false, quiet = false;
};

std::map<std::string, std::string> assignments(const std::vector<std::string>& texts, const std::string& option) {
  std::map<std::string, std::string> out;
  for (const auto& text : texts) {
    auto [name, value] = parse_text_assignment(text, option);
    if (!out.emplace(name, value).second) throw InputError(option + " '" + text + "': '" + name + "' given twice");
  }
  return out;
}

void run_import(const ImportArgs& args, const GlobalOptions& global) {
  hydrocoef::ImportOptions options = args.options;
  options.columns = assignments(args.columns, "--column");
  options.units = assignments(args.units, "--unit");
  options.monitors = assignments(args.monitors, "--monitor");
  options.reference_database = global.database;  // a captive table's body reference data
  const bool progress = isatty(STDERR_FILENO) && !args.quiet;
  if (progress)
    options.progress = [](std::size_t done, std::size_t total, const std::string& path) {
      std::cerr << "\r\033[K[" << done << "/" << total << "] "
                << escape::one_line(std::filesystem::path(path).filename().string()) << std::flush;
    };
  // Everything is read before the database is opened: a bad input leaves it
  // as it was (or not made at all).
  auto prepared = hydrocoef::prepare_import(args.inputs, options);
  if (progress) std::cerr << "\r\033[K" << std::flush;
  auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::Create);
  const auto summary = hydrocoef::import_prepared(database, std::move(prepared));
  std::cout << (args.json ? summary.json() : summary.text(args.quiet));
}

}  // namespace

void add_import_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ImportArgs>();
  auto* command =
      app.add_subcommand("import", "Import CFD results (files, folders, OpenFOAM case folders) into the run database");
  command->add_option("inputs", args->inputs, "Files, folders or case folders to import (all in one transaction)")
      ->required();
  command
      ->add_option("--format", args->options.format,
                   "auto (by extension and content), table, monitor, history, cfdpost, vtk, cfx-out (the wall "
                   "force summary of a CFX solver output) or captive-table (non-dimensional captive-test forces)")
      ->capture_default_str();
  command->add_option("--body", args->options.body, "Body name the runs belong to (default vehicle)");
  add_surface_options(*command, args->options);
  command->get_option("--location")
      ->description(
          "Surface exports: a patch, block, zone or [Name] to integrate; CFX .out: a boundary or domain group of the "
          "wall force summary (default its domain group's totals) (repeatable; several are summed)");
  command->add_option("--include", args->options.include,
                      "Folders: import only files matching this glob (repeatable; applied before twins are paired)");
  command->add_option("--exclude", args->options.exclude,
                      "Folders: leave out files matching this glob (repeatable; applied before twins are paired)");
  command->add_option("--manifest", args->options.manifest,
                      "A sweep manifest: CSV of path and key columns (see the README)");
  command->add_option("--key-from-name", args->options.key_from_name,
                      "Run keys from folder or file names, e.g. 'u{u}_v{v}' or 'r{r [deg s^-1]}', of folder contents "
                      "and of files and case folders named on the command line (their path as given)");
  command->add_flag("--prefer-surfaces", args->options.prefer_surfaces,
                    "Of a force history and surface exports of one run, import the surfaces (in an OpenFOAM case "
                    "folder: the export under its VTK/ rather than postProcessing's forces)");
  command->add_option("--column", args->columns,
                      "Tables and histories: map a header to a component, COMPONENT=HEADER, e.g. X=Drag (repeatable)");
  command->add_option("--unit", args->units, "Unit of a column without one, NAME=UNIT, e.g. X=kN (repeatable)");
  command->add_option("--disturbance", args->options.disturbance_columns,
                      "Table: a header whose values are a disturbance parameter (repeatable)");
  command->add_option("--ignore", args->options.ignored_columns, "Table: a header to skip (repeatable)");
  command->add_option("--sign", args->options.sign,
                      "Tables, monitors, histories: on-body (force on the body; the default) or opposing (positive "
                      "opposes motion)");
  command->add_option("--monitor", args->monitors, "Monitor: COMPONENT=COLUMN, e.g. X=\"USER POINT,Fx\" (repeatable)");
  command
      ->add_option("--average-last", args->options.average_last,
                   "Monitor: average the last N iterations (as --window last:N; by default the steady window "
                   "is found as for any force history)")
      ->capture_default_str();
  auto& o = args->options;
  command->add_option("--form", o.form, "Captive table: its forces' form, prime (SNAME), bis (Norrbin) or mmg");
  command->add_option("--drift-convention", o.drift_convention,
                      "Captive table: mmg (beta = atan2(-v, u), bow to port for beta > 0) or fossen (atan2(v, u))");
  command->add_option("--length", o.length, "Captive table: reference length L [m] (else the file's, body set's)");
  command->add_option("--speed", o.speed, "Captive table without a speed column: the speed U [m/s] of every row");
  command->add_option("--density", o.density, "Captive table: water density [kg m^-3] (as --rho)");
  command->add_option("--draft", o.draft, "Captive table, mmg: draft d [m] (else the file's, body set's)");
  command->add_option("--mass", o.mass, "Captive table, bis: mass m [kg] (else rho times the volume)");
  command->add_option("--volume", o.volume, "Captive table, bis: displaced volume [m^3] (else the file's, body set's)");
  command->add_option("--gravity", o.gravity, "Captive table: g [m s^-2] for bis and Fn (default 9.80665)");
  command->add_option("--jobs", args->options.jobs, "Inputs read in parallel (default: the number of cores)");
  command->add_flag("--replace", args->options.replace,
                    "Replace the runs of an earlier import of the same file with other settings, and supersede force "
                    "components that runs already have from other files");
  command->add_option("--also", args->options.also,
                      "Keep this as a second, named reading of a file imported before (e.g. --also mean for pMean "
                      "beside p); an identifier");
  command->add_flag("--quiet", args->quiet, "Print only the summary line");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_import(*args, global); });
}

}  // namespace hydrocoef::cli
