// hydrocoef merge SHARD... --into DB: the databases cluster jobs wrote, one
// each, merged into one; hydrocoef copy --from A --to B: a whole database
// moved to another place or backend (src/store/merge.cpp, copy.cpp);
// hydrocoef migrate: a database's schema brought up to date in place (what
// reading commands never do).
#include <unistd.h>

#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/text.hpp"

namespace hydrocoef::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> shards;
  std::string into;
  bool json = false;
};

struct CopyArgs {
  std::string from, to;
  bool json = false;
};

struct MigrateArgs {
  bool json = false;
};

void print_merge(const std::vector<MergeOutcome>& outcomes, const std::string& into, bool json) {
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& o : outcomes)
      out.push_back({{"shard", o.shard},
                     {"imports_added", o.imports_added},
                     {"imports_already", o.imports_already},
                     {"runs_created", o.runs_created},
                     {"runs_extended", o.runs_extended},
                     {"components", o.components},
                     {"fits_added", o.fits_added},
                     {"fits_already", o.fits_already},
                     {"surfaces_added", o.surfaces_added},
                     {"surfaces_already", o.surfaces_already},
                     {"mesh_studies_added", o.mesh_studies_added},
                     {"mesh_studies_already", o.mesh_studies_already},
                     {"pmm_added", o.pmm_added},
                     {"pmm_already", o.pmm_already}});
    std::cout << escape::json_text({{"into", into}, {"shards", out}}, 2) << '\n';
    return;
  }
  MergeOutcome total;
  for (const auto& o : outcomes) {
    std::cout << printable_text(o.shard, 120) << ": " << o.imports_added << " imports added";
    if (o.imports_already) std::cout << " (" << o.imports_already << " here already)";
    std::cout << ", " << o.runs_created << " runs created, " << o.runs_extended << " extended, " << o.components
              << " force components";
    if (o.fits_added + o.surfaces_added + o.mesh_studies_added + o.pmm_added)
      std::cout << "; " << o.fits_added << " fits, " << o.surfaces_added << " surfaces, " << o.mesh_studies_added
                << " mesh-study rows, " << o.pmm_added << " forced-oscillation runs";
    std::cout << '\n';
    total.imports_added += o.imports_added;
    total.runs_created += o.runs_created;
    total.components += o.components;
  }
  std::cout << "merged " << outcomes.size() << " shard(s) into " << printable_text(into, 120)
            << " in one transaction: " << total.imports_added << " imports, " << total.runs_created << " new runs, "
            << total.components << " force components\n";
}

}  // namespace

void add_merge_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<MergeArgs>();
  auto* command = app.add_subcommand(
      "merge",
      "Merge databases (e.g. one SQLite shard per cluster job) into one, in one transaction: files, imports with "
      "their provenance, runs, force components, statistics, mesh studies, forced-oscillation runs, fits and "
      "surfaces. What is there already adds nothing (merging twice changes nothing); a conflict is refused as an "
      "import would refuse it, and nothing is merged");
  command->add_option("shards", args->shards, "Shard databases (paths, sqlite:PATH or postgresql://...)")->required();
  command->add_option("--into", args->into, "The database to merge into (default: --db)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    const std::string into = args->into.empty() ? global.database : args->into;
    const bool progress = isatty(STDERR_FILENO) != 0;
    RunDatabase database(into);
    const auto outcomes = database.merge(args->shards, [progress](std::size_t done, std::size_t total) {
      if (progress) std::cerr << "\r\033[K[" << done << "/" << total << "] shards read" << std::flush;
    });
    if (progress) std::cerr << "\r\033[K" << std::flush;
    print_merge(outcomes, database.path().string(), args->json);
  });

  auto migrate = std::make_shared<MigrateArgs>();
  auto* migrate_command = app.add_subcommand(
      "migrate",
      "Bring the database (--db) up to this hydrocoef's schema in place, in one transaction. Writing commands do "
      "the same when they open a database; reading commands (runs, query, export, merge's shards...) never change "
      "one: they read an older SQLite file through an upgraded private copy and refuse an older PostgreSQL "
      "database");
  migrate_command->add_flag("--json", migrate->json, "Print JSON");
  migrate_command->callback([migrate, &global] {
    RunDatabase database(global.database, RunDatabase::OpenMode::MustExist);
    const int from = database.opened_at_version();
    const int to = database.schema_version();
    if (migrate->json) {
      std::cout << escape::json_text({{"database", database.path().string()}, {"from", from}, {"to", to}}, 2) << '\n';
      return;
    }
    std::cout << printable_text(database.path().string(), 120) << ": ";
    if (from == to)
      std::cout << "at schema version " << to << " already; nothing changed\n";
    else
      std::cout << "schema version " << from << " upgraded to " << to << '\n';
  });

  auto copy = std::make_shared<CopyArgs>();
  auto* copy_command = app.add_subcommand(
      "copy",
      "Copy a whole database into an empty one, ids included, e.g. from an SQLite file to a PostgreSQL server or "
      "back; one transaction");
  copy_command->add_option("--from", copy->from, "The database to copy")->required();
  copy_command->add_option("--to", copy->to, "An empty database (created when it is a new SQLite file)")->required();
  copy_command->add_flag("--json", copy->json, "Print JSON");
  copy_command->callback([copy] {
    RunDatabase source(copy->from, RunDatabase::OpenMode::ReadOnly);
    RunDatabase target(copy->to);
    const auto copied = target.copy_from(source);
    if (copy->json) {
      nlohmann::json tables = nlohmann::json::object();
      for (const auto& [table, rows] : copied) tables[table] = rows;
      std::cout << escape::json_text(
                       {{"from", source.path().string()}, {"to", target.path().string()}, {"rows", tables}}, 2)
                << '\n';
      return;
    }
    std::size_t rows = 0;
    for (const auto& [table, n] : copied) rows += n;
    std::cout << "copied " << rows << " rows from " << printable_text(source.path().string(), 120) << " to "
              << printable_text(target.path().string(), 120) << ":";
    for (const auto& [table, n] : copied)
      if (n) std::cout << ' ' << table << ' ' << n;
    std::cout << '\n';
  });
}

}  // namespace hydrocoef::cli
