// hydrocoef runs: list stored runs with their key and force components;
// runs show ID: one run with its full provenance; runs delete: remove runs
// (by id, --where selection or --source file) in one transaction.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cli/common.hpp"
#include "cli/runs_output.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/sign_convention.hpp"
#include "src/pipeline/run_curation.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::cli {
namespace {

struct RunsArgs {
  std::optional<std::string> body;
  SelectionArgs selection;
  bool json = false;
  bool csv = false;
};

void run_runs(const RunsArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  RunFilter filter;
  filter.body = args.body;
  const auto runs = selected_runs(database, filter, parse_selection(args.selection.where, args.selection.exclude_runs));
  if (args.csv) {
    print_runs_csv(runs);
  } else if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& run : runs) out.push_back(run_json(run));
    std::cout << escape::json_text(out, 2) << '\n';
  } else {
    print_runs_table(runs, args.body, global.database);
  }
}

struct ShowArgs {
  std::int64_t id = 0;
  bool json = false;
};

void run_show(const ShowArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::ReadOnly);
  const auto all = database.runs();
  const auto found = std::find_if(all.begin(), all.end(), [&](const StoredRun& run) { return run.id == args.id; });
  if (found == all.end())
    throw InputError(SourceLocation{global.database},
                     "no run " + std::to_string(args.id) + "; 'hydrocoef runs' lists them");
  const StoredRun& run = *found;
  std::map<std::int64_t, ImportRecord> imports;
  for (const auto& force : run.tau_b)
    if (force && force->import_id && !imports.count(force->import_id))
      if (auto record = database.import_record(force->import_id)) imports.emplace(force->import_id, std::move(*record));
  print_run(run, imports, args.json);
}

struct DeleteArgs {
  std::vector<std::int64_t> ids;
  std::optional<std::string> body;
  SelectionArgs selection;
  std::optional<std::string> source;
  bool json = false;
};

void run_delete(const DeleteArgs& args, const GlobalOptions& global) {
  RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
  const DeleteOutcome outcome = delete_runs(
      database, RunDeletion{args.ids, args.body, args.selection.where, args.selection.exclude_runs, args.source});
  if (args.json) {
    std::cout << escape::json_text({{"deleted_runs", outcome.runs},
                                    {"deleted_components", outcome.components},
                                    {"fits_made_stale", outcome.fits_made_stale},
                                    {"surfaces_made_stale", outcome.surfaces_made_stale},
                                    {"imports_removed", outcome.imports_removed}},
                                   2)
              << '\n';
    return;
  }
  std::cout << "deleted " << outcome.runs << (outcome.runs == 1 ? " run" : " runs") << " (" << outcome.components
            << " force components) from " << escape::one_line(global.database) << "; " << outcome.fits_made_stale
            << " fits and " << outcome.surfaces_made_stale
            << " surfaces became stale (hydrocoef fits / surface list show them; "
            << "surface rebuild --stale builds the surfaces again)\n";
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
  delete_command->add_option("ids", remove->ids, "Run ids");
  delete_command->add_option("--body", remove->body, "With --where or --source: only runs of this body");
  add_selection_options(*delete_command, remove->selection);
  delete_command->add_option("--source", remove->source, "Runs with a force component from this file");
  delete_command->add_flag("--json", remove->json, "Print JSON");
  delete_command->callback([remove, &global] { run_delete(*remove, global); });
}

}  // namespace hydrocoef::cli
