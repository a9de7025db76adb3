// Test support: a database as an older hydrocoef made it. The rows of a
// database of the current schema are copied into a new file made by the
// migrations up to `version` alone (each table's columns of that version;
// the tables a later migration added are left out), so that a test can
// check what opening it does: migrations that convert data, and refusals
// that must leave the file at its version.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/store/connection.hpp"
#include "src/store/migrations.hpp"

namespace hydrocoef::test {

inline void copy_as_schema_version(const std::filesystem::path& current, const std::filesystem::path& out,
                                   int version) {
  std::filesystem::remove(out);
  store::Connection connection(out.string(), store::Access::ReadWriteCreate);
  for (int i = 0; i < version; ++i) connection.execute(store::migrations()[static_cast<std::size_t>(i)].sql);
  connection.execute("PRAGMA foreign_keys = OFF");
  auto attach = connection.prepare("ATTACH DATABASE ? AS source");
  attach.bind(1, current.string()).run();
  std::vector<std::string> tables;
  auto list = connection.prepare(
      "SELECT name FROM main.sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%' ORDER BY name");
  while (list.step()) tables.push_back(list.get_text(0));
  for (const auto& table : tables) {
    std::string columns;
    auto info = connection.prepare("SELECT name FROM pragma_table_info(?, 'main')");
    info.bind(1, table);
    while (info.step()) columns += (columns.empty() ? "\"" : ", \"") + info.get_text(0) + "\"";
    connection.execute("INSERT INTO main.\"" + table + "\" (" + columns + ") SELECT " + columns + " FROM source.\"" +
                       table + "\"");
  }
  connection.execute("DETACH DATABASE source");
  connection.execute("PRAGMA user_version = " + std::to_string(version));
}

}  // namespace hydrocoef::test
