// What a store backend implements (src/store/sqlite_backend.cpp,
// src/store/postgresql_backend.cpp) behind store::Connection and
// store::Statement. Only src/store includes this header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "src/store/connection.hpp"

namespace hydrocoef::store::detail {

class StatementBackend {
 public:
  virtual ~StatementBackend() = default;
  /// NaN binds as NULL (SQLite's own rule, kept on PostgreSQL); infinities as
  /// themselves.
  virtual void bind_double(int index, double value) = 0;
  virtual void bind_int(int index, std::int64_t value) = 0;
  virtual void bind_text(int index, std::string_view value) = 0;
  /// Bytes as a blob (SQLite BLOB, PostgreSQL bytea); `size` 0 is an empty blob, not NULL.
  virtual void bind_blob(int index, const void* data, std::size_t size) = 0;
  virtual void bind_null(int index) = 0;
  virtual bool step() = 0;
  virtual void reset() = 0;
  virtual ColumnType column_type(int column) const = 0;
  virtual double get_double(int column) const = 0;
  virtual std::int64_t get_int(int column) const = 0;
  /// A text value's bytes (empty for NULL).
  virtual std::string_view get_text(int column) const = 0;
  /// A blob value's bytes (empty for NULL).
  virtual std::string_view get_blob(int column) const = 0;
  virtual const char* column_name(int column) const = 0;
};

class ConnectionBackend {
 public:
  virtual ~ConnectionBackend() = default;
  virtual Backend kind() const = 0;
  virtual void execute(std::string_view sql) = 0;
  virtual std::unique_ptr<StatementBackend> prepare(std::string_view sql) = 0;
  virtual bool read_only() const = 0;
  virtual void begin_write() = 0;
  virtual void commit() = 0;
  virtual void rollback() noexcept = 0;
  /// A read of several statements that must see one state of the database
  /// (ReadSnapshot): SQLite's deferred BEGIN (in WAL mode, one snapshot from
  /// the first read), PostgreSQL's REPEATABLE READ, READ ONLY. Inside an
  /// open transaction it joins it; a write may not begin inside a read.
  virtual void begin_read() = 0;
  virtual void end_read() noexcept = 0;
  virtual void use_wal() = 0;
};

std::unique_ptr<ConnectionBackend> open_sqlite(const std::string& path, Access access);
/// A private temporary SQLite database holding a copy of `source` (an SQLite
/// connection), which is only read: what a reader may change (migrate) without
/// writing the file. Deleted when closed.
std::unique_ptr<ConnectionBackend> sqlite_private_copy(ConnectionBackend& source);
std::unique_ptr<ConnectionBackend> open_postgresql(const std::string& url, const std::string& display, Access access);

/// A consistent read for the guard's lifetime (ConnectionBackend::begin_read).
class ReadSnapshot {
 public:
  explicit ReadSnapshot(ConnectionBackend& backend) : backend_(backend) { backend_.begin_read(); }
  ~ReadSnapshot() { backend_.end_read(); }
  ReadSnapshot(const ReadSnapshot&) = delete;
  ReadSnapshot& operator=(const ReadSnapshot&) = delete;

 private:
  ConnectionBackend& backend_;
};

}  // namespace hydrocoef::store::detail
