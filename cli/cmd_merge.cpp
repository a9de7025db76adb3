// hydrocoef merge SHARD... --into DB: the databases cluster jobs wrote, one
// each, merged into one; hydrocoef copy --from A --to B: a whole database
// moved to another place or backend (src/store/merge.cpp, copy.cpp);
// hydrocoef migrate: a database's schema brought up to date in place (what
// reading commands never do).
#include <unistd.h>

#include <iostream>
#include <memory>

#include "cli/common.hpp"
#include "hydrocoef/records.hpp"

namespace hydrocoef::cli {
namespace {

struct MergeArgs {
  hydrocoef::MergeOptions options;
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

}  // namespace

void add_merge_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<MergeArgs>();
  auto* command = app.add_subcommand(
      "merge",
      "Merge databases (e.g. one SQLite shard per cluster job) into one, in one transaction: files, imports with "
      "their provenance, runs, force components, statistics, mesh studies, forced-oscillation runs, fits and "
      "surfaces. What is there already adds nothing (merging twice changes nothing); a conflict is refused as an "
      "import would refuse it, and nothing is merged");
  command->add_option("shards", args->options.shards, "Shard databases (paths, sqlite:PATH or postgresql://...)")
      ->required();
  command->add_option("--into", args->into, "The database to merge into (default: --db)");
  command->add_flag("--json", args->json, "Print JSON");
  command->callback([args, &global] {
    const bool progress = isatty(STDERR_FILENO) != 0;
    auto options = args->options;
    options.progress = [progress](std::size_t done, std::size_t total) {
      if (progress) std::cerr << "\r\033[K[" << done << "/" << total << "] shards read" << std::flush;
    };
    auto database =
        hydrocoef::Database::open(args->into.empty() ? global.database : args->into, hydrocoef::OpenMode::Create);
    const auto merged = hydrocoef::merge_databases(database, options);
    if (progress) std::cerr << "\r\033[K" << std::flush;
    std::cout << (args->json ? merged.json() : merged.text());
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
    const auto database = hydrocoef::Database::open(global.database, hydrocoef::OpenMode::ReadWrite);
    const auto migrated = hydrocoef::migration(database);
    std::cout << (migrate->json ? migrated.json() : migrated.text());
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
    const auto source = hydrocoef::Database::open(copy->from, hydrocoef::OpenMode::ReadOnly);
    auto target = hydrocoef::Database::open(copy->to, hydrocoef::OpenMode::Create);
    const auto copied = hydrocoef::copy_database(source, target);
    std::cout << (copy->json ? copied.json() : copied.text());
  });
}

}  // namespace hydrocoef::cli
