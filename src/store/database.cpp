#include "src/store/database.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>
#include <unordered_map>

#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/core/names.hpp"
#include "src/core/numbers.hpp"
#include "src/core/text.hpp"
#include "src/core/version.hpp"
#include "src/store/backend.hpp"
#include "src/store/build_spec_migration.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/dialect.hpp"
#include "src/store/location.hpp"
#include "src/store/migrations.hpp"
#include "src/store/run_rows.hpp"
#include "src/store/schema_check.hpp"

namespace hydrocoef {
namespace {

using store::canonical;
using store::same_value;

constexpr double kFilterTolerance = 1e-9;

std::string force_name(std::size_t i) { return std::string(kForceNames[i]); }

/// The settings two imports of one file differ in, for the refusal of a
/// re-import with other settings: "rho: 998.2 (command line) then 1025
/// (sidecar a.vtp.json)", at most four of them.
std::string settings_difference(const std::string& before, const std::string& after) {
  if (before.empty()) return "the earlier import's settings are not recorded: it was made by an older hydrocoef";
  const auto old_json = nlohmann::json::parse(before, nullptr, false);
  const auto new_json = nlohmann::json::parse(after.empty() ? "{}" : after, nullptr, false);
  if (!old_json.is_object() || !new_json.is_object()) return "settings differ";
  const auto describe_setting = [](const nlohmann::json& setting) {
    if (!setting.is_object()) return std::string("not set");
    return printable_text(escape::json_text(setting.value("value", nlohmann::json())), 40) + " (" +
           printable_text(setting.value("source", std::string("?")), 40) + ")";
  };
  std::vector<std::string> differences;
  std::set<std::string> keys;
  for (const auto& [key, value] : old_json.items()) keys.insert(key);
  for (const auto& [key, value] : new_json.items()) keys.insert(key);
  for (const auto& key : keys) {
    const auto a = old_json.contains(key) ? old_json.at(key) : nlohmann::json();
    const auto b = new_json.contains(key) ? new_json.at(key) : nlohmann::json();
    const auto value_of = [](const nlohmann::json& s) {
      return s.is_object() ? s.value("value", nlohmann::json()) : nlohmann::json();
    };
    if (value_of(a) == value_of(b)) continue;
    differences.push_back(printable_text(key, 40) + ": " + describe_setting(a) + " then " + describe_setting(b));
  }
  if (differences.empty()) return "the same values from other places";
  std::string out;
  for (std::size_t i = 0; i < differences.size() && i < 4; ++i) out += (i ? "; " : "") + differences[i];
  if (differences.size() > 4) out += "; and " + std::to_string(differences.size() - 4) + " more";
  return out;
}

}  // namespace

std::string utc_timestamp_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return text;
}

namespace {

store::Connection open_connection(const store::DatabaseLocation& location, Database::OpenMode mode) {
  if (location.backend == store::Backend::PostgreSQL)
    return store::Connection::postgresql(
        location.target, location.display,
        mode == Database::OpenMode::ReadOnly ? store::Access::ReadOnly : store::Access::ReadWrite);
  const std::filesystem::path path(location.target);
  if (mode != Database::OpenMode::CreateIfMissing && !std::filesystem::exists(path))
    throw InputError(SourceLocation{path.string()},
                     "no database here; create one with 'hydrocoef import' or give --db PATH");
  switch (mode) {
    case Database::OpenMode::CreateIfMissing: return {path.string(), store::Access::ReadWriteCreate};
    case Database::OpenMode::MustExist: return {path.string(), store::Access::ReadWrite};
    case Database::OpenMode::ReadOnly: break;
  }
  // A reader that may write the file and its folder opens it read-write (and
  // never writes): SQLite then removes the WAL's -wal and -shm files when it
  // closes, as it cannot for a read-only connection. Elsewhere: read-only.
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (::access(path.c_str(), W_OK) == 0 && ::access(folder.c_str(), W_OK) == 0)
    return {path.string(), store::Access::ReadWrite};
  return {path.string(), store::Access::ReadOnly};
}

/// A database that cannot be opened normally where it is read-only (its WAL
/// index, the -shm file, is missing and cannot be made) is read as immutable,
/// which ignores the -wal file: refused instead when a -wal file that is not
/// empty is beside it, as its committed changes would go unread.
void refuse_unread_wal(const std::filesystem::path& path) {
  const std::filesystem::path wal = path.string() + "-wal";
  std::error_code error;
  const auto size = std::filesystem::file_size(wal, error);
  if (error || size == 0) return;
  throw InputError(SourceLocation{path.string()},
                   "a write-ahead log (" + printable_text(wal.string(), 200) + ", " + std::to_string(size) +
                       " bytes) beside the database cannot be read here (no -shm file, and none can be made in a "
                       "read-only folder), so its changes would be left unread; expected it checkpointed: open the "
                       "database once where its folder is writable, or have its owner run sqlite3 " +
                       printable_text(path.string(), 200) + " 'PRAGMA wal_checkpoint(TRUNCATE)'");
}

/// What every connection of a Database runs first.
void configure(store::Connection& connection) {
  if (connection.backend() != store::Backend::SQLite) return;
  connection.execute("PRAGMA foreign_keys = ON");
  // FULL: the WAL is synced at every commit, so a committed import survives a
  // power loss as well as a killed process. NORMAL would already keep it after
  // SIGKILL (the WAL is in the OS page cache), but imports are one transaction
  // per call and one fsync per call costs nothing next to reading CFD files.
  connection.execute("PRAGMA synchronous = FULL");
}

/// The schema version as stored (any 64-bit value in a received file):
/// SQLite's PRAGMA user_version; on PostgreSQL the one row of table
/// hydrocoef_schema, or 0 when there is no such table.
std::int64_t stored_schema_version(store::Connection& connection) {
  if (connection.backend() == store::Backend::PostgreSQL) {
    // A query of the catalog (not to_regclass, whose cache may miss a table
    // another session has just committed): what is committed now.
    auto exists = connection.prepare(
        "SELECT count(*) FROM pg_catalog.pg_tables WHERE schemaname = current_schema() AND "
        "tablename = 'hydrocoef_schema'");
    exists.step();
    if (exists.get_int(0) == 0) return 0;
    auto version = connection.prepare("SELECT version FROM hydrocoef_schema");
    if (!version.step()) return -1;
    return version.get_int(0);
  }
  auto statement = connection.prepare("PRAGMA user_version");
  statement.step();
  return statement.get_int(0);
}

}  // namespace

Database::Database(const std::filesystem::path& path, OpenMode mode)
    : Database(store::parse_database_location(path.string()), mode) {}

