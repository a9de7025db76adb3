#include "src/store/sqlite.hpp"

#include <sqlite3.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <string>
#include <utility>

#include "src/core/error.hpp"

namespace hydrocoef::store {

int busy_timeout_seconds() {
  const char* text = std::getenv("HYDROCOEF_DB_TIMEOUT");
  if (!text || !*text) return 60;
  int seconds = -1;
  const std::string_view view(text);
  const auto [end, ec] = std::from_chars(view.data(), view.data() + view.size(), seconds);
  if (ec != std::errc() || end != view.data() + view.size() || seconds < 0 || seconds > 3600)
    throw InputError("HYDROCOEF_DB_TIMEOUT is '" + printable_text(view, 40) +
                     "'; expected a whole number of seconds from 0 to 3600");
  return seconds;
}

Connection::Connection(const std::string& path, Access access) : path_(path) {
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

Connection::~Connection() {
  if (db_) sqlite3_close_v2(db_);
}

Connection::Connection(Connection&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)), path_(std::move(other.path_)) {}

Connection& Connection::operator=(Connection&& other) noexcept {
  if (this != &other) {
    if (db_) sqlite3_close_v2(db_);
    db_ = std::exchange(other.db_, nullptr);
    path_ = std::move(other.path_);
  }
  return *this;
}

void Connection::fail(int rc, std::string_view what) const {
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

void Connection::execute(std::string_view sql) {
  char* error = nullptr;
  const std::string text(sql);
  const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error);
  if (rc != SQLITE_OK) {
    sqlite3_free(error);
    fail(rc, "executing SQL");
  }
}

Statement Connection::prepare(std::string_view sql) { return Statement(*this, sql); }

std::int64_t Connection::last_insert_id() const { return sqlite3_last_insert_rowid(db_); }

int Connection::changes() const { return sqlite3_changes(db_); }

Statement::Statement(const Connection& connection, std::string_view sql) : connection_(&connection) {
  const int rc =
      sqlite3_prepare_v2(connection.handle(), sql.data(), static_cast<int>(sql.size()), &statement_, nullptr);
  if (rc != SQLITE_OK) connection.fail(rc, "preparing '" + std::string(sql.substr(0, 60)) + "'");
}

Statement::~Statement() { sqlite3_finalize(statement_); }

Statement::Statement(Statement&& other) noexcept
    : connection_(other.connection_), statement_(std::exchange(other.statement_, nullptr)) {}

Statement& Statement::bind(int index, double value) {
  sqlite3_bind_double(statement_, index, value);
  return *this;
}
Statement& Statement::bind(int index, std::int64_t value) {
  sqlite3_bind_int64(statement_, index, value);
  return *this;
}
Statement& Statement::bind(int index, std::string_view value) {
  sqlite3_bind_text(statement_, index, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
  return *this;
}
Statement& Statement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : bind_null(index);
}
Statement& Statement::bind_doubles(int index, const std::vector<double>& values) {
  if (values.empty()) {  // a blob of no bytes, not NULL
    sqlite3_bind_zeroblob(statement_, index, 0);
    return *this;
  }
  sqlite3_bind_blob64(statement_, index, values.data(), values.size() * sizeof(double), SQLITE_TRANSIENT);
  return *this;
}
Statement& Statement::bind_null(int index) {
  sqlite3_bind_null(statement_, index);
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(statement_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  connection_->fail(rc, "running '" + std::string(sqlite3_sql(statement_)).substr(0, 60) + "'");
}

void Statement::run() {
  while (step()) {}
  reset();
}

void Statement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

bool Statement::is_null(int column) const { return sqlite3_column_type(statement_, column) == SQLITE_NULL; }
double Statement::get_double(int column) const { return sqlite3_column_double(statement_, column); }
std::int64_t Statement::get_int(int column) const { return sqlite3_column_int64(statement_, column); }
std::string Statement::get_text(int column) const {
  const auto* text = sqlite3_column_text(statement_, column);
  return text ? std::string(reinterpret_cast<const char*>(text)) : std::string();
}
std::vector<double> Statement::get_doubles(int column) const {
  const auto* bytes = static_cast<const double*>(sqlite3_column_blob(statement_, column));
  const auto size = static_cast<std::size_t>(sqlite3_column_bytes(statement_, column));
  if (bytes == nullptr || size % sizeof(double) != 0) return {};
  return std::vector<double>(bytes, bytes + size / sizeof(double));
}
int Statement::column_type(int column) const { return sqlite3_column_type(statement_, column); }
std::size_t Statement::column_bytes(int column) const {
  return static_cast<std::size_t>(sqlite3_column_bytes(statement_, column));
}
const char* Statement::column_name(int column) const { return sqlite3_column_name(statement_, column); }
std::optional<double> Statement::get_optional_double(int column) const {
  if (is_null(column)) return std::nullopt;
  return get_double(column);
}

Transaction::Transaction(Connection& connection) : connection_(connection) { connection_.execute("BEGIN IMMEDIATE"); }

Transaction::~Transaction() {
  if (open_) sqlite3_exec(connection_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::commit() {
  connection_.execute("COMMIT");
  open_ = false;
}

}  // namespace hydrocoef::store
