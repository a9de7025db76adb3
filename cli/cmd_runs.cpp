// hydrocoef runs: list stored runs with their key and force components;
// runs show ID: one run with its full provenance; runs delete: remove runs
// (by id, --where selection or --source file) in one transaction; runs
// --coefficients: the runs' non-dimensional coefficients, Re and Fn. The
// library reads, deletes and renders (hydrocoef/database.hpp, records.hpp,
// reference.hpp).
#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/records.hpp"
#include "hydrocoef/reference.hpp"

namespace hydrocoef::cli {
namespace {

struct RunsArgs {
  std::optional<std::string> body;
  SelectionArgs selection;
  bool json = false;
  bool csv = false;
  bool coefficients = false;
  std::string area;
};

void run_runs(const RunsArgs& args, const GlobalOptions& global) {
  const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  if (args.coefficients) {
    const auto table = hydrocoef::run_coefficients(
        database, {args.body.value_or(""), args.selection.where, args.selection.exclude_runs, args.area});
    std::cout << (args.csv ? table.csv() : args.json ? table.json() : table.text());
    return;
  }
  const auto runs = database.runs(args.selection.where, args.body.value_or(""), args.selection.exclude_runs);
  std::cout << (args.csv ? runs.csv() : args.json ? runs.json() : runs.text());
}

struct ShowArgs {
  std::int64_t id = 0;
  bool json = false;
};

void run_show(const ShowArgs& args, const GlobalOptions& global) {
  const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadOnly);
  const auto run = hydrocoef::show_run(database, args.id);
  std::cout << (args.json ? run.json() : run.text());
}

struct DeleteArgs {
  hydrocoef::DeleteRunsOptions options;
  SelectionArgs selection;
  bool json = false;
};

void run_delete(const DeleteArgs& args, const GlobalOptions& global) {
  auto options = args.options;
  options.where = args.selection.where;
  options.exclude_runs = args.selection.exclude_runs;
  auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
  const auto deleted = hydrocoef::delete_runs(database, options);
  std::cout << (args.json ? deleted.json() : deleted.text());
}

}  // namespace

void add_runs_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<RunsArgs>();
  auto* command = app.add_subcommand("runs", "List the runs in the database");
  command->add_option("--body", args->body, "Only runs of this body");
  add_selection_options(*command, args->selection);
  command->add_flag("--json", args->json, "Print JSON");
  command->add_flag("--csv", args->csv,
                    "Print CSV: id, body, u..r, disturbances, X..N (forces on the body, SI) and the source files");
  auto* coefficients = command->add_flag(
      "--coefficients", args->coefficients,
      "Print the non-dimensional coefficients instead: C_X..C_N = F/(1/2 rho U^2 A), M/(1/2 rho U^2 A L), "
      "Re = U L/nu, Fn = U/sqrt(g L), with the body's reference data (hydrocoef body set)");
  command
      ->add_option("--area", args->area,
                   "With --coefficients: the reference area of this name (default: the "
                   "body's default area)")
      ->needs(coefficients);
  command->callback([args, command, &global] {
    // "runs" lists only when no subcommand (show, delete) was given.
    if (!command->get_subcommands().empty()) return;
    run_runs(*args, global);
  });

  auto show = std::make_shared<ShowArgs>();
  auto* show_command =
      command->add_subcommand("show", "One run with its full provenance: every force's file, import and settings");
  show_command->add_option("id", show->id, "Run id (hydrocoef runs lists them)")->required();
  show_command->add_flag("--json", show->json, "Print JSON");
  show_command->callback([show, &global] { run_show(*show, global); });

  auto remove = std::make_shared<DeleteArgs>();
  auto* delete_command = command->add_subcommand(
      "delete",
      "Delete runs by id, by --where selection or by --source file, in one transaction; fits and surfaces "
      "built from them become stale");
  delete_command->add_option("ids", remove->options.ids, "Run ids");
  delete_command->add_option("--body", remove->options.body, "With --where or --source: only runs of this body");
  add_selection_options(*delete_command, remove->selection);
  delete_command->add_option("--source", remove->options.source, "Runs with a force component from this file");
  delete_command->add_flag("--json", remove->json, "Print JSON");
  delete_command->callback([remove, &global] { run_delete(*remove, global); });
}

}  // namespace hydrocoef::cli