Database::Database(const store::DatabaseLocation& location, OpenMode mode)
    : path_(location.display), connection_(open_connection(location, mode)), read_only_(mode == OpenMode::ReadOnly) {
  if (read_only_ && connection_.backend() == store::Backend::SQLite) {
    // A WAL database in a folder where the -shm file cannot be made (a
    // read-only share) cannot be opened normally: read it as immutable,
    // unless a -wal file beside it holds changes that would go unread.
    try {
      (void)schema_version();
    } catch (const InputError&) {
      refuse_unread_wal(path_);
      connection_ = store::Connection(path_.string(), store::Access::Immutable);
    }
  }
  configure(connection_);
  // Reading the schema is the first access to the file's content: a foreign or
  // damaged file fails here with SQLite's "file is not a database".
  const std::string check = integrity_check();
  if (check != "ok")
    throw InputError(SourceLocation{path_.string()},
                     "database fails its integrity check: " + printable_text(check, 200));
  const int version = checked_schema_version();
  // A server's schema is always there: one that must hold a database and has
  // no hydrocoef tables yet is refused as a missing SQLite file is.
  const bool must_hold_data =
      read_only_ || (mode == OpenMode::MustExist && connection_.backend() == store::Backend::PostgreSQL);
  if (must_hold_data && version == 0) {
    check_schema(0);
    throw InputError(SourceLocation{path_.string()},
                     "an empty database (no hydrocoef data yet); expected one made by 'hydrocoef import'");
  }
  opened_at_version_ = version;
  if (version < latest_schema_version()) {
    if (read_only_) {
      // Reading never writes, so never upgrades: an SQLite file is read
      // through an upgraded private copy (the file stays byte for byte as it
      // was); a PostgreSQL database is refused with how to upgrade it.
      check_schema(version);
      if (connection_.backend() != store::Backend::SQLite)
        throw InputError(SourceLocation{path_.string()},
                         "database is at schema version " + std::to_string(version) + ", this hydrocoef reads " +
                             std::to_string(latest_schema_version()) +
                             " and a reading command does not upgrade it: run 'hydrocoef --db " +
                             printable_text(path_.string(), 200) + " migrate' (or any writing command) once");
      connection_ = store::Connection::sqlite_private_copy(connection_);
      configure(connection_);
      migrate();
      // Writes through the copy would be lost: it refuses them.
      connection_.execute("PRAGMA query_only = ON");
    } else {
      migrate();
    }
  } else {
    check_schema(version);
  }
}

// Write-ahead log, switched on after the first write that succeeds (a
// migration, an import, a fit...), so that a file that is refused, or a
// write that fails, leaves the file byte for byte as it was (the switch
// rewrites the header): readers never wait for an import and never see part
// of one, and a killed import leaves only an uncommitted WAL tail that the
// next open discards. The mode is stored in the file. (PostgreSQL: nothing.)
void Database::use_wal() {
  if (!read_only_) connection_.use_wal();
}

int Database::latest_schema_version() { return static_cast<int>(store::migrations().size()); }

int Database::schema_version() { return static_cast<int>(stored_schema_version(connection_)); }

std::string Database::integrity_check() {
  // A PostgreSQL server keeps its own pages whole; what it holds is checked
  // by the schema check and by every row read.
  if (connection_.backend() == store::Backend::PostgreSQL) return "ok";
  auto statement = connection_.prepare("PRAGMA quick_check");
  std::string out;
  while (statement.step()) {
    if (!out.empty()) out += "; ";
    out += statement.get_text(0);
  }
  // SQLite's report may span lines ("*** in database main ***\nPage 19: ..."):
  // one line, so that the CLI's error stays one line.
  std::replace(out.begin(), out.end(), '\n', ' ');
  return out;
}

int Database::checked_schema_version() {
  const std::int64_t version = stored_schema_version(connection_);
  const int latest = latest_schema_version();
  if (version > latest)
    throw InputError(SourceLocation{path_.string()}, "database is at schema version " + std::to_string(version) +
                                                         ", this hydrocoef knows up to " + std::to_string(latest) +
                                                         "; use a newer hydrocoef");
  if (version < 0)
    throw InputError(SourceLocation{path_.string()}, "database has schema version " + std::to_string(version) +
                                                         "; expected 0 to " + std::to_string(latest) +
                                                         " (a file changed by another program)");
  return static_cast<int>(version);
}

void Database::check_schema(int version) {
  if (connection_.backend() == store::Backend::PostgreSQL) {
    if (const auto difference = store::postgresql_schema_difference(connection_, version))
      throw InputError(SourceLocation{path_.string()},
                       "database (schema version " + std::to_string(version) + ") " + *difference +
                           "; expected exactly the schema hydrocoef creates, so a database changed by another "
                           "program is refused");
    return;
  }
  const auto found = store::schema_of(connection_);
  if (version == 0) {
    if (!found.empty())
      throw InputError(SourceLocation{path_.string()},
                       "an SQLite database with tables but no hydrocoef schema version; expected a hydrocoef "
                       "database or a new file");
    return;
  }
  if (const auto difference = store::schema_difference(store::expected_schema(version), found))
    throw InputError(SourceLocation{path_.string()},
                     "database (schema version " + std::to_string(version) + ") " + *difference +
                         "; expected exactly the schema hydrocoef creates, so a database changed by another program "
                         "is refused");
}

void Database::migrate() {
  const bool sqlite = connection_.backend() == store::Backend::SQLite;
  // SQLite migrations may rebuild tables, which needs foreign keys off; they
  // are checked before the commit instead. The pragma cannot change inside a
  // transaction, so it is set around it. (PostgreSQL checks every reference
  // as it is made.)
  if (sqlite) connection_.execute("PRAGMA foreign_keys = OFF");
  {
    store::Transaction transaction(connection_);
    // Read again under the write lock: another process may have created or
    // upgraded the schema since this one looked.
    const int version = checked_schema_version();
    check_schema(version);
    const int latest = latest_schema_version();
    if (!sqlite && version == 0) connection_.execute("CREATE TABLE hydrocoef_schema (version BIGINT NOT NULL)");
    for (int next = version + 1; next <= latest; ++next) {
      const store::Migration& migration = store::migrations()[static_cast<std::size_t>(next - 1)];
      connection_.execute(sqlite ? std::string(migration.sql)
                                 : store::postgresql_migration(migration.postgresql_sql()));
      if (next == store::kBuildSpecMigration) store::convert_surface_build_options(connection_, path_.string());
      if (sqlite) {
        connection_.execute("PRAGMA user_version = " + std::to_string(next));
      } else {
        connection_.execute("DELETE FROM hydrocoef_schema; INSERT INTO hydrocoef_schema VALUES (" +
                            std::to_string(next) + ")");
      }
    }
    if (sqlite) {
      auto foreign = connection_.prepare("PRAGMA foreign_key_check");
      if (foreign.step())
        throw InputError(SourceLocation{path_.string()},
                         "database: table '" + printable_text(foreign.get_text(0), 60) + "', row " +
                             std::to_string(foreign.get_int(1)) + " refers to a missing row of table '" +
                             printable_text(foreign.get_text(2), 60) + "'; expected every reference to hold");
      foreign.reset();
    }
    transaction.commit();
  }
  if (sqlite) connection_.execute("PRAGMA foreign_keys = ON");
  use_wal();
}

std::int64_t Database::body_id(const std::string& name, bool create) {
  auto find = connection_.prepare("SELECT id FROM body WHERE name = ?");
  find.bind(1, name);
  if (find.step()) return find.get_int(0);
  if (!create) return -1;
  auto insert = connection_.prepare("INSERT INTO body(name) VALUES (?) RETURNING id");
  insert.bind(1, name);
  return store::returned_id(insert);
}

