// The PostgreSQL backend of store::Connection: one session with a server
// through libpq. Statements are sent with their parameters (text, and bytea
// as binary) and read back as text: float8 in PostgreSQL's shortest exact
// form (extra_float_digits > 0, PostgreSQL 12 and newer), so a double read
// back is the double sent.
#include <libpq-fe.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <system_error>
#include <utility>

#include "src/core/error.hpp"
#include "src/store/backend.hpp"
#include "src/store/dialect.hpp"

namespace hydrocoef::store::detail {
namespace {

// Type OIDs of PostgreSQL's built-in types (pg_type.dat).
constexpr Oid kBool = 16, kBytea = 17, kInt8 = 20, kInt2 = 21, kInt4 = 23, kText = 25, kOid = 26, kFloat4 = 700,
              kFloat8 = 701, kNumeric = 1700;

/// Writers of one hydrocoef database (a PostgreSQL database and schema) take
/// a transaction-scoped advisory lock, so that they run one after another as
/// SQLite's writers do: the pair (kWriteLock, a hash of the schema's name),
/// so that databases in other schemas of the server do not wait for them.
constexpr int kWriteLock = 0x68796472;  // "hydr"

/// The first line of a libpq message, without its trailing newline.
std::string first_line(const char* message) {
  std::string text = message ? message : "";
  const auto newline = text.find('\n');
  if (newline != std::string::npos) text.resize(newline);
  return text;
}

struct ResultDeleter {
  void operator()(PGresult* result) const { PQclear(result); }
};
using Result = std::unique_ptr<PGresult, ResultDeleter>;

class PgConnection;

class PgStatement final : public StatementBackend {
 public:
  PgStatement(PgConnection& connection, std::string_view sql);

  void bind_double(int index, double value) override {
    // NaN is stored as NULL, as SQLite stores it: a value left undefined (a
    // fit's R^2 of a constant) reads back as absent on both backends.
    if (std::isnan(value)) return bind_null(index);
    std::string text;
    if (std::isinf(value)) {
      text = value > 0 ? "Infinity" : "-Infinity";
    } else {
      char buffer[32];
      const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
      text.assign(buffer, result.ptr);
    }
    set(index, std::move(text), kFloat8, 0);
  }
  void bind_int(int index, std::int64_t value) override { set(index, std::to_string(value), kInt8, 0); }
  void bind_text(int index, std::string_view value) override;
  void bind_blob(int index, const void* data, std::size_t size) override {
    set(index, std::string(static_cast<const char*>(data), size), kBytea, 1);
  }
  void bind_null(int index) override {
    Parameter& p = parameter(index);
    p = Parameter{};
  }
  bool step() override;
  void reset() override {
    result_.reset();
    row_ = -1;
    rows_ = 0;
    for (auto& p : parameters_) p = Parameter{};
  }
  ColumnType column_type(int column) const override {
    check_column(column);
    if (PQgetisnull(result_.get(), row_, column)) return ColumnType::Null;
    switch (PQftype(result_.get(), column)) {
      case kBool:
      case kInt2:
      case kInt4:
      case kInt8:
      case kOid: return ColumnType::Integer;
      case kFloat4:
      case kFloat8:
      case kNumeric: return ColumnType::Float;
      case kBytea: return ColumnType::Blob;
      default: return ColumnType::Text;
    }
  }
  double get_double(int column) const override {
    const std::string_view text = get_text(column);
    if (text == "NaN") return std::numeric_limits<double>::quiet_NaN();
    if (text == "Infinity") return std::numeric_limits<double>::infinity();
    if (text == "-Infinity") return -std::numeric_limits<double>::infinity();
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
  }
  std::int64_t get_int(int column) const override {
    const std::string_view text = get_text(column);
    if (text == "t") return 1;
    if (text == "f") return 0;
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) {
      // numeric or float text where an integer was asked for: SQLite's truncation
      double real = 0.0;
      std::from_chars(text.data(), text.data() + text.size(), real);
      if (std::isfinite(real) && std::abs(real) < 9.2e18) value = static_cast<std::int64_t>(real);
    }
    return value;
  }
  std::string_view get_text(int column) const override {
    check_column(column);
    if (PQgetisnull(result_.get(), row_, column)) return {};
    return {PQgetvalue(result_.get(), row_, column),
            static_cast<std::size_t>(PQgetlength(result_.get(), row_, column))};
  }
  std::string_view get_blob(int column) const override;
  const char* column_name(int column) const override {
    check_column(column);
    return PQfname(result_.get(), column);
  }

