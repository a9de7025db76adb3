// RunDatabase: opening a database (an SQLite file or a PostgreSQL server),
// checking and migrating its schema, the write-ahead log, and what every
// record kind shares: bodies and the tables that link a record to its runs.
// The records themselves are in the *_store.cpp files beside this one
// (run_store, fit_store, surface_store, uncertainty_store, pmm_store,
// trace_store).
#include "src/store/database.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <limits>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/text.hpp"
#include "src/store/backend.hpp"
#include "src/store/build_spec_migration.hpp"
#include "src/store/checked_row.hpp"
#include "src/store/dialect.hpp"
#include "src/store/location.hpp"
#include "src/store/migrations.hpp"
#include "src/store/schema_check.hpp"

namespace hydrocoef {

std::string utc_timestamp_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return text;
}

namespace {

store::Connection open_connection(const store::DatabaseLocation& location, RunDatabase::OpenMode mode) {
  if (location.backend == store::Backend::PostgreSQL)
    return store::Connection::postgresql(
        location.target, location.display,
        mode == RunDatabase::OpenMode::ReadOnly ? store::Access::ReadOnly : store::Access::ReadWrite);
  const std::filesystem::path path(location.target);
  if (mode != RunDatabase::OpenMode::CreateIfMissing && !std::filesystem::exists(path))
    throw InputError(SourceLocation{path.string()},
                     "no database here; create one with 'hydrocoef import' or give --db PATH");
  switch (mode) {
    case RunDatabase::OpenMode::CreateIfMissing: return {path.string(), store::Access::ReadWriteCreate};
    case RunDatabase::OpenMode::MustExist: return {path.string(), store::Access::ReadWrite};
    case RunDatabase::OpenMode::ReadOnly: break;
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

/// What every connection of a RunDatabase runs first.
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

RunDatabase::RunDatabase(const std::filesystem::path& path, OpenMode mode)
    : RunDatabase(store::parse_database_location(path.string()), mode) {}

RunDatabase::RunDatabase(const store::DatabaseLocation& location, OpenMode mode)
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
void RunDatabase::use_wal() {
  if (!read_only_) connection_.use_wal();
}

int RunDatabase::latest_schema_version() { return static_cast<int>(store::migrations().size()); }

int RunDatabase::schema_version() { return static_cast<int>(stored_schema_version(connection_)); }

std::string RunDatabase::integrity_check() {
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

int RunDatabase::checked_schema_version() {
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

void RunDatabase::check_schema(int version) {
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

void RunDatabase::migrate() {
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

std::int64_t RunDatabase::body_id(const std::string& name, bool create) {
  auto find = connection_.prepare("SELECT id FROM body WHERE name = ?");
  find.bind(1, name);
  if (find.step()) return find.get_int(0);
  if (!create) return -1;
  auto insert = connection_.prepare("INSERT INTO body(name) VALUES (?) RETURNING id");
  insert.bind(1, name);
  return store::returned_id(insert);
}

std::int64_t RunDatabase::existing_body_id(const std::string& name) {
  const std::int64_t id = body_id(name, false);
  if (id < 0) throw InputError("no body named '" + name + "' in " + path_.string());
  return id;
}

std::vector<std::string> RunDatabase::bodies() {
  auto select = connection_.prepare("SELECT name, id FROM body ORDER BY name");
  std::vector<std::string> out;
  while (select.step())
    out.push_back(store::CheckedRow(select, path_.string(), "body", select.get_int(1)).name(0, NameKind::Body));
  return out;
}

void RunDatabase::link_runs(const char* table, const char* owner, std::int64_t id,
                            const std::vector<std::int64_t>& run_ids) {
  auto insert = connection_.prepare(std::string("INSERT INTO ") + table + "(" + owner + ", run_id) VALUES (?, ?)");
  for (const auto run_id : run_ids) insert.bind(1, id).bind(2, run_id).run();
}

std::vector<std::int64_t> RunDatabase::linked_runs(const char* table, const char* owner, std::int64_t id) {
  auto select =
      connection_.prepare(std::string("SELECT run_id FROM ") + table + " WHERE " + owner + " = ? ORDER BY run_id");
  select.bind(1, id);
  std::vector<std::int64_t> out;
  while (select.step())
    out.push_back(
        store::CheckedRow(select, path_.string(), table, id).integer(0, 1, std::numeric_limits<std::int64_t>::max()));
  return out;
}

}  // namespace hydrocoef
