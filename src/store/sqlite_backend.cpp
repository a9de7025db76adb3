// The SQLite backend of store::Connection: one database file through
// SQLite's C API.
#include <sqlite3.h>

#include <cerrno>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "src/core/error.hpp"
#include "src/store/backend.hpp"

namespace hydrocoef::store::detail {
namespace {

class SqliteConnection;

class SqliteStatement final : public StatementBackend {
 public:
  SqliteStatement(const SqliteConnection& connection, std::string_view sql);
  ~SqliteStatement() override { sqlite3_finalize(statement_); }
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  void bind_double(int index, double value) override { check(sqlite3_bind_double(statement_, index, value), index); }
  void bind_int(int index, std::int64_t value) override { check(sqlite3_bind_int64(statement_, index, value), index); }
  void bind_text(int index, std::string_view value) override {
    check(sqlite3_bind_text64(statement_, index, value.data(), value.size(), SQLITE_TRANSIENT, SQLITE_UTF8), index);
  }
  void bind_blob(int index, const void* data, std::size_t size) override {
    if (size == 0)
      check(sqlite3_bind_zeroblob(statement_, index, 0), index);  // a blob of no bytes, not NULL
    else
      check(sqlite3_bind_blob64(statement_, index, data, size, SQLITE_TRANSIENT), index);
  }
  void bind_null(int index) override { check(sqlite3_bind_null(statement_, index), index); }
  bool step() override;
  void reset() override {
    sqlite3_reset(statement_);
    sqlite3_clear_bindings(statement_);
  }
  ColumnType column_type(int column) const override {
    switch (sqlite3_column_type(statement_, column)) {
      case SQLITE_INTEGER: return ColumnType::Integer;
      case SQLITE_FLOAT: return ColumnType::Float;
      case SQLITE_TEXT: return ColumnType::Text;
      case SQLITE_BLOB: return ColumnType::Blob;
      default: return ColumnType::Null;
    }
  }
  double get_double(int column) const override { return sqlite3_column_double(statement_, column); }
  std::int64_t get_int(int column) const override { return sqlite3_column_int64(statement_, column); }
  std::string_view get_text(int column) const override {
    const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(statement_, column));
    if (!text) return {};
    return {text, static_cast<std::size_t>(sqlite3_column_bytes(statement_, column))};
  }
  std::string_view get_blob(int column) const override {
    const auto* bytes = static_cast<const char*>(sqlite3_column_blob(statement_, column));
    if (!bytes) return {};
    return {bytes, static_cast<std::size_t>(sqlite3_column_bytes(statement_, column))};
  }
  const char* column_name(int column) const override { return sqlite3_column_name(statement_, column); }

 private:
  /// A value that could not be bound (no memory for its copy, too big)
  /// would leave the parameter NULL: the statement must not run.
  void check(int rc, int index) const;

  const SqliteConnection* connection_;
  sqlite3_stmt* statement_ = nullptr;
};

class SqliteConnection final : public ConnectionBackend {
 public:
  SqliteConnection(const std::string& path, Access access);
  ~SqliteConnection() override {
    if (db_) sqlite3_close_v2(db_);
  }
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  Backend kind() const override { return Backend::SQLite; }
  void execute(std::string_view sql) override {
    const std::string text(sql);
    const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, nullptr);
    if (rc != SQLITE_OK) fail(rc, "executing SQL");
  }
  std::unique_ptr<StatementBackend> prepare(std::string_view sql) override {
    return std::make_unique<SqliteStatement>(*this, sql);
  }
  bool read_only() const override { return sqlite3_db_readonly(db_, "main") == 1; }
  // A write transaction begun inside another joins it (see Transaction).
  void begin_write() override {
    if (depth_ > 0 && reading_) throw std::logic_error("a write transaction begun inside a read snapshot");
    if (depth_ == 0) execute("BEGIN IMMEDIATE");
    ++depth_;
  }
  void begin_read() override {
    if (depth_ == 0) {
      execute("BEGIN");
      reading_ = true;
    }
    ++depth_;
  }
  void end_read() noexcept override {
    if (depth_ > 0 && --depth_ == 0) {
      if (sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr) != SQLITE_OK)
        sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
      reading_ = false;
    }
  }
  void commit() override {
    if (depth_ == 1) {
      const int rc = sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr);
      if (rc != SQLITE_OK) fail_commit(rc);
    }
    if (depth_ > 0) --depth_;
  }
  void rollback() noexcept override {
    if (depth_ > 0) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    depth_ = 0;
    reading_ = false;
  }
  void use_wal() override;

  /// A private temporary database (SQLite's "" file: pages in memory,
  /// spilled to a temporary file when large, deleted on close) that holds a
  /// copy of `source`'s pages; messages name `display`.
  static std::unique_ptr<SqliteConnection> private_copy(const SqliteConnection& source);

  sqlite3* handle() const { return db_; }
  /// Throws the right exception for SQLite result code `rc` (with context).
  [[noreturn]] void fail(int rc, std::string_view what) const;
  /// The same for a COMMIT that failed.
  [[noreturn]] void fail_commit(int rc) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
  int depth_ = 0;         ///< transactions open, the outermost one real
  bool reading_ = false;  ///< the outermost one is a read snapshot
};

