// Test support: a fresh, empty database on either store backend, and a
// backend-neutral dump of its rows.
//
// PostgreSQL tests run against the throw-away server that
// scripts/postgresql-test-server.sh starts: $HYDROCOEF_TEST_POSTGRESQL is its
// URL. Each TestDatabase gets a schema of its own there (dropped at the end),
// named in its URL's search_path, so tests never see each other's rows. When
// the variable is unset the PostgreSQL cases are skipped, unless
// $HYDROCOEF_TEST_POSTGRESQL_REQUIRED is set (scripts/test.sh sets it), when
// they fail.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "src/store/connection.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {

inline std::optional<std::string> postgresql_test_server() {
  const char* url = std::getenv("HYDROCOEF_TEST_POSTGRESQL");
  if (!url || !*url) return std::nullopt;
  return std::string(url);
}

/// The server's URL with a search_path of `schema` (which it does not create).
inline std::string url_with_schema(const std::string& server, const std::string& schema) {
  return server + (server.find('?') == std::string::npos ? "?" : "&") + "options=-csearch_path%3D" + schema;
}

inline const char* backend_name(store::Backend backend) {
  return backend == store::Backend::SQLite ? "SQLite" : "PostgreSQL";
}

namespace detail {

inline std::string dump_value(const store::Statement& row, int c) {
  switch (row.column_type(c)) {
    case store::ColumnType::Null: return "NULL";
    case store::ColumnType::Integer: return std::to_string(row.get_int(c));
    case store::ColumnType::Float: {
      char buffer[32];
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, row.get_double(c)).ptr;
      return std::string(buffer, end);
    }
    case store::ColumnType::Text: return "'" + row.get_text(c) + "'";
    case store::ColumnType::Blob: {
      const auto values = row.get_doubles(c);
      std::string text = "blob:";
      for (const double v : values) {
        char buffer[32];
        text += std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr) + ",";
      }
      return text;
    }
  }
  return "?";
}

}  // namespace detail

/// Every row of every table, as text, tables by name and rows sorted: two
/// dumps are equal when the databases hold the same rows, on either backend.
/// Doubles are written exactly (shortest round-trip form), blobs in hex.
/// `ignored` columns (e.g. imported_at) are left out.
inline std::string dump_rows(store::Connection& connection, const std::set<std::string>& ignored = {}) {
  const bool sqlite = connection.backend() == store::Backend::SQLite;
  std::vector<std::string> tables;
  {
    auto list = connection.prepare(
        sqlite ? "SELECT name FROM sqlite_schema WHERE type = 'table' AND name NOT LIKE 'sqlite%' ORDER BY name"
               : "SELECT table_name FROM information_schema.tables WHERE table_schema = current_schema() AND "
                 "table_name <> 'hydrocoef_schema' ORDER BY table_name");
    while (list.step()) tables.push_back(list.get_text(0));
  }
  std::string out;
  for (const auto& table : tables) {
    std::vector<std::string> columns;
    {
      auto info = connection.prepare(sqlite ? "SELECT name FROM pragma_table_info(?) ORDER BY cid"
                                            : "SELECT column_name FROM information_schema.columns WHERE table_schema "
                                              "= current_schema() AND table_name = ? ORDER BY column_name");
      info.bind(1, table);
      while (info.step())
        if (!ignored.count(info.get_text(0))) columns.push_back(info.get_text(0));
    }
    std::sort(columns.begin(), columns.end());
    std::string select;
    for (const auto& c : columns) select += (select.empty() ? "" : ", ") + ("\"" + c + "\"");
    auto rows = connection.prepare("SELECT " + select + " FROM \"" + table + "\"");
    std::vector<std::string> lines;
    while (rows.step()) {
      std::string line;
      for (std::size_t c = 0; c < columns.size(); ++c) line += "|" + detail::dump_value(rows, static_cast<int>(c));
      lines.push_back(std::move(line));
    }
    std::sort(lines.begin(), lines.end());
    out += "== " + table + "\n";
    for (const auto& line : lines) out += line + "\n";
  }
  return out;
}

class TestDatabase {
 public:
  /// An SQLite file in a temporary folder, or a new schema on the test
  /// server. available() is false (and the test should GTEST_SKIP) when no
  /// server is configured.
  explicit TestDatabase(store::Backend backend) : backend_(backend) {
    if (backend == store::Backend::SQLite) {
      location_ = (dir_ / "runs.db").string();
      return;
    }
    const auto server = postgresql_test_server();
    if (!server) return;
    static std::atomic<int> counter{0};
    schema_ = "hc_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    server_ = *server;
    admin().execute("DROP SCHEMA IF EXISTS " + schema_ + " CASCADE; CREATE SCHEMA " + schema_);
    location_ = url_with_schema(*server, schema_);
  }
  ~TestDatabase() {
    if (schema_.empty()) return;
    try {
      admin().execute("DROP SCHEMA IF EXISTS " + schema_ + " CASCADE");
    } catch (...) {}
  }
  TestDatabase(const TestDatabase&) = delete;
  TestDatabase& operator=(const TestDatabase&) = delete;

  /// An SQLite file of the test's own choosing (e.g. a shard).
  TestDatabase(store::Backend backend, std::string sqlite_path)
      : backend_(backend), location_(std::move(sqlite_path)) {}

  bool available() const { return !location_.empty(); }
  /// What RunDatabase and --db take.
  const std::string& location() const { return location_; }
  const TempDir& dir() const { return dir_; }
  store::Backend backend() const { return backend_; }

  /// A connection of the test's own to the database (for tampering).
  store::Connection connect() const {
    if (backend_ == store::Backend::SQLite) return store::Connection(location_, store::Access::ReadWrite);
    return store::Connection::postgresql(location_, location_, store::Access::ReadWrite);
  }

  /// Every row of every table (dump_rows), `ignored` columns left out.
  std::string dump(const std::set<std::string>& ignored = {}) const {
    store::Connection connection = connect();
    return dump_rows(connection, ignored);
  }

 private:
  store::Connection admin() const { return store::Connection::postgresql(server_, server_, store::Access::ReadWrite); }

  store::Backend backend_;
  TempDir dir_;
  std::string server_;
  std::string schema_;
  std::string location_;
};

/// In a test body: skips (or, with $HYDROCOEF_TEST_POSTGRESQL_REQUIRED set,
/// fails) when `db` has no server.
#define HYDROCOEF_NEED_DATABASE(db)                                                                      \
  do {                                                                                                   \
    if (!(db).available()) {                                                                             \
      if (std::getenv("HYDROCOEF_TEST_POSTGRESQL_REQUIRED"))                                             \
        FAIL() << "HYDROCOEF_TEST_POSTGRESQL is not set (scripts/postgresql-test-server.sh starts one)"; \
      GTEST_SKIP() << "no PostgreSQL test server: HYDROCOEF_TEST_POSTGRESQL is not set";                 \
    }                                                                                                    \
  } while (false)

}  // namespace hydrocoef::test
