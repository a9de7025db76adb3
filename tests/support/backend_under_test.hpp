// Test support: the store backend a test binary runs against, so that the
// store, CLI and reliability suites written with SQLite file names run
// unchanged on PostgreSQL too.
//
// $HYDROCOEF_TEST_BACKEND is unset (or "sqlite") for the SQLite run and
// "postgresql" for the second run that tests/CMakeLists.txt registers (tests
// named "postgresql.*"), against the server in $HYDROCOEF_TEST_POSTGRESQL.
// There a test's database file name (dir / "runs.db") stands for a schema of
// its own on the server: database_location() gives what RunDatabase and --db
// take, run_cli() passes it for --db and for the default database, and
// dump_database() dumps it. Tests about the SQLite file itself (its bytes,
// its header, its WAL) say so with HYDROCOEF_SQLITE_FILE_ONLY.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "src/store/connection.hpp"
#include "src/store/location.hpp"
#include "tests/support/test_database.hpp"

namespace hydrocoef::test {

/// The backend this test binary runs against ($HYDROCOEF_TEST_BACKEND).
inline store::Backend backend_under_test() {
  const char* name = std::getenv("HYDROCOEF_TEST_BACKEND");
  if (!name || !*name || std::string(name) == "sqlite") return store::Backend::SQLite;
  if (std::string(name) == "postgresql") return store::Backend::PostgreSQL;
  throw std::runtime_error(std::string("HYDROCOEF_TEST_BACKEND is '") + name + "'; expected sqlite or postgresql");
}

inline bool on_postgresql() { return backend_under_test() == store::Backend::PostgreSQL; }

namespace detail {

/// The schemas this process made on the test server, by the database file
/// name they stand for; dropped when the process ends.
class SchemaRegistry {
 public:
  static SchemaRegistry& instance() {
    static SchemaRegistry registry;
    return registry;
  }
  ~SchemaRegistry() {
    for (const auto& [path, schema] : schemas_) {
      try {
        admin().execute("DROP SCHEMA IF EXISTS " + schema + " CASCADE");
      } catch (...) {}
    }
  }

  /// The schema standing for `path`: created empty the first time this
  /// process names it.
  std::string schema_for(const std::filesystem::path& path) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string key = std::filesystem::absolute(path).lexically_normal().string();
    if (const auto found = schemas_.find(key); found != schemas_.end()) return found->second;
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a of the path
    for (const unsigned char c : key) hash = (hash ^ c) * 1099511628211ull;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    const std::string schema = "t" + std::to_string(::getpid()) + "_" + hex;
    admin().execute("DROP SCHEMA IF EXISTS " + schema + " CASCADE; CREATE SCHEMA " + schema);
    schemas_.emplace(key, schema);
    return schema;
  }

  static std::string server() {
    const auto url = postgresql_test_server();
    if (!url)
      throw std::runtime_error(
          "HYDROCOEF_TEST_BACKEND=postgresql needs HYDROCOEF_TEST_POSTGRESQL (scripts/postgresql-test-server.sh)");
    return *url;
  }

 private:
  SchemaRegistry() = default;
  static store::Connection admin() {
    const std::string url = server();
    return store::Connection::postgresql(url, url, store::Access::ReadWrite);
  }

  std::mutex mutex_;
  std::map<std::string, std::string> schemas_;
};

}  // namespace detail

/// What RunDatabase and --db take for the test database named `path`: the path
/// itself on SQLite; on PostgreSQL the test server's URL with a search_path
/// of the schema standing for the path.
inline std::string database_location(const std::filesystem::path& path) {
  if (!on_postgresql()) return path.string();
  const std::string server = detail::SchemaRegistry::server();
  const std::string schema = detail::SchemaRegistry::instance().schema_for(path);
  return url_with_schema(server, schema);
}

/// How the store names that database in its messages.
inline std::string database_display(const std::filesystem::path& path) {
  if (!on_postgresql()) return path.string();
  return store::parse_database_location(database_location(path)).display;
}

/// A connection of the test's own (for tampering and inspection).
inline store::Connection connect_database(const std::filesystem::path& path,
                                          store::Access access = store::Access::ReadWrite) {
  if (!on_postgresql()) return store::Connection(path.string(), access);
  const std::string url = database_location(path);
  return store::Connection::postgresql(url, url, access);
}

/// Whether a database has been made there (on PostgreSQL: its schema holds
/// the store's version table).
inline bool database_exists(const std::filesystem::path& path) {
  if (!on_postgresql()) return std::filesystem::exists(path);
  auto connection = connect_database(path, store::Access::ReadOnly);
  auto query = connection.prepare(
      "SELECT count(*) FROM pg_catalog.pg_tables WHERE schemaname = current_schema() AND "
      "tablename = 'hydrocoef_schema'");
  query.step();
  return query.get_int(0) > 0;
}

namespace detail {

/// Skips every test of a binary run on PostgreSQL when no test server is
/// configured (a developer's plain `ctest`). With
/// $HYDROCOEF_TEST_POSTGRESQL_REQUIRED set (scripts/test.sh) nothing is
/// skipped: the tests fail at their first database (database_location).
class PostgresqlServerCheck : public ::testing::Environment {
 public:
  void SetUp() override {
    if (!on_postgresql() || postgresql_test_server() || std::getenv("HYDROCOEF_TEST_POSTGRESQL_REQUIRED")) return;
    // The line ctest's skip pattern (gtest_discover_tests) looks for: a
    // skip in the environment prints none of its own.
    std::printf("[  SKIPPED ] the PostgreSQL run: HYDROCOEF_TEST_POSTGRESQL is not set\n");
    GTEST_SKIP() << "HYDROCOEF_TEST_BACKEND=postgresql but no test server: HYDROCOEF_TEST_POSTGRESQL is not set";
  }
};

inline const bool kPostgresqlServerCheckRegistered =
    (::testing::AddGlobalTestEnvironment(new PostgresqlServerCheck), true);

}  // namespace detail

/// In a test body: the test is about the SQLite file itself (its bytes,
/// header, WAL or file system rights) and has no PostgreSQL counterpart here
/// (tests/store/store_backends_test.cpp holds PostgreSQL's own).
#define HYDROCOEF_SQLITE_FILE_ONLY(why)                            \
  do {                                                             \
    if (::hydrocoef::test::on_postgresql()) GTEST_SKIP() << (why); \
  } while (false)

}  // namespace hydrocoef::test