 private:
  struct Parameter {
    bool bound = false;  ///< false: NULL
    std::string value;
    Oid type = 0;
    int format = 0;  ///< 0 text, 1 binary
  };
  Parameter& parameter(int index);
  void set(int index, std::string value, Oid type, int format) {
    Parameter& p = parameter(index);
    p.bound = true;
    p.value = std::move(value);
    p.type = type;
    p.format = format;
  }
  void check_column(int column) const {
    if (!result_ || row_ < 0 || row_ >= rows_ || column < 0 || column >= PQnfields(result_.get()))
      throw std::logic_error("PostgreSQL result: no column " + std::to_string(column) + " in this row");
  }

  PgConnection& connection_;
  NumberedStatement statement_;
  std::vector<Parameter> parameters_;
  Result result_;
  int row_ = -1;
  int rows_ = 0;
  mutable std::vector<std::string> blobs_;  ///< decoded bytea of the current row, by column
  mutable std::vector<int> blob_rows_;      ///< the row each was decoded for
};

class PgConnection final : public ConnectionBackend {
 public:
  PgConnection(const std::string& url, std::string display, Access access);
  ~PgConnection() override {
    if (connection_) PQfinish(connection_);
  }
  PgConnection(const PgConnection&) = delete;
  PgConnection& operator=(const PgConnection&) = delete;

  Backend kind() const override { return Backend::PostgreSQL; }
  void execute(std::string_view sql) override {
    const std::string text(sql);
    Result result(PQexec(connection_, text.c_str()));
    check(result.get(), "executing '" + std::string(sql.substr(0, 60)) + "'");
  }
  std::unique_ptr<StatementBackend> prepare(std::string_view sql) override {
    return std::make_unique<PgStatement>(*this, sql);
  }
  bool read_only() const override { return read_only_; }
  void begin_write() override;
  void commit() override {
    if (depth_ == 1) execute("COMMIT");
    if (depth_ > 0) --depth_;
  }
  void begin_read() override;
  void end_read() noexcept override;
  void rollback() noexcept override {
    depth_ = 0;
    reading_ = false;
    if (PQtransactionStatus(connection_) != PQTRANS_IDLE) PQclear(PQexec(connection_, "ROLLBACK"));
  }
  void use_wal() override {}

  PGconn* handle() const { return connection_; }
  const std::string& display() const { return display_; }
  /// Throws unless `result` is a success.
  void check(PGresult* result, const std::string& what);

