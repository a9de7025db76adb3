// A thin RAII layer over the SQLite C API for src/store: one connection, one
// prepared statement, one transaction guard. Every SQLite failure becomes an
// exception naming the database file and SQLite's own message.
//
// SQLite's own header stays out of this one (and so out of database.hpp and
// everything that includes it): the handles are declared here, as SQLite
// declares them, and only src/store's sources include <sqlite3.h>.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// SQLite's handle types, declared as <sqlite3.h> declares them.
struct sqlite3;
struct sqlite3_stmt;

namespace hydrocoef::store {

class Statement;

/// How a connection opens its file.
enum class Access {
  ReadWrite,        ///< an existing file, for reading and writing
  ReadWriteCreate,  ///< the same, creating the file when missing
  ReadOnly,         ///< an existing file, never written
  /// An existing file on a read-only medium: read without locks and without
  /// the WAL's -shm/-wal files (SQLite's immutable=1); valid only while no
  /// process writes it.
  Immutable,
};

/// How long a writer waits for another process's transaction before giving
/// up: $HYDROCOEF_DB_TIMEOUT seconds (0 to 3600), default 60. InputError when
/// the variable is set to anything else.
int busy_timeout_seconds();

class Connection {
 public:
  /// Opens the database file.
  Connection(const std::string& path, Access access);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;
  Connection(Connection&& other) noexcept;
  Connection& operator=(Connection&& other) noexcept;

  /// Runs one or more statements that return no rows.
  void execute(std::string_view sql);
  Statement prepare(std::string_view sql);
  std::int64_t last_insert_id() const;
  int changes() const;
  const std::string& path() const { return path_; }
  sqlite3* handle() const { return db_; }

  /// Throws the right exception for SQLite result code `rc` (with context).
  [[noreturn]] void fail(int rc, std::string_view what) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

class Statement {
 public:
  Statement(const Connection& connection, std::string_view sql);
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
  void reset();

  // Columns are 0-based, as in SQLite.
  bool is_null(int column) const;
  double get_double(int column) const;
  std::int64_t get_int(int column) const;
  std::string get_text(int column) const;
  std::optional<double> get_optional_double(int column) const;
  std::vector<double> get_doubles(int column) const;
  /// SQLITE_INTEGER, SQLITE_FLOAT, SQLITE_TEXT, SQLITE_BLOB or SQLITE_NULL
  /// (<sqlite3.h>).
  int column_type(int column) const;
  /// Size in bytes of a text or blob value.
  std::size_t column_bytes(int column) const;
  const char* column_name(int column) const;

 private:
  const Connection* connection_;
  sqlite3_stmt* statement_ = nullptr;
};

/// BEGIN IMMEDIATE on construction; ROLLBACK on destruction unless commit()
/// was called, so an exception anywhere leaves the database as it was.
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
