// A received database is untrusted input: before hydrocoef reads a row, the
// file's schema (its tables, columns, indexes, triggers and views, as stored
// in sqlite_schema) must be exactly the one the migrations create for its
// version. A trigger someone added (which would run on the next import), a
// dropped column or a view is refused with one line naming it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "src/store/connection.hpp"

namespace hydrocoef::store {

/// One sqlite_schema row.
struct SchemaEntry {
  std::string type;  ///< table, index, trigger, view
  std::string name;
  std::string table;  ///< the table it belongs to
  std::string sql;    ///< as stored (NULL for automatic indexes: "")
};

/// The schema of the open database, sorted by type and name. SQLite's own
/// statistics tables (sqlite_stat1..4, written by ANALYZE) are left out.
std::vector<SchemaEntry> schema_of(Connection& connection);

/// The schema migrations 1..version create, built in an in-memory database
/// (cached per version).
const std::vector<SchemaEntry>& expected_schema(int version);

/// What differs, as one phrase ("has a trigger 'x' on table 'run' that
/// hydrocoef does not create"), or nullopt when the schemas are the same.
std::optional<std::string> schema_difference(const std::vector<SchemaEntry>& expected,
                                             const std::vector<SchemaEntry>& found);

/// The same check for a PostgreSQL database at `version`, in its current
/// schema (search_path), against what the migrations create (each SQLite type
/// as the dialect layer turns it): its tables and their columns (name, type,
/// collation, NOT NULL, whether a default or an identity fills them), primary
/// keys, unique and other indexes (by their columns: their names are each
/// database's own), foreign keys with their ON UPDATE / ON DELETE actions, the
/// number of CHECK constraints of each table (PostgreSQL rewrites their
/// expressions its own way), triggers with their functions, rules, and no
/// views. A dropped unique key would let a sweep store one key twice, a
/// dropped foreign key or cascade leave rows of deleted runs behind.
std::optional<std::string> postgresql_schema_difference(Connection& connection, int version);

}  // namespace hydrocoef::store
