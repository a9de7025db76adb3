// hydrocoef import: read CFD result files and store their runs, all files in
// one transaction.
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "importers/force_table.hpp"
#include "src/core/error.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> files;
  std::string body = "vehicle";
  std::string format = "auto";
  std::vector<std::string> set;
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::vector<std::string> disturbance_columns;
  std::vector<std::string> ignored;
  std::string sign = "on-body";
  std::optional<double> rho;
  std::optional<double> nu;
  std::string ref_point = "0,0,0";
  bool replace = false;
  bool json = false;
};

std::string resolve_format(const std::string& requested, const std::filesystem::path& file) {
  if (requested != "auto") return requested;
  const auto extension = file.extension().string();
  if (extension == ".csv" || extension == ".txt" || extension == ".tsv" || extension == ".dat") return "table";
  throw InputError(SourceLocation{file.string()},
                   "cannot tell the format from the extension '" + extension + "'; expected .csv, .txt, .tsv or "
                   ".dat, or give --format table");
}

void run_import(const ImportArgs& args, const GlobalOptions& global) {
  ForceTableOptions options;
  options.body = args.body;
  for (const auto& text : args.set) options.disturbances.insert(parse_assignment(text, "--set"));
  for (const auto& text : args.columns) {
    auto [component, header] = parse_text_assignment(text, "--column");
    if (!velocity_index(component) && !force_index(component))
      throw InputError("--column '" + text + "': '" + component + "' is not one of u v w p q r X Y Z K M N");
    options.columns[component] = header;
  }
  for (const auto& text : args.units) options.units.insert(parse_text_assignment(text, "--unit"));
  options.disturbance_columns = args.disturbance_columns;
  options.ignored_columns = args.ignored;
  options.sign = parse_sign_convention(args.sign);
  options.fluid.density_kg_m3 = args.rho;
  options.fluid.kinematic_viscosity_m2_s = args.nu;
  options.reference_point_b = parse_triple(args.ref_point, "--ref-point");

  // Parse every file before touching the database: a bad file leaves it as it was.
  std::vector<ImportBatch> batches;
  for (const auto& file : args.files) {
    const std::string format = resolve_format(args.format, file);
    if (format != "table") throw InputError("--format '" + format + "': expected 'table' or 'auto'");
    batches.push_back(read_force_table(file, options));
  }
  Database database(global.database);
  const auto outcomes =
      database.import(batches, args.replace ? ConflictPolicy::Replace : ConflictPolicy::Error);

  if (args.json) {
    nlohmann::json out;
    out["database"] = global.database;
    out["files"] = nlohmann::json::array();
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const auto& o = outcomes[i];
      nlohmann::json file = {{"path", o.path},
                             {"sha256", o.sha256},
                             {"status", o.already_imported ? "already_imported" : "imported"},
                             {"runs_in_file", batches[i].runs.size()},
                             {"runs_created", o.runs_created},
                             {"runs_extended", o.runs_extended},
                             {"components_written", o.components_written}};
      if (o.already_imported) {
        file["previous_path"] = o.previous_path;
        file["previously_imported_at"] = o.previously_imported_at;
      }
      out["files"].push_back(file);
    }
    std::cout << out.dump(2) << '\n';
    return;
  }
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const auto& o = outcomes[i];
    if (o.already_imported) {
      std::cout << o.path << ": already imported (same SHA-256 as " << o.previous_path << ", imported "
                << o.previously_imported_at << "); nothing added\n";
    } else {
      std::cout << o.path << ": imported " << batches[i].runs.size() << " runs of body '" << args.body << "' ("
                << o.runs_created << " new, " << o.runs_extended << " extended, " << o.components_written
                << " force components, sign convention " << args.sign << ")\n";
    }
  }
  std::cout << "database: " << global.database << '\n';
}

}  // namespace

void add_import_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ImportArgs>();
  auto* command = app.add_subcommand("import", "Import CFD result files into the run database");
  command->add_option("files", args->files, "Files to import (all in one transaction)")->required();
  command->add_option("--body", args->body, "Body name the runs belong to")->capture_default_str();
  command->add_option("--format", args->format, "File format: auto (by extension) or table")->capture_default_str();
  command->add_option("--set", args->set, "Disturbance parameter for every run, NAME=VALUE in SI (repeatable)");
  command->add_option("--column", args->columns,
                      "Map a file header to a component, COMPONENT=HEADER, e.g. X=Drag (repeatable)");
  command->add_option("--unit", args->units,
                      "Unit of a component whose header has none, COMPONENT=UNIT, e.g. X=kN (repeatable)");
  command->add_option("--disturbance", args->disturbance_columns,
                      "A header whose values are a disturbance parameter (repeatable)");
  command->add_option("--ignore", args->ignored, "A header to skip (repeatable)");
  command->add_option("--sign", args->sign,
                      "Sign convention of the forces: on-body (force on the body) or opposing (positive "
                      "opposes motion)")
      ->capture_default_str();
  command->add_option("--rho", args->rho, "Fluid density [kg m^-3]");
  command->add_option("--nu", args->nu, "Fluid kinematic viscosity [m^2 s^-1]");
  command->add_option("--ref-point", args->ref_point, "Moment reference point x,y,z [m], body axes")
      ->capture_default_str();
  command->add_flag("--replace", args->replace, "Supersede force components that runs already have");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] { run_import(*args, global); });
}

}  // namespace hydrocoef::cli