double StoredForce::standard_uncertainty() const {
  const double se = statistics ? statistics->values.standard_error : 0.0;
  const double given = value.uncertainty.value_or(0.0);
  return std::hypot(se, given, numerical_uncertainty.value_or(0.0));
}

std::map<std::string, double> physical_disturbances(const std::map<std::string, double>& disturbances,
                                                    const std::string& mesh_parameter) {
  std::map<std::string, double> out = disturbances;
  out.erase(mesh_parameter);
  out.erase(std::string(kCellCountParameter));
  out.erase(std::string(kCellSizeParameter));
  return out;
}

std::optional<std::int64_t> Database::find_run_id(std::int64_t body, const RunKey& key) {
  auto find = connection_.prepare(
      "SELECT id FROM run WHERE body_id = ? AND u = ? AND v = ? AND w = ? AND p = ? AND q = ? AND r = ? "
      "AND disturbance_key = ?");
  find.bind(1, body);
  for (int i = 0; i < 6; ++i) find.bind(2 + i, canonical(key.nu_b[static_cast<std::size_t>(i)]));
  find.bind(8, disturbance_signature(key.disturbances));
  if (find.step()) return find.get_int(0);
  return std::nullopt;
}

std::vector<ImportOutcome> Database::import(const std::vector<ImportBatch>& batches, ConflictPolicy policy) {
  ImportOptions options;
  options.components = policy;
  options.replace = policy == ConflictPolicy::Replace;
  return import(batches, options);
}

std::vector<ImportOutcome> Database::import(const std::vector<ImportBatch>& batches, const ImportOptions& options) {
  const ConflictPolicy policy = options.components;
  if (!options.also.empty()) check_name(NameKind::Parameter, options.also, {}, "--also");
  std::vector<ImportOutcome> outcomes;
  store::Transaction transaction(connection_);
  const std::string now = utc_timestamp_now();

  auto find_source = connection_.prepare("SELECT id FROM source_file WHERE sha256 = ?");
  auto find_import = connection_.prepare(
      "SELECT id, settings_key, settings, path, imported_at FROM import WHERE source_id = ? AND reading = ?");
  auto insert_import = connection_.prepare(
      "INSERT INTO import(source_id, reading, settings_key, settings, path, resolved_path, importer, importer_version, "
      "hydrocoef_version, imported_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?) RETURNING id");
  auto insert_source = connection_.prepare(
      "INSERT INTO source_file(path, sha256, size_bytes, importer, importer_version, imported_at) "
      "VALUES (?, ?, ?, ?, ?, ?) RETURNING id");
  store::RunRows rows(connection_);
  auto existing_force = connection_.prepare(
      "SELECT s.path, f.source_line, s.imported_at FROM run_force f JOIN source_file s ON s.id = f.source_id "
      "WHERE f.run_id = ? AND f.component = ?");

  // A component's statistics go with it: a value written without
  // statistics leaves none of an earlier value behind.
  auto drop_statistics = connection_.prepare("DELETE FROM run_force_statistics WHERE run_id = ? AND component = ?");

  for (const auto& batch : batches) {
    ImportOutcome outcome;
    outcome.path = batch.source.path;
    outcome.sha256 = batch.source.sha256;
    outcome.reading = options.also;
    // The file's bytes, once per database.
    std::int64_t source_id = 0;
    find_source.bind(1, batch.source.sha256);
    if (find_source.step()) {
      source_id = find_source.get_int(0);
      find_source.reset();
    } else {
      find_source.reset();
      insert_source.bind(1, batch.source.path)
          .bind(2, batch.source.sha256)
          .bind(3, static_cast<std::int64_t>(batch.source.size_bytes))
          .bind(4, batch.source.importer)
          .bind(5, batch.source.importer_version)
          .bind(6, now);
      source_id = store::returned_id(insert_source);
    }
    // The import: those bytes read with these settings.
    find_import.bind(1, source_id).bind(2, options.also);
    if (find_import.step()) {
      const std::int64_t previous = find_import.get_int(0);
      const std::string previous_key = find_import.get_text(1);
      const std::string previous_settings = find_import.get_text(2);
      outcome.previous_path = find_import.get_text(3);
      outcome.previously_imported_at = find_import.get_text(4);
      find_import.reset();
      if (previous_key == batch.source.settings_key) {
        outcome.already_imported = true;
        outcome.import_id = previous;
        outcomes.push_back(outcome);
        continue;
      }
      if (!options.replace)
        throw InputError(SourceLocation{batch.source.path},
                         "already imported on " + outcome.previously_imported_at + " from '" +
                             printable_text(outcome.previous_path, 80) + "'" +
                             (options.also.empty() ? "" : " as reading '" + options.also + "'") +
                             " with other settings (" + settings_difference(previous_settings, batch.source.settings) +
                             "); give --replace to replace the runs of that import, or --also NAME to keep both "
                             "readings of the file");
      outcome.replaced = true;
      remove_import_forces(previous);
      connection_.prepare("DELETE FROM import WHERE id = ?").bind(1, previous).run();
    } else {
      find_import.reset();
    }
    insert_import.bind(1, source_id)
        .bind(2, options.also)
        .bind(3, batch.source.settings_key)
        .bind(4, batch.source.settings)
        .bind(5, batch.source.path)
        .bind(6, batch.source.resolved_path)
        .bind(7, batch.source.importer)
        .bind(8, batch.source.importer_version)
        .bind(9, std::string_view(kVersion))
        .bind(10, now);
    const std::int64_t import_id = store::returned_id(insert_import);
    outcome.import_id = import_id;

    for (const auto& run : batch.runs) {
      const SourceLocation where{batch.source.path, run.source_line, 0};
      // Names are checked where they enter; the store checks again, so that
      // no caller of the library can store a name that breaks the rule.
      check_name(NameKind::Body, run.key.body, where, "the run's body");
      for (const auto& [name, value] : run.key.disturbances) {
        check_name(NameKind::Parameter, name, where, "a disturbance");
        if (!std::isfinite(value))
          throw InputError(where, "disturbance '" + name + "' is not a finite number; expected one");
      }
      const std::int64_t body = body_id(run.key.body, true);
      std::int64_t run_id = 0;
      bool created = false;
      if (const auto existing = find_run_id(body, run.key)) {
        run_id = *existing;
        rows.check_and_fill(run_id, run.key, run.fluid, run.reference_point_b, where);
      } else {
        run_id = rows.insert(body, run.key, run.fluid, run.reference_point_b);
        created = true;
        ++outcome.runs_created;
      }

      bool extended = false;
      for (std::size_t i = 0; i < 6; ++i) {
        if (!run.tau_b[i]) continue;
        existing_force.bind(1, run_id).bind(2, force_name(i));
        if (existing_force.step()) {
          const std::string previous = existing_force.get_text(0) + ":" + existing_force.get_text(1) + " (imported " +
                                       existing_force.get_text(2) + ")";
          existing_force.reset();
          if (policy == ConflictPolicy::Error)
            throw InputError(where, "run " + describe(run.key) + " already has " + force_name(i) + " from " + previous +
                                        "; give --replace to supersede it");
        } else {
          existing_force.reset();
        }
        const auto& force = *run.tau_b[i];
        rows.write_force(run_id, i, force, run.sign, source_id, run.source_line, import_id);
        drop_statistics.bind(1, run_id).bind(2, force_name(i)).run();
        if (run.statistics && run.statistics->components[i]) {
          const RunStatistics& statistics = *run.statistics;
          const ComponentWindow& window = statistics.windows[i];
          rows.write_statistics(run_id, i,
                                StoredStatistics{statistics.abscissa, window.method, window.first, window.last,
                                                 window.samples, window.flags, *statistics.components[i],
                                                 statistics.convergence, statistics.convergence_reason});
        }
        ++outcome.components_written;
        extended = true;
      }
      if (extended && !created) ++outcome.runs_extended;
      if (run.surface) rows.write_surface(run_id, source_id, *run.surface);
      // The trace of the latest history; a component without one takes an earlier one away.
      if (run.trace && run.statistics)
        rows.write_trace(run_id, *run.trace);
      else if (extended)
        rows.drop_trace(run_id);
    }
    outcomes.push_back(outcome);
  }
  transaction.commit();
  use_wal();
  return outcomes;
}