SqliteStatement::SqliteStatement(const SqliteConnection& connection, std::string_view sql) : connection_(&connection) {
  const int rc =
      sqlite3_prepare_v2(connection.handle(), sql.data(), static_cast<int>(sql.size()), &statement_, nullptr);
  if (rc != SQLITE_OK) connection.fail(rc, "preparing '" + std::string(sql.substr(0, 60)) + "'");
}

void SqliteStatement::check(int rc, int index) const {
  if (rc != SQLITE_OK)
    connection_->fail(rc, "binding parameter " + std::to_string(index) + " of '" +
                              std::string(sqlite3_sql(statement_)).substr(0, 60) + "'");
}

bool SqliteStatement::step() {
  const int rc = sqlite3_step(statement_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  connection_->fail(rc, "running '" + std::string(sqlite3_sql(statement_)).substr(0, 60) + "'");
}

std::unique_ptr<SqliteConnection> SqliteConnection::private_copy(const SqliteConnection& source) {
  auto copy = std::make_unique<SqliteConnection>("", Access::ReadWriteCreate);
  copy->path_ = source.path_;
  sqlite3_backup* backup = sqlite3_backup_init(copy->db_, "main", source.db_, "main");
  if (!backup) copy->fail(sqlite3_extended_errcode(copy->db_), "copying the database to read it");
  const int stepped = sqlite3_backup_step(backup, -1);
  const int finished = sqlite3_backup_finish(backup);
  if (stepped != SQLITE_DONE) source.fail(stepped, "copying the database to read it");
  if (finished != SQLITE_OK) copy->fail(finished, "copying the database to read it");
  return copy;
}

SqliteConnection::SqliteConnection(const std::string& path, Access access) : path_(path) {
  int flags = SQLITE_OPEN_READWRITE;
  std::string name = path;
  switch (access) {
    case Access::ReadWrite: break;
    case Access::ReadWriteCreate: flags |= SQLITE_OPEN_CREATE; break;
    case Access::ReadOnly: flags = SQLITE_OPEN_READONLY; break;
    case Access::Immutable: {
      // A URI: the path's '%', '?' and '#' must be escaped.
      flags = SQLITE_OPEN_READONLY | SQLITE_OPEN_URI;
      name = "file:";
      for (const char c : path) {
        if (c == '%' || c == '?' || c == '#') {
          static constexpr char kHex[] = "0123456789ABCDEF";
          name += '%';
          name += kHex[static_cast<unsigned char>(c) >> 4];
          name += kHex[static_cast<unsigned char>(c) & 15];
        } else {
          name += c;
        }
      }
      name += "?immutable=1";
      break;
    }
  }
  const int timeout = busy_timeout_seconds();
  const int rc = sqlite3_open_v2(name.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(SourceLocation{path}, "cannot open database: " + message);
  }
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, timeout * 1000);
  // A received file is untrusted: no triggers or views it adds may call
  // application functions, and no schema may hide in a shadow table.
  sqlite3_db_config(db_, SQLITE_DBCONFIG_TRUSTED_SCHEMA, 0, nullptr);
  sqlite3_db_config(db_, SQLITE_DBCONFIG_DEFENSIVE, 1, nullptr);
}