 private:
  PGconn* connection_ = nullptr;
  std::string display_;
  bool read_only_ = false;
  int depth_ = 0;         ///< transactions open, the outermost one real
  bool reading_ = false;  ///< the outermost one is a read snapshot
};

PgStatement::PgStatement(PgConnection& connection, std::string_view sql)
    : connection_(connection), statement_(postgresql_statement(sql)) {
  parameters_.resize(static_cast<std::size_t>(statement_.parameters));
}

PgStatement::Parameter& PgStatement::parameter(int index) {
  if (index < 1 || index > statement_.parameters)
    throw std::logic_error("SQL parameter " + std::to_string(index) + " of a statement with " +
                           std::to_string(statement_.parameters) + ": '" + statement_.sql.substr(0, 60) + "'");
  return parameters_[static_cast<std::size_t>(index - 1)];
}

bool PgStatement::step() {
  if (!result_) {
    const std::size_t n = parameters_.size();
    std::vector<Oid> types(n);
    std::vector<const char*> values(n);
    std::vector<int> lengths(n), formats(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Parameter& p = parameters_[i];
      // An unbound parameter is NULL, as in SQLite; one the statement never
      // names still needs a type.
      types[i] = p.bound ? p.type : (statement_.referenced[i] ? 0 : kText);
      values[i] = p.bound ? p.value.data() : nullptr;
      lengths[i] = static_cast<int>(p.value.size());
      formats[i] = p.format;
    }
    result_.reset(PQexecParams(connection_.handle(), statement_.sql.c_str(), static_cast<int>(n), types.data(),
                               values.data(), lengths.data(), formats.data(), 0));
    connection_.check(result_.get(), "running '" + statement_.sql.substr(0, 60) + "'");
    rows_ = PQresultStatus(result_.get()) == PGRES_TUPLES_OK ? PQntuples(result_.get()) : 0;
    row_ = -1;
    const auto columns = static_cast<std::size_t>(std::max(0, PQnfields(result_.get())));
    blobs_.assign(columns, std::string());
    blob_rows_.assign(columns, -1);
  }
  if (row_ < rows_) ++row_;
  return row_ < rows_;
}

std::string_view PgStatement::get_blob(int column) const {
  check_column(column);
  if (PQgetisnull(result_.get(), row_, column)) return {};
  const auto c = static_cast<std::size_t>(column);
  if (blob_rows_[c] == row_) return blobs_[c];
  // bytea_output = hex: "\x" and two hex digits a byte.
  const std::string_view text = get_text(column);
  std::string& out = blobs_[c];
  out.clear();
  if (text.size() < 2 || text[0] != '\\' || text[1] != 'x' || text.size() % 2 != 0)
    throw std::runtime_error("PostgreSQL returned a bytea value not in hex form");
  out.resize((text.size() - 2) / 2);
  const auto digit = [](char h) -> int {
    if (h >= '0' && h <= '9') return h - '0';
    if (h >= 'a' && h <= 'f') return h - 'a' + 10;
    if (h >= 'A' && h <= 'F') return h - 'A' + 10;
    throw std::runtime_error("PostgreSQL returned a bytea value with a character that is not hex");
  };
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<char>(digit(text[2 + 2 * i]) * 16 + digit(text[3 + 2 * i]));
  blob_rows_[c] = row_;
  return out;
}

void PgStatement::bind_text(int index, std::string_view value) {
  // Text parameters travel as C strings: a NUL would cut the value short.
  if (value.find('\0') != std::string_view::npos)
    throw InputError(SourceLocation{connection_.display()},
                     "a text value holds a NUL byte ('" + printable_text(value, 60) +
                         "'), which PostgreSQL cannot store; expected text without NUL bytes");
  set(index, std::string(value), kText, 0);
}

void ignore_notice(void*, const char*) {}

PgConnection::PgConnection(const std::string& url, std::string display, Access access)
    : display_(std::move(display)), read_only_(access == Access::ReadOnly || access == Access::Immutable) {
  const int timeout = busy_timeout_seconds();
  // A server that does not answer would hold libpq for as long as the
  // operating system keeps trying (minutes): without a connect_timeout of
  // the URL's own or $PGCONNECT_TIMEOUT, the connection waits
  // HYDROCOEF_DB_TIMEOUT (at least libpq's 2 s). The URL is expanded after
  // the default, so that its own connect_timeout wins.
  const std::string connect_timeout = std::to_string(std::max(timeout, 2));
  const char* environment_timeout = std::getenv("PGCONNECT_TIMEOUT");
  const bool use_default = !environment_timeout || !*environment_timeout;
  const char* const keywords[] = {"connect_timeout", "dbname", nullptr};
  const char* const values[] = {use_default ? connect_timeout.c_str() : environment_timeout, url.c_str(), nullptr};
  connection_ = PQconnectdbParams(keywords, values, 1);
  if (!connection_ || PQstatus(connection_) != CONNECTION_OK) {
    const std::string message = first_line(connection_ ? PQerrorMessage(connection_) : "out of memory");
    PQfinish(connection_);  // the destructor does not run for an object whose constructor throws
    connection_ = nullptr;
    throw InputError(SourceLocation{display_},
                     "cannot connect to the PostgreSQL server: " + printable_text(message, 200));
  }
  PQsetNoticeProcessor(connection_, ignore_notice, nullptr);
  // lock_timeout 0 would wait for ever; HYDROCOEF_DB_TIMEOUT=0 means "do not wait".
  const std::string wait = timeout == 0 ? "1ms" : std::to_string(timeout) + "s";
  try {
    // Doubles in their shortest exact form need PostgreSQL 12 (on 11 and
    // older extra_float_digits gives 17 digits, not always the same double
    // back through a shorter print).
    if (PQserverVersion(connection_) < 120000)
      throw InputError(SourceLocation{display_}, "the server is PostgreSQL " +
                                                     std::to_string(PQserverVersion(connection_) / 10000) +
                                                     "; expected PostgreSQL 12 or newer");
    execute(
        "SET client_min_messages = warning; SET extra_float_digits = 3; SET bytea_output = 'hex'; "
        "SET client_encoding = 'UTF8'; SET standard_conforming_strings = on; SET lock_timeout = '" +
        wait + "'");
    if (read_only_) execute("SET default_transaction_read_only = on");
    // A search_path that names no existing schema leaves nowhere to read or
    // write (and no schema to key the writers' lock by).
    PGresult* schema = PQexec(connection_, "SELECT pg_catalog.current_schema()");
    const bool none =
        PQresultStatus(schema) == PGRES_TUPLES_OK && PQntuples(schema) == 1 && PQgetisnull(schema, 0, 0) == 1;
    PQclear(schema);
    if (none)
      throw InputError(SourceLocation{display_},
                       "the search_path names no schema that exists on the server; expected an existing schema "
                       "(CREATE SCHEMA, or options=-csearch_path%3DNAME in the URL)");
    // The search_path pinned to the schema in use alone (pg_catalog, searched
    // first when not named, stays first): a function or operator planted in
    // another schema of the user's search_path is never chosen for one of
    // the store's calls (CVE-2018-1058; the calls are qualified as well,
    // dialect.hpp), and the schema check covers every schema searched.
    execute("SELECT pg_catalog.set_config('search_path', pg_catalog.quote_ident(pg_catalog.current_schema()), false)");
    // session_replication_role other than origin (e.g. options=-c
    // session_replication_role=replica in the URL) switches off the triggers
    // that mark fits and surfaces stale when their forces change.
    PGresult* role = PQexec(connection_, "SELECT pg_catalog.current_setting('session_replication_role')");
    const std::string value =
        PQresultStatus(role) == PGRES_TUPLES_OK && PQntuples(role) == 1 && !PQgetisnull(role, 0, 0)
            ? std::string(PQgetvalue(role, 0, 0))
            : std::string("(unreadable)");
    PQclear(role);
    if (value != "origin")
      throw InputError(SourceLocation{display_},
                       "the session's session_replication_role is '" + printable_text(value, 40) +
                           "', which switches off the triggers that mark fits and surfaces stale; expected 'origin' "
                           "(remove session_replication_role from the URL's options, PGOPTIONS or the role's "
                           "settings)");
  } catch (...) {
    PQfinish(connection_);
    connection_ = nullptr;
    throw;
  }
}

// A write transaction begun inside another joins it (see Transaction).
void PgConnection::begin_read() {
  if (depth_ > 0) {
    ++depth_;
    return;
  }
  execute("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY");
  reading_ = true;
  depth_ = 1;
}

void PgConnection::end_read() noexcept {
  if (depth_ > 0 && --depth_ == 0) {
    Result result(PQexec(connection_, "COMMIT"));
    reading_ = false;
  }
}

void PgConnection::begin_write() {
  if (depth_ > 0 && reading_) throw std::logic_error("a write transaction begun inside a read snapshot");
  if (depth_ > 0) {
    ++depth_;
    return;
  }
  execute("BEGIN");
  try {
    execute("SELECT pg_catalog.pg_advisory_xact_lock(" + std::to_string(kWriteLock) +
            ", pg_catalog.hashtext(pg_catalog.current_schema()) & 2147483647)");
  } catch (...) {
    rollback();
    throw;
  }
  depth_ = 1;
}

void PgConnection::check(PGresult* result, const std::string& what) {
  const ExecStatusType status = result ? PQresultStatus(result) : PGRES_FATAL_ERROR;
  if (status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK) return;
  const SourceLocation where{display_};
  const char* code_text = result ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  const std::string code = code_text ? code_text : "";
  const std::string detail =
      printable_text(first_line(result ? PQresultErrorMessage(result) : PQerrorMessage(connection_)), 200);
  // What a user can cause (another process, the server, the data) is said in
  // words and is exit 2; anything else is a bug in hydrocoef.
  if (code == "57014")
    throw InputError(where, "database: the server cancelled the statement while " + what + " (" + detail +
                                "; statement_timeout or an administrator); nothing was changed");
  if (PQstatus(connection_) != CONNECTION_OK || code.rfind("08", 0) == 0 || code.rfind("57", 0) == 0)
    throw InputError(where, "database: lost the connection to the PostgreSQL server while " + what + " (" + detail +
                                "); the transaction was not committed");
  if (code == "55P03" || code == "40001" || code == "40P01")
    throw InputError(where, "database is busy: another process has held it for " +
                                std::to_string(busy_timeout_seconds()) +
                                " s (HYDROCOEF_DB_TIMEOUT sets how long to wait); nothing was changed, try again when "
                                "it has finished");
  if (code == "53100")
    throw InputError(where,
                     "database: the server's disk is full while " + what + " (" + detail + "); nothing was changed");
  if (code == "25006")
    throw InputError(where, "database is read-only here (" + detail + "); expected a writable database for " + what);
  if (code.rfind("53", 0) == 0 || code == "42501" || code.rfind("28", 0) == 0 || code == "22021" || code == "54000")
    throw InputError(where, "database: " + what + ": " + detail);
  // hydrocoef's statements are fixed and tested against the schema it makes:
  // a value or constraint the server refuses, or a missing table, column or
  // constraint, comes from a schema or rows another program changed.
  if (code.rfind("22", 0) == 0 || code.rfind("23", 0) == 0 || code == "42P10" || code == "42804" || code == "42703" ||
      code == "42P01")
    throw InputError(where, "database: " + what + ": " + detail + " (SQLSTATE " + code +
                                "); expected a schema and rows as hydrocoef makes them: was it changed by another "
                                "program?");
  throw std::runtime_error(display_ + ": database: " + what + ": " + detail);
}

}  // namespace

std::unique_ptr<ConnectionBackend> open_postgresql(const std::string& url, const std::string& display, Access access) {
  return std::make_unique<PgConnection>(url, display, access);
}

}  // namespace hydrocoef::store::detail
