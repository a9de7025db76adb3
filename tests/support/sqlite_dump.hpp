// Test support: the whole content of a test database as text, so a test can
// assert that a failed operation left a database exactly as it was. On
// SQLite: the file's schema, user version and every row of every table,
// sorted. On PostgreSQL (tests/support/backend_under_test.hpp): the schema
// version and every row of the schema standing for the file name.
#pragma once

#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/backend_under_test.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {

inline std::string dump_database(const std::filesystem::path& path) {
  if (on_postgresql()) {
    auto connection = connect_database(path, store::Access::ReadOnly);
    std::string version = "none";
    if (database_exists(path)) {
      auto row = connection.prepare("SELECT version FROM hydrocoef_schema");
      version = row.step() ? std::to_string(row.get_int(0)) : "no row";
    }
    return "version=" + version + "\n" + dump_rows(connection);
  }
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    throw std::runtime_error("cannot open " + path.string());
  }
  std::string out;
  auto query = [&](const std::string& sql) {
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr) != SQLITE_OK)
      throw std::runtime_error(sqlite3_errmsg(db));
    std::vector<std::vector<std::string>> rows;
    while (sqlite3_step(statement) == SQLITE_ROW) {
      std::vector<std::string> row;
      for (int c = 0; c < sqlite3_column_count(statement); ++c) {
        const auto* text = sqlite3_column_text(statement, c);
        row.emplace_back(text ? reinterpret_cast<const char*>(text) : "NULL");
      }
      rows.push_back(std::move(row));
    }
    sqlite3_finalize(statement);
    return rows;
  };
  out += "user_version=" + query("PRAGMA user_version").at(0).at(0) + "\n";
  for (const auto& table : query("SELECT name, sql FROM sqlite_schema WHERE type = 'table' ORDER BY name")) {
    out += table[1] + "\n";
    auto rows = query("SELECT * FROM \"" + table[0] + "\"");
    std::sort(rows.begin(), rows.end());
    for (const auto& row : rows) {
      for (const auto& value : row) out += value + "|";
      out += "\n";
    }
  }
  sqlite3_close(db);
  return out;
}

}  // namespace hydrocoef::test