void SqliteConnection::fail(int rc, std::string_view what) const {
  const std::string detail = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
  const int primary = rc & 0xff;
  const int error = db_ ? sqlite3_system_errno(db_) : 0;
  const SourceLocation where{path_};
  // What a user can cause (another process, the disk, the file) is said in
  // words and is exit 2; anything else is a bug in hydrocoef.
  if (primary == SQLITE_FULL || error == ENOSPC)
    throw InputError(
        where, "database: disk full (no space left on device) while " + std::string(what) + "; nothing was changed");
  if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED)
    throw InputError(where, "database is busy: another process has held it for " +
                                std::to_string(busy_timeout_seconds()) +
                                " s (HYDROCOEF_DB_TIMEOUT sets how long to wait); nothing was changed, try again when "
                                "it has finished");
  if (primary == SQLITE_READONLY)
    throw InputError(where, "database is read-only here (" + detail + "); expected a writable file and folder for " +
                                std::string(what));
  if (primary == SQLITE_NOTADB || primary == SQLITE_CORRUPT || primary == SQLITE_CANTOPEN || primary == SQLITE_IOERR ||
      primary == SQLITE_NOMEM || primary == SQLITE_TOOBIG || primary == SQLITE_AUTH)
    throw InputError(where, "database: " + std::string(what) + ": " + detail);
  throw std::runtime_error(path_ + ": database: " + std::string(what) + ": " + detail);
}

// A COMMIT whose sync fails may have reached the disk all the same: SQLite
// syncs the WAL after writing its commit frame, and reports the failed sync
// although the frame is there, for the next opening of the file to replay.
// So the message cannot say that nothing was changed. (A write that fails
// before the sync leaves no commit frame, so the file is as it was, as
// fail() says; in rollback-journal mode the commit is the journal's
// deletion, after every sync, and a failed sync there is answered with the
// same caution.)
void SqliteConnection::fail_commit(int rc) const {
  if (rc != SQLITE_IOERR_FSYNC) fail(rc, "committing");
  throw InputError(SourceLocation{path_}, "database: the disk failed to sync the commit (" +
                                              std::string(sqlite3_errmsg(db_)) +
                                              "): the write may or may not have been stored; look at the database "
                                              "before trying again");
}

// The switch to write-ahead logging needs every other connection to let go
// of the file, and SQLite answers "busy" at once (without its busy handler)
// while one reads it. The write before has committed, so the switch is tried
// for up to 2 s and otherwise left to the next writer, as is a switch that
// the disk or memory fails: the file is whole in either mode, and the
// command that wrote it must not fail saying nothing was changed.
void SqliteConnection::use_wal() {
  if (read_only() || depth_ > 0) return;  // not inside a transaction: after the outermost one
  try {
    SqliteStatement mode_now(*this, "PRAGMA journal_mode");
    if (mode_now.step() && mode_now.get_text(0) == "wal") return;
  } catch (const InputError&) {
    return;
  }
  for (int attempt = 0; attempt < 200; ++attempt) {
    const int rc = sqlite3_exec(db_, "PRAGMA journal_mode = WAL", nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK || ((rc & 0xff) != SQLITE_BUSY && (rc & 0xff) != SQLITE_LOCKED)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

std::unique_ptr<ConnectionBackend> open_sqlite(const std::string& path, Access access) {
  return std::make_unique<SqliteConnection>(path, access);
}

std::unique_ptr<ConnectionBackend> sqlite_private_copy(ConnectionBackend& source) {
  const auto* sqlite = dynamic_cast<const SqliteConnection*>(&source);
  if (!sqlite) throw std::logic_error("a private copy of a database that is not an SQLite file");
  return SqliteConnection::private_copy(*sqlite);
}

}  // namespace hydrocoef::store::detail
