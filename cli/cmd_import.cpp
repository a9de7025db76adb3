// hydrocoef import: CFD results (files, folders, solver case folders) into
// the run database. The library plans and reads the import
// (src/pipeline/import_files.hpp); this command parses the options, shows
// progress, stores the runs in one transaction and prints what happened.
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <map>
#include <memory>

#include "cli/common.hpp"
#include "cli/import_output.hpp"
#include "cli/surface_options.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/pipeline/import_files.hpp"
#include "src/pipeline/sweep_keys.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> inputs;
  std::string format = "auto";
  SurfaceArgs surface;
  std::vector<std::string> include, exclude;
  std::optional<std::string> manifest, key_pattern;
  bool prefer_surfaces = false;
  // tables, monitors, histories
  std::vector<std::string> columns, units, disturbance_columns, ignored, monitors;
  std::optional<std::string> sign;
  std::size_t average_last = 1;
  unsigned jobs = 0;
  bool replace = false, json = false, quiet = false;
  std::string also;
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
  ImportRequest request;
  for (const auto& input : args.inputs) request.inputs.emplace_back(input);
  request.command_line = command_line_settings(args.surface);
  if (args.sign) request.command_line.set("sign", *args.sign, "--sign");
  request.format = args.format;
  request.columns.columns = assignments(args.columns, "--column");
  request.columns.units = assignments(args.units, "--unit");
  request.columns.disturbance_columns = args.disturbance_columns;
  request.columns.ignored_columns = args.ignored;
  request.columns.monitors = assignments(args.monitors, "--monitor");
  request.columns.average_last = args.average_last;
  request.jobs = args.jobs;
  std::optional<Manifest> manifest;
  std::optional<NamePattern> pattern;
  if (args.manifest) manifest = Manifest::read(*args.manifest);
  if (args.key_pattern) pattern.emplace(*args.key_pattern);
  request.plan.include = args.include;
  request.plan.exclude = args.exclude;
  request.plan.manifest = manifest ? &*manifest : nullptr;
  request.plan.key_pattern = pattern ? &*pattern : nullptr;
  request.plan.use_sidecars = !args.surface.no_sidecar;
  request.plan.prefer_surfaces = args.prefer_surfaces;
  const bool progress = isatty(STDERR_FILENO) && !args.quiet;
  if (progress)
    request.progress = [](std::size_t done, std::size_t total, const std::filesystem::path& path) {
      std::cerr << "\r\033[K[" << done << "/" << total << "] " << escape::one_line(path.filename().string())
                << std::flush;
    };

  // Everything is read before the database is opened: a bad input leaves it
  // as it was (or not made at all).
  ImportResult result = read_import(request);
  if (progress) std::cerr << "\r\033[K" << std::flush;
  RunDatabase database(global.database);
  ImportPolicy import_options;
  import_options.components = args.replace ? ConflictPolicy::Replace : ConflictPolicy::Error;
  import_options.replace = args.replace;
  import_options.also = args.also;
  store_import(database, result, import_options);
  print_import(result, global.database, args.json, args.quiet);
}

}  // namespace

void add_import_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ImportArgs>();
  auto* command =
      app.add_subcommand("import", "Import CFD results (files, folders, OpenFOAM case folders) into the run database");
  command->add_option("inputs", args->inputs, "Files, folders or case folders to import (all in one transaction)")
      ->required();
  command
      ->add_option("--format", args->format,
                   "auto (by extension and content), table, monitor, history, cfdpost, vtk or cfx-out (the wall "
                   "force summary of a CFX solver output)")
      ->capture_default_str();
  command->add_option("--body", args->surface.body, "Body name the runs belong to (default vehicle)");
  add_surface_options(*command, args->surface);
  command->get_option("--location")
      ->description(
          "Surface exports: a patch, block, zone or [Name] to integrate; CFX .out: a boundary or domain group of the "
          "wall force summary (default its domain group's totals) (repeatable; several are summed)");
  command->add_option("--include", args->include,
                      "Folders: import only files matching this glob (repeatable; applied before twins are paired)");
  command->add_option("--exclude", args->exclude,
                      "Folders: leave out files matching this glob (repeatable; applied before twins are paired)");
  command->add_option("--manifest", args->manifest, "A sweep manifest: CSV of path and key columns (see the README)");
  command->add_option("--key-from-name", args->key_pattern,
                      "Run keys from folder or file names, e.g. 'u{u}_v{v}' or 'r{r [deg s^-1]}', of folder contents "
                      "and of files and case folders named on the command line (their path as given)");
  command->add_flag("--prefer-surfaces", args->prefer_surfaces,
                    "Of a force history and surface exports of one run, import the surfaces (in an OpenFOAM case "
                    "folder: the export under its VTK/ rather than postProcessing's forces)");
  command->add_option("--column", args->columns,
                      "Tables and histories: map a header to a component, COMPONENT=HEADER, e.g. X=Drag (repeatable)");
  command->add_option("--unit", args->units, "Unit of a column without one, NAME=UNIT, e.g. X=kN (repeatable)");
  command->add_option("--disturbance", args->disturbance_columns,
                      "Table: a header whose values are a disturbance parameter (repeatable)");
  command->add_option("--ignore", args->ignored, "Table: a header to skip (repeatable)");
  command->add_option("--sign", args->sign,
                      "Tables, monitors, histories: on-body (force on the body; the default) or opposing (positive "
                      "opposes motion)");
  command->add_option("--monitor", args->monitors, "Monitor: COMPONENT=COLUMN, e.g. X=\"USER POINT,Fx\" (repeatable)");
  command
      ->add_option("--average-last", args->average_last,
                   "Monitor: average the last N iterations (as --window last:N; by default the steady window "
                   "is found as for any force history)")
      ->capture_default_str();
  command->add_option("--jobs", args->jobs, "Inputs read in parallel (default: the number of cores)");
  command->add_flag("--replace", args->replace,
                    "Replace the runs of an earlier import of the same file with other settings, and supersede force "
                    "components that runs already have from other files");
  command->add_option("--also", args->also,
                      "Keep this as a second, named reading of a file imported before (e.g. --also mean for pMean "
                      "beside p); an identifier");
  command->add_flag("--quiet", args->quiet, "Print only the summary line");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_import(*args, global); });
}

}  // namespace hydrocoef::cli