namespace {

/// A run's key as read: its disturbance_key column must be the canonical text
/// of its run_disturbance rows (the column, with the velocity, keeps each key
/// once in the table; the rows are what every reader uses). A run whose
/// column and rows disagree could be another run's key, and merge into it or
/// be listed as it; it is refused naming its table and row.
void check_run_keys(const std::string& db, const std::vector<StoredRun>& runs, const std::vector<std::string>& keys) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const StoredRun& run = runs[i];
    const std::string signature = disturbance_signature(run.key.disturbances);
    if (keys[i] != signature)
      throw InputError(SourceLocation{db},
                       "table 'run', row " + std::to_string(run.id) + ": column 'disturbance_key' is '" +
                           printable_text(keys[i], 80) + "' but its rows in table 'run_disturbance' give '" +
                           printable_text(signature, 80) +
                           "'; expected the key of its disturbances (a database changed by another program)");
  }
}

}  // namespace

std::vector<StoredRun> Database::load_runs(std::optional<std::int64_t> body, std::optional<std::int64_t> run) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT run.id, body.name, u, v, w, p, q, r, density, kinematic_viscosity, ref_x, ref_y, ref_z, body.id, "
      "disturbance_key FROM run JOIN body ON body.id = run.body_id WHERE TRUE";
  if (body) sql += " AND run.body_id = ?1";
  if (run) sql += " AND run.id = ?2";
  sql += " ORDER BY body.name, u, v, w, p, q, r, disturbance_key";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  if (run) select.bind(2, *run);

  std::vector<StoredRun> out;
  std::vector<std::string> stored_keys;  // each run's disturbance_key column, by position in out
  std::unordered_map<std::int64_t, std::size_t> index;
  const std::string db = path_.string();
  while (select.step()) {
    const store::CheckedRow row(select, db, "run", select.get_int(0));
    StoredRun stored;
    stored.id = select.get_int(0);
    stored.key.body = store::CheckedRow(select, db, "body", select.get_int(13)).name(1, NameKind::Body);
    for (int i = 0; i < 6; ++i) stored.key.nu_b[static_cast<std::size_t>(i)] = row.real(2 + i);
    stored.fluid.density_kg_m3 = row.optional_positive(8);
    stored.fluid.kinematic_viscosity_m2_s = row.optional_positive(9);
    for (int i = 0; i < 3; ++i) stored.reference_point_b[static_cast<std::size_t>(i)] = row.real(10 + i);
    stored_keys.push_back(row.text(14, std::size_t{1} << 20));
    index[stored.id] = out.size();
    out.push_back(std::move(stored));
  }
  if (out.empty()) return out;

  auto disturbances = connection_.prepare("SELECT run_id, name, value FROM run_disturbance");
  while (disturbances.step()) {
    const auto found = index.find(disturbances.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(disturbances, db, "run_disturbance", disturbances.get_int(0));
    std::string name = row.name(1, NameKind::Parameter);
    if (std::find(kVelocityNames.begin(), kVelocityNames.end(), name) != kVelocityNames.end())
      row.fail(1, "a disturbance parameter, not a velocity component (u v w p q r are columns of table 'run')");
    out[found->second].key.disturbances[std::move(name)] = row.real(2);
  }
  check_run_keys(db, out, stored_keys);
  auto forces = connection_.prepare(
      "SELECT f.run_id, f.component, f.total, f.pressure, f.viscous, f.sign_convention, f.source_id, s.path, "
      "coalesce(f.source_line, 0), coalesce(f.import_id, 0), f.uncertainty FROM run_force f JOIN source_file s ON "
      "s.id = f.source_id");
  while (forces.step()) {
    const auto found = index.find(forces.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(forces, db, "run_force", forces.get_int(0));
    const auto component = force_index(row.one_of(1, {"X", "Y", "Z", "K", "M", "N"}));
    StoredForce force;
    force.value.total = row.real(2);
    force.value.pressure = row.optional_real(3);
    force.value.viscous = row.optional_real(4);
    force.sign = parse_sign_convention(row.one_of(5, {"on-body", "opposing"}));
    force.source_id = row.integer(6, 1, std::numeric_limits<std::int64_t>::max());
    force.source_path = row.text(7);
    force.source_line = static_cast<std::size_t>(row.integer(8, 0, std::numeric_limits<std::int64_t>::max()));
    force.import_id = row.integer(9, 0, std::numeric_limits<std::int64_t>::max());
    force.value.uncertainty = row.optional_non_negative(10);
    out[found->second].tau_b[*component] = std::move(force);
  }
  auto statistics = connection_.prepare(
      "SELECT run_id, component, abscissa, window_method, window_first, window_last, samples, flags, standard_error, "
      "spread, drift, effective_samples, convergence, convergence_reason FROM run_force_statistics");
  while (statistics.step()) {
    const auto found = index.find(statistics.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(statistics, db, "run_force_statistics", statistics.get_int(0));
    const auto component = *force_index(row.one_of(1, {"X", "Y", "Z", "K", "M", "N"}));
    auto& force = out[found->second].tau_b[component];
    if (!force)
      throw InputError(SourceLocation{db}, "table run_force_statistics, run " + std::to_string(statistics.get_int(0)) +
                                               ": statistics of " + force_name(component) +
                                               ", which the run does not have; expected statistics only beside a "
                                               "stored force component");
    StoredStatistics stored;
    stored.abscissa = row.one_of(2, {"time", "iteration"});
    stored.window_method = row.text(3, 1024);
    stored.window_first = row.real(4);
    stored.window_last = row.real(5);
    stored.samples = static_cast<std::size_t>(row.integer(6, 0, std::numeric_limits<std::int64_t>::max()));
    const std::string flags = row.text(7, 1024);
    for (std::size_t start = 0; start < flags.size();) {
      const std::size_t end = std::min(flags.find(',', start), flags.size());
      stored.flags.emplace_back(check_name(NameKind::Field, std::string_view(flags).substr(start, end - start),
                                           SourceLocation{db}, "a convergence flag in table run_force_statistics"));
      start = end + 1;
    }
    stored.values.standard_error = row.non_negative(8);
    stored.values.spread = row.non_negative(9);
    stored.values.drift = row.real(10);
    stored.values.effective_samples = row.non_negative(11);
    stored.convergence = row.one_of(12, {"", "converged", "steady-window", "transient-window", "given-window"});
    stored.convergence_reason = row.text(13, 4096);
    force->statistics = std::move(stored);
  }
  auto surfaces = connection_.prepare(
      "SELECT run_id, faces, area, signed_volume, closed, boundary_edges, degenerate_faces, normals_flipped, "
      "n_dA_x, n_dA_y, n_dA_z, x_cross_n_dA_x, x_cross_n_dA_y, x_cross_n_dA_z, reference_pressure, "
      "pressure_array, shear_array, pressure_kind, shear_convention, axes FROM run_surface");
  while (surfaces.step()) {
    const auto found = index.find(surfaces.get_int(0));
    if (found == index.end()) continue;
    const store::CheckedRow row(surfaces, db, "run_surface", surfaces.get_int(0));
    constexpr std::int64_t kMost = std::numeric_limits<std::int64_t>::max();
    SurfaceIntegrals g;
    g.faces = static_cast<std::size_t>(row.integer(1, 0, kMost));
    g.area = row.non_negative(2);
    g.signed_volume = row.real(3);
    g.closed = row.integer(4, 0, 1) != 0;
    g.boundary_edges = static_cast<std::size_t>(row.integer(5, 0, kMost));
    g.degenerate_faces = static_cast<std::size_t>(row.integer(6, 0, kMost));
    g.normals_flipped = row.integer(7, 0, 1) != 0;
    for (int i = 0; i < 3; ++i) {
      g.integral_n_dA_b[static_cast<std::size_t>(i)] = row.real(8 + i);
      g.integral_x_cross_n_dA_b[static_cast<std::size_t>(i)] = row.real(11 + i);
    }
    g.reference_pressure = row.real(14);
    g.pressure_array = row.text(15, 1024);
    g.shear_array = row.text(16, 1024);
    g.pressure_kind = row.one_of(17, {"static", "kinematic"});
    g.shear_convention = row.one_of(18, {"on-wall", "on-fluid"});
    g.axes = row.text(19, 256);
    out[found->second].surface = std::move(g);
  }
  apply_numerical_uncertainties(out);
  return out;
}

void Database::apply_numerical_uncertainties(std::vector<StoredRun>& runs) {
  if (runs.empty()) return;
  std::optional<std::string> body;
  if (std::all_of(runs.begin(), runs.end(), [&](const StoredRun& r) { return r.key.body == runs.front().key.body; }))
    body = runs.front().key.body;
  const auto records = numerical_uncertainties(body);
  if (records.empty()) return;
  for (StoredRun& run : runs) {
    for (const auto& record : records) {
      if (!record.numerical_uncertainty || record.key.body != run.key.body) continue;
      auto& force = run.tau_b[record.component];
      if (!force) continue;
      const auto level = run.key.disturbances.find(record.mesh_parameter);
      if (level == run.key.disturbances.end() || !same_value(level->second, record.fine_level)) continue;
      bool same = true;
      for (std::size_t i = 0; i < 6; ++i) same = same && canonical(run.key.nu_b[i]) == record.key.nu_b[i];
      if (!same) continue;
      if (disturbance_signature(physical_disturbances(run.key.disturbances, record.mesh_parameter)) !=
          disturbance_signature(record.key.disturbances))
        continue;
      force->numerical_uncertainty = record.numerical_uncertainty;
    }
  }
}

void Database::save_numerical_uncertainties(const std::vector<NumericalUncertaintyRecord>& records) {
  store::Transaction transaction(connection_);
  // The numerical uncertainty of every force of the bodies concerned, before
  // and after: fits of a force whose uncertainty changed, and the body's
  // surfaces, become stale (a weighted fit or a GP surface would differ).
  std::set<std::string> bodies;
  for (const auto& record : records) bodies.insert(record.key.body);
  const auto snapshot = [&] {
    std::map<std::pair<std::int64_t, std::size_t>, std::optional<double>> out;
    for (const auto& name : bodies) {
      const std::int64_t id = body_id(name, false);
      if (id < 0) continue;
      for (const auto& run : load_runs(id, std::nullopt))
        for (std::size_t c = 0; c < 6; ++c)
          if (run.tau_b[c]) out[{run.id, c}] = run.tau_b[c]->numerical_uncertainty;
    }
    return out;
  };
  const auto before = snapshot();
  auto drop = connection_.prepare(
      "DELETE FROM numerical_uncertainty WHERE body_id = ? AND u = ? AND v = ? AND w = ? AND p = ? AND q = ? AND "
      "r = ? AND disturbance_key = ?");
  auto insert = connection_.prepare(
      "INSERT INTO numerical_uncertainty(body_id, u, v, w, p, q, r, disturbance_key, component, mesh_parameter, "
      "fine_level, levels, h1, h2, h3, phi1, phi2, phi3, convergence, apparent_order, extrapolated, relative_error, "
      "extrapolated_relative_error, gci_fine, numerical_uncertainty, note, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, "
      "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  std::set<std::pair<std::int64_t, std::string>> cleared;
  for (const auto& record : records) {
    const std::int64_t body = existing_body_id(record.key.body);
    const std::string signature = disturbance_signature(record.key.disturbances);
    std::string identity = signature;
    for (const double x : record.key.nu_b) identity += ' ' + shortest_number(canonical(x));
    if (cleared.insert({body, identity}).second) {
      drop.bind(1, body);
      for (int i = 0; i < 6; ++i) drop.bind(2 + i, canonical(record.key.nu_b[static_cast<std::size_t>(i)]));
      drop.bind(8, signature).run();
      drop.reset();
    }
    int c = 1;
    insert.bind(c++, body);
    for (const double x : record.key.nu_b) insert.bind(c++, canonical(x));
    insert.bind(c++, signature);
    insert.bind(c++, force_name(record.component));
    insert.bind(c++, record.mesh_parameter);
    insert.bind(c++, record.fine_level);
    insert.bind(c++, static_cast<std::int64_t>(record.levels));
    for (const double h : record.h) insert.bind(c++, h);
    for (const double phi : record.phi) insert.bind(c++, phi);
    insert.bind(c++, record.convergence);
    insert.bind(c++, record.apparent_order);
    insert.bind(c++, record.extrapolated);
    insert.bind(c++, record.relative_error);
    insert.bind(c++, record.extrapolated_relative_error);
    insert.bind(c++, record.gci_fine);
    insert.bind(c++, record.numerical_uncertainty);
    insert.bind(c++, record.note);
    insert.bind(c++, record.created_at.empty() ? utc_timestamp_now() : record.created_at);
    insert.run();
    insert.reset();
  }
  auto stale_fits = connection_.prepare(
      "UPDATE fit SET stale = 1 WHERE dof = ? AND id IN (SELECT fit_id FROM fit_run WHERE run_id = ?)");
  auto stale_surfaces =
      connection_.prepare("UPDATE surface SET stale = 1 WHERE body_id = (SELECT body_id FROM run WHERE id = ?)");
  for (const auto& [force, uncertainty] : snapshot()) {
    const auto old = before.find(force);
    if (old != before.end() && old->second == uncertainty) continue;
    stale_fits.bind(1, force_name(force.second)).bind(2, force.first).run();
    stale_fits.reset();
    stale_surfaces.bind(1, force.first).run();
    stale_surfaces.reset();
  }
  transaction.commit();
  use_wal();
}

std::vector<NumericalUncertaintyRecord> Database::numerical_uncertainties(const std::optional<std::string>& body) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT n.body_id, body.name, u, v, w, p, q, r, disturbance_key, component, mesh_parameter, fine_level, "
      "levels, h1, h2, h3, phi1, phi2, phi3, convergence, apparent_order, extrapolated, relative_error, "
      "extrapolated_relative_error, gci_fine, numerical_uncertainty, note, created_at FROM numerical_uncertainty n "
      "JOIN body ON body.id = n.body_id";
  if (body) sql += " WHERE body.name = ?1";
  sql += " ORDER BY body.name, u, v, w, p, q, r, disturbance_key, component";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<NumericalUncertaintyRecord> out;
  const std::string db = path_.string();
  std::int64_t row_number = 0;
  while (select.step()) {
    const store::CheckedRow row(select, db, "numerical_uncertainty", ++row_number);
    NumericalUncertaintyRecord record;
    record.key.body = row.name(1, NameKind::Body);
    for (int i = 0; i < 6; ++i) record.key.nu_b[static_cast<std::size_t>(i)] = row.real(2 + i);
    const std::string signature = row.text(8);
    for (const std::string_view entry : split(signature, ';')) {
      if (entry.empty()) continue;
      const auto equals = entry.find('=');
      const auto value =
          equals == std::string_view::npos ? std::nullopt : parse_finite_number(entry.substr(equals + 1));
      if (!value) row.fail(8, "the canonical text of disturbances, name=value;...");
      record.key.disturbances[std::string(check_name(NameKind::Parameter, entry.substr(0, equals), SourceLocation{db},
                                                     "a disturbance in table numerical_uncertainty"))] = *value;
    }
    record.component = *force_index(row.one_of(9, {"X", "Y", "Z", "K", "M", "N"}));
    record.mesh_parameter = row.name(10, NameKind::Parameter);
    record.fine_level = row.real(11);
    record.levels = static_cast<std::size_t>(row.integer(12, 3, std::numeric_limits<std::int64_t>::max()));
    for (int i = 0; i < 3; ++i) {
      record.h[static_cast<std::size_t>(i)] = row.positive(13 + i);
      record.phi[static_cast<std::size_t>(i)] = row.real(16 + i);
    }
    record.convergence = row.one_of(19, {"monotonic", "oscillatory", "converged", "not found"});
    record.apparent_order = row.optional_real(20);
    record.extrapolated = row.optional_real(21);
    record.relative_error = row.optional_real(22);
    record.extrapolated_relative_error = row.optional_real(23);
    record.gci_fine = row.optional_non_negative(24);
    record.numerical_uncertainty = row.optional_non_negative(25);
    record.note = row.text(26);
    record.created_at = row.text(27, 64);
    out.push_back(std::move(record));
  }
  return out;
}

std::vector<StoredRun> Database::runs(const RunFilter& filter) {
  std::optional<std::int64_t> body;
  if (filter.body) {
    body = body_id(*filter.body, false);
    if (*body < 0) return {};
  }
  auto all = load_runs(body, std::nullopt);
  std::erase_if(all, [&](const StoredRun& run) {
    if (filter.with_force && !run.tau_b[*filter.with_force]) return true;
    for (const auto& [name, wanted] : filter.equal) {
      double value = 0.0;
      if (const auto i = velocity_index(name)) {
        value = run.key.nu_b[*i];
      } else if (const auto found = run.key.disturbances.find(name); found != run.key.disturbances.end()) {
        value = found->second;
      } else {
        return true;
      }
      if (std::abs(value - wanted) > kFilterTolerance * std::max(1.0, std::abs(wanted))) return true;
    }
    return false;
  });
  return all;
}

std::optional<StoredRun> Database::find_run(const RunKey& key) {
  const std::int64_t body = body_id(key.body, false);
  if (body < 0) return std::nullopt;
  const auto id = find_run_id(body, key);
  if (!id) return std::nullopt;
  auto found = load_runs(body, *id);
  if (found.empty()) return std::nullopt;
  return std::move(found.front());
}

std::vector<SourceRecord> Database::sources() {
  auto select = connection_.prepare(
      "SELECT id, path, sha256, size_bytes, importer, importer_version, imported_at FROM source_file ORDER BY id");
  std::vector<SourceRecord> out;
  while (select.step()) {
    const store::CheckedRow row(select, path_.string(), "source_file", select.get_int(0));
    SourceRecord record;
    record.id = select.get_int(0);
    record.provenance.path = row.text(1);
    record.provenance.sha256 = row.text(2, 64);
    record.provenance.size_bytes =
        static_cast<std::uint64_t>(row.integer(3, 0, std::numeric_limits<std::int64_t>::max()));
    record.provenance.importer = row.text(4, 256);
    record.provenance.importer_version = row.text(5, 256);
    record.imported_at = row.text(6, 64);
    out.push_back(std::move(record));
  }
  return out;
}

std::vector<std::string> run_flags(const StoredRun& run) {
  std::vector<std::string> out;
  for (const auto& force : run.tau_b)
    if (force && force->statistics)
      for (const auto& flag : force->statistics->flags)
        if (std::find(out.begin(), out.end(), flag) == out.end()) out.push_back(flag);
  return out;
}

std::vector<std::string> Database::bodies() {
  auto select = connection_.prepare("SELECT name, id FROM body ORDER BY name");
  std::vector<std::string> out;
  while (select.step())
    out.push_back(store::CheckedRow(select, path_.string(), "body", select.get_int(1)).name(0, NameKind::Body));
  return out;
}

std::int64_t Database::save_fit(const FitRecord& fit, NameTaken taken) { return save_fits({fit}, taken).front(); }

std::vector<std::int64_t> Database::save_fits(const std::vector<FitRecord>& fits, NameTaken taken) {
  for (const auto& fit : fits) check_name(NameKind::Fit, fit.name, {}, "the fit");
  store::Transaction transaction(connection_);
  if (taken == NameTaken::Refuse) {
    auto existing = connection_.prepare("SELECT id, created_at FROM fit WHERE name = ?");
    for (const auto& fit : fits) {
      existing.bind(1, fit.name);
      if (existing.step()) {
        const std::string message = "a fit named '" + escape::one_line(fit.name) + "' exists (fit " +
                                    std::to_string(existing.get_int(0)) + ", made " + existing.get_text(1) +
                                    "); give --replace to replace it, or another --name";
        throw InputError(SourceLocation{path_.string()}, message);
      }
      existing.reset();
    }
  }
  std::vector<std::int64_t> ids;
  for (const auto& fit : fits) ids.push_back(insert_fit(fit));
  transaction.commit();
  use_wal();
  return ids;
}

std::int64_t Database::insert_fit(const FitRecord& fit) {
  const std::int64_t body = existing_body_id(fit.body);
  connection_.prepare("DELETE FROM fit WHERE name = ?").bind(1, fit.name).run();
  auto insert = connection_.prepare(
      "INSERT INTO fit(name, body_id, dof, variable, terms, loss, run_filter, sign_convention, n, rmse, r2, "
      "created_at, mirror, weighting, chi2_reduced, covariance) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
      "?) RETURNING id");
  insert.bind(1, fit.name)
      .bind(2, body)
      .bind(3, fit.dof)
      .bind(4, fit.variable)
      .bind(5, fit.terms)
      .bind(6, fit.loss)
      .bind(7, fit.run_filter)
      .bind(8, to_string(fit.sign))
      .bind(9, static_cast<std::int64_t>(fit.n))
      .bind(10, fit.rmse)
      .bind(11, fit.r2)
      .bind(12, utc_timestamp_now())
      .bind(13, fit.mirror)
      .bind(14, fit.weighting)
      .bind(15, fit.chi2_reduced)
      .bind(16, fit.covariance.empty() ? std::string() : escape::json_text(nlohmann::json(fit.covariance)));
  const std::int64_t id = store::returned_id(insert);
  auto coefficient = connection_.prepare(
      "INSERT INTO fit_coefficient(fit_id, position, term, value, std_error) VALUES (?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < fit.coefficients.size(); ++i) {
    const auto& c = fit.coefficients[i];
    coefficient.bind(1, id).bind(2, static_cast<std::int64_t>(i)).bind(3, c.term).bind(4, c.value).bind(5, c.std_error);
    coefficient.run();
  }
  link_runs("fit_run", "fit_id", id, fit.run_ids);
  return id;
}

std::vector<FitRecord> Database::fits(const std::optional<std::string>& body) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT fit.id, fit.name, body.name, dof, variable, terms, loss, run_filter, sign_convention, n, rmse, r2, "
      "created_at, stale, mirror, weighting, chi2_reduced, covariance FROM fit JOIN body ON body.id = fit.body_id";
  if (body) sql += " WHERE body.name = ?1";
  sql += " ORDER BY fit.name";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  std::vector<FitRecord> out;
  while (select.step()) {
    const store::CheckedRow row(select, path_.string(), "fit", select.get_int(0));
    constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();
    FitRecord fit;
    fit.id = select.get_int(0);
    fit.name = row.name(1, NameKind::Fit);
    fit.body = row.name(2, NameKind::Body);
    fit.dof = row.one_of(3, {"X", "Y", "Z", "K", "M", "N"});
    fit.variable = row.one_of(4, {"u", "v", "w", "p", "q", "r"});
    fit.terms = row.text(5, 1024);
    fit.loss = row.text(6, 256);
    fit.run_filter = row.text(7);
    fit.sign = parse_sign_convention(row.one_of(8, {"on-body", "opposing"}));
    fit.n = static_cast<std::size_t>(row.integer(9, 0, std::int64_t{1} << 40));
    fit.rmse = row.optional_non_negative(10).value_or(kAbsent);
    fit.r2 = row.optional_real(11).value_or(kAbsent);
    fit.created_at = row.text(12, 64);
    fit.stale = row.integer(13, 0, 1) != 0;
    fit.mirror = row.text(14, 256);
    fit.weighting = row.one_of(15, {"none", "uncertainty"});
    fit.chi2_reduced = row.optional_non_negative(16);
    fit.covariance = row.real_list(17, 36 * 36);
    out.push_back(std::move(fit));
  }
  auto coefficients =
      connection_.prepare("SELECT term, value, std_error FROM fit_coefficient WHERE fit_id = ? ORDER BY position");
  for (auto& fit : out) {
    coefficients.bind(1, fit.id);
    while (coefficients.step()) {
      const store::CheckedRow row(coefficients, path_.string(), "fit_coefficient", fit.id);
      fit.coefficients.push_back({row.text(0, 256), row.real(1), row.optional_non_negative(2)});
    }
    coefficients.reset();
    if (!fit.covariance.empty() && fit.covariance.size() != fit.coefficients.size() * fit.coefficients.size())
      throw InputError(SourceLocation{path_.string()},
                       "table 'fit', row " + std::to_string(fit.id) + ": column 'covariance' holds " +
                           std::to_string(fit.covariance.size()) + " numbers; expected " +
                           std::to_string(fit.coefficients.size() * fit.coefficients.size()) +
                           " (one per pair of its coefficients) or none");
    fit.run_ids = linked_runs("fit_run", "fit_id", fit.id);
  }
  return out;
}

std::int64_t Database::existing_body_id(const std::string& name) {
  const std::int64_t id = body_id(name, false);
  if (id < 0) throw InputError("no body named '" + name + "' in " + path_.string());
  return id;
}

void Database::link_runs(const char* table, const char* owner, std::int64_t id,
                         const std::vector<std::int64_t>& run_ids) {
  auto insert = connection_.prepare(std::string("INSERT INTO ") + table + "(" + owner + ", run_id) VALUES (?, ?)");
  for (const auto run_id : run_ids) insert.bind(1, id).bind(2, run_id).run();
}

std::vector<std::int64_t> Database::linked_runs(const char* table, const char* owner, std::int64_t id) {
  auto select =
      connection_.prepare(std::string("SELECT run_id FROM ") + table + " WHERE " + owner + " = ? ORDER BY run_id");
  select.bind(1, id);
  std::vector<std::int64_t> out;
  while (select.step())
    out.push_back(
        store::CheckedRow(select, path_.string(), table, id).integer(0, 1, std::numeric_limits<std::int64_t>::max()));
  return out;
}

std::int64_t Database::save_surface(const SurfaceRecord& surface) {
  check_name(NameKind::Surface, surface.name, {}, "the surface");
  store::Transaction transaction(connection_);
  const std::int64_t body = existing_body_id(surface.body);
  connection_.prepare("DELETE FROM surface WHERE name = ?").bind(1, surface.name).run();
  auto insert = connection_.prepare(
      "INSERT INTO surface(name, body_id, kind, method, definition, data, quality, created_at, stale) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, 0) RETURNING id");
  insert.bind(1, surface.name)
      .bind(2, body)
      .bind(3, surface.kind)
      .bind(4, surface.method)
      .bind(5, surface.definition)
      .bind_doubles(6, surface.data)
      .bind(7, surface.quality)
      .bind(8, utc_timestamp_now());
  const std::int64_t id = store::returned_id(insert);
  link_runs("surface_run", "surface_id", id, surface.run_ids);
  transaction.commit();
  use_wal();
  return id;
}

std::vector<SurfaceRecord> Database::load_surfaces(const std::optional<std::string>& body,
                                                   const std::optional<std::string>& name) {
  // One state of the database for all the statements below.
  const store::detail::ReadSnapshot snapshot(connection_.backend_impl());
  std::string sql =
      "SELECT surface.id, surface.name, body.name, kind, method, definition, data, quality, created_at, stale "
      "FROM surface JOIN body ON body.id = surface.body_id WHERE TRUE";
  if (body) sql += " AND body.name = ?1";
  if (name) sql += " AND surface.name = ?2";
  sql += " ORDER BY surface.name";
  auto select = connection_.prepare(sql);
  if (body) select.bind(1, *body);
  if (name) select.bind(2, *name);
  std::vector<SurfaceRecord> out;
  while (select.step()) {
    const store::CheckedRow row(select, path_.string(), "surface", select.get_int(0));
    SurfaceRecord record;
    record.id = select.get_int(0);
    record.name = row.name(1, NameKind::Surface);
    record.body = row.name(2, NameKind::Body);
    record.kind = row.one_of(3, {"grid", "rbf", "gp"});
    record.method = row.text(4, 64);
    record.definition = row.text(5, kMaxSurfaceDefinitionBytes);
    record.data = row.doubles(6, kMaxSurfaceValues);
    record.quality = row.text(7, kMaxSurfaceDefinitionBytes);
    record.created_at = row.text(8, 64);
    record.stale = row.integer(9, 0, 1) != 0;
    record.database = path_.string();
    record.run_ids = linked_runs("surface_run", "surface_id", record.id);
    out.push_back(std::move(record));
  }
  return out;
}

std::vector<SurfaceRecord> Database::surfaces(const std::optional<std::string>& body) {
  return load_surfaces(body, std::nullopt);
}

void Database::remove_import_forces(std::int64_t import_id) {
  std::vector<std::int64_t> runs;
  auto touched = connection_.prepare("SELECT DISTINCT run_id FROM run_force WHERE import_id = ?");
  touched.bind(1, import_id);
  while (touched.step()) runs.push_back(touched.get_int(0));
  touched.reset();
  connection_
      .prepare(
          "DELETE FROM run_surface WHERE source_id = (SELECT source_id FROM import WHERE id = ?1) AND run_id IN "
          "(SELECT run_id FROM run_force WHERE import_id = ?1)")
      .bind(1, import_id)
      .run();
  connection_
      .prepare(
          "DELETE FROM run_force_statistics WHERE EXISTS (SELECT 1 FROM run_force f WHERE f.import_id = ? AND "
          "f.run_id = run_force_statistics.run_id AND f.component = run_force_statistics.component)")
      .bind(1, import_id)
      .run();
  connection_
      .prepare("DELETE FROM run_force_trace WHERE run_id IN (SELECT run_id FROM run_force WHERE import_id = ?)")
      .bind(1, import_id)
      .run();
  connection_.prepare("DELETE FROM run_force WHERE import_id = ?").bind(1, import_id).run();
  // A run left with no force component is no run.
  auto remaining = connection_.prepare("SELECT count(*) FROM run_force WHERE run_id = ?");
  auto drop_surface = connection_.prepare("DELETE FROM run_surface WHERE run_id = ?");
  auto drop_run = connection_.prepare("DELETE FROM run WHERE id = ?");
  for (const auto run : runs) {
    remaining.bind(1, run);
    remaining.step();
    const bool empty = remaining.get_int(0) == 0;
    remaining.reset();
    if (!empty) continue;
    drop_surface.bind(1, run).run();
    drop_run.bind(1, run).run();
  }
}

DeleteOutcome Database::delete_runs(const std::vector<std::int64_t>& ids) {
  store::Transaction transaction(connection_);
  const auto count = [&](const char* sql) {
    auto statement = connection_.prepare(sql);
    statement.step();
    return static_cast<std::size_t>(statement.get_int(0));
  };
  const std::size_t stale_fits = count("SELECT count(*) FROM fit WHERE stale = 1");
  const std::size_t stale_surfaces = count("SELECT count(*) FROM surface WHERE stale = 1");
  const std::size_t imports = count("SELECT count(*) FROM import");
  DeleteOutcome outcome;
  auto exists = connection_.prepare("SELECT count(*) FROM run WHERE id = ?");
  auto components = connection_.prepare("SELECT count(*) FROM run_force WHERE run_id = ?");
  std::set<std::int64_t> done;
  for (const auto id : ids) {
    if (!done.insert(id).second) continue;
    exists.bind(1, id);
    exists.step();
    const bool found = exists.get_int(0) != 0;
    exists.reset();
    if (!found)
      throw InputError(SourceLocation{path_.string()}, "no run " + std::to_string(id) + "; nothing was deleted");
    components.bind(1, id);
    components.step();
    outcome.components += static_cast<std::size_t>(components.get_int(0));
    components.reset();
    connection_.prepare("DELETE FROM run_force_statistics WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run_force_trace WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run_force WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run_surface WHERE run_id = ?").bind(1, id).run();
    connection_.prepare("DELETE FROM run WHERE id = ?").bind(1, id).run();
    ++outcome.runs;
  }
  // Imports and files that no longer give any run.
  connection_.execute(
      "DELETE FROM import WHERE id NOT IN (SELECT import_id FROM run_force WHERE import_id IS NOT NULL)");
  connection_.execute(
      "DELETE FROM source_file WHERE id NOT IN (SELECT source_id FROM import) AND id NOT IN (SELECT source_id FROM "
      "run_force) AND id NOT IN (SELECT source_id FROM run_surface)");
  outcome.fits_made_stale = count("SELECT count(*) FROM fit WHERE stale = 1") - stale_fits;
  outcome.surfaces_made_stale = count("SELECT count(*) FROM surface WHERE stale = 1") - stale_surfaces;
  outcome.imports_removed = imports - count("SELECT count(*) FROM import");
  transaction.commit();
  use_wal();
  return outcome;
}

std::optional<ImportRecord> Database::import_record(std::int64_t id) {
  auto select = connection_.prepare(
      "SELECT i.id, i.source_id, s.sha256, i.reading, i.settings, i.settings_key, i.path, i.resolved_path, i.importer, "
      "i.importer_version, i.hydrocoef_version, i.imported_at, s.size_bytes FROM import i JOIN source_file s ON "
      "s.id = i.source_id WHERE i.id = ?");
  select.bind(1, id);
  if (!select.step()) return std::nullopt;
  const store::CheckedRow row(select, path_.string(), "import", id);
  ImportRecord record;
  record.id = id;
  record.source_id = select.get_int(1);
  record.sha256 = row.text(2, 64);
  record.reading = row.text(3, 256);
  record.settings = row.text(4, 1 << 20);
  record.settings_key = row.text(5, 1 << 20);
  record.path = row.text(6);
  record.resolved_path = row.text(7);
  record.importer = row.text(8, 256);
  record.importer_version = row.text(9, 256);
  record.hydrocoef_version = row.text(10, 256);
  record.imported_at = row.text(11, 64);
  record.size_bytes = static_cast<std::uint64_t>(row.integer(12, 0, std::numeric_limits<std::int64_t>::max()));
  return record;
}

SurfaceRecord Database::surface(const std::string& name) {
  auto found = load_surfaces(std::nullopt, name);
  if (!found.empty()) return std::move(found.front());
  // Only the names, for the message: no value blobs are read.
  auto select = connection_.prepare("SELECT name FROM surface ORDER BY name");
  std::string names;
  while (select.step()) names += (names.empty() ? "'" : ", '") + printable_text(select.get_text(0), 60) + "'";
  throw InputError("no surface named '" + name + "' in " + path_.string() +
                   "; surfaces there: " + (names.empty() ? "none" : names));
}

}  // namespace hydrocoef
