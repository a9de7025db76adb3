// The store's connection to a database: one connection, one prepared
// statement, one transaction guard, over either backend (an SQLite file or a
// PostgreSQL server, src/store/backend.hpp). Every failure becomes an
// exception naming the database and the backend's own message: InputError
// for what a user can cause (a busy or full database, a refused connection),
// std::runtime_error for a bug in hydrocoef's SQL.
//
// SQL is written once, in the dialect SQLite and PostgreSQL share: '?' or
// '?N' parameters (PostgreSQL gets '$N'), INSERT ... ON CONFLICT, RETURNING,
// TRUE. Neither backend's C header is included here (nor, so, in
// database.hpp and everything that includes it).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef::store {

class Statement;

namespace detail {
class ConnectionBackend;
class StatementBackend;
}  // namespace detail

/// Which kind of database a connection talks to.
enum class Backend { SQLite, PostgreSQL };

/// How a connection opens its database.
enum class Access {
  ReadWrite,        ///< an existing file, for reading and writing
  ReadWriteCreate,  ///< the same, creating the file when missing
  ReadOnly,         ///< an existing file, never written
  /// An existing SQLite file on a read-only medium: read without locks and
  /// without the WAL's -shm/-wal files (SQLite's immutable=1); valid only
  /// while no process writes it.
  Immutable,
};

/// The type of a value in a result row.
enum class ColumnType { Integer, Float, Text, Blob, Null };

/// How long a writer waits for another process's transaction before giving
/// up: $HYDROCOEF_DB_TIMEOUT seconds (0 to 3600), default 60. InputError when
/// the variable is set to anything else.
int busy_timeout_seconds();

class Connection {
 public:
  /// Opens an SQLite database file.
  Connection(const std::string& path, Access access);
  /// Connects to a PostgreSQL server with a libpq connection URL
  /// ("postgresql://host/db?..."); `display` names it in messages.
  static Connection postgresql(const std::string& url, const std::string& display, Access access);
  /// A private copy of an SQLite database (`source`, only read) in a
  /// temporary database of SQLite's own, deleted when the connection closes;
  /// named as `source` in messages. What a reader opens to bring an older
  /// schema up to date without writing the file.
  static Connection sqlite_private_copy(Connection& source);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;
  Connection(Connection&& other) noexcept;
  Connection& operator=(Connection&& other) noexcept;

  Backend backend() const;
  /// Runs one or more statements that return no rows (in the backend's own
  /// dialect: the schema's migrations, PRAGMAs, SET).
  void execute(std::string_view sql);
  Statement prepare(std::string_view sql);
  /// The file's path, or the server URL without credentials.
  const std::string& path() const { return name_; }
  /// True when the database cannot be written through this connection (an
  /// SQLite file opened read-only or read-only on disk; a read-only session).
  bool read_only() const;

  /// Begins a write transaction that no other writer runs beside: SQLite's
  /// BEGIN IMMEDIATE; on PostgreSQL BEGIN and a transaction-scoped advisory
  /// lock. Waits up to busy_timeout_seconds() for another writer.
  void begin_write();
  void commit();
  /// Rolls back an open transaction; never throws.
  void rollback() noexcept;
  /// SQLite: switches the file to write-ahead logging once a write has
  /// committed (see RunDatabase); PostgreSQL: nothing to do.
  void use_wal();

  detail::ConnectionBackend& backend_impl() { return *backend_; }

 private:
  Connection(std::unique_ptr<detail::ConnectionBackend> backend, std::string name);
  std::unique_ptr<detail::ConnectionBackend> backend_;
  std::string name_;
};

class Statement {
 public:
  explicit Statement(std::unique_ptr<detail::StatementBackend> backend);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&&) = delete;

  // Parameters are 1-based, as in SQLite.
  Statement& bind(int index, double value);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, std::string_view value);
  Statement& bind(int index, const std::optional<double>& value);
  Statement& bind_null(int index);
  /// Binds doubles as a blob of their bytes (float64, host order: little-endian on every target here).
  Statement& bind_doubles(int index, const std::vector<double>& values);

  /// Advances to the next row; false when done.
  bool step();
  /// Runs a statement that returns no row.
  void run();
  /// Makes the statement ready to run again, its parameters unbound.
  void reset();

  // Columns are 0-based, as in SQLite.
  bool is_null(int column) const;
  double get_double(int column) const;
  std::int64_t get_int(int column) const;
  std::string get_text(int column) const;
  std::optional<double> get_optional_double(int column) const;
  std::vector<double> get_doubles(int column) const;
  ColumnType column_type(int column) const;
  /// Size in bytes of a text or blob value.
  std::size_t column_bytes(int column) const;
  const char* column_name(int column) const;

 private:
  std::unique_ptr<detail::StatementBackend> backend_;
};

/// Runs an INSERT ... RETURNING id and gives the new row's id (the
/// statement is reset for its next row).
std::int64_t returned_id(Statement& insert);

/// A write transaction (Connection::begin_write) for the guard's lifetime;
/// rolled back on destruction unless commit() was called, so an exception
/// anywhere leaves the database as it was. A transaction begun while another
/// is open on the connection joins it: only the outermost one commits, and a
/// rollback at any depth rolls back the whole (RunDatabase::merge stores many
/// shards through the methods that store one, all or none).
class Transaction {
 public:
  explicit Transaction(Connection& connection);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Connection& connection_;
  bool open_ = true;
};

}  // namespace hydrocoef::store
