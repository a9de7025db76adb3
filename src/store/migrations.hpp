// The database schema as an ordered list of SQL migrations (schema/NNNN_*.sql,
// compiled in). Migration i (1-based) brings a database to schema version i.
// The SQL is SQLite's; PostgreSQL gets it through the dialect layer
// (src/store/dialect.hpp), or, where a migration cannot be turned
// mechanically, from schema/postgresql/NNNN_*.sql of the same name.
#pragma once

#include <string_view>
#include <vector>

namespace hydrocoef::store {

struct Migration {
  std::string_view file;        ///< e.g. "0001_initial.sql"
  std::string_view sql;         ///< SQLite
  std::string_view postgresql;  ///< schema/postgresql/<file>, or empty when `sql` serves both

  /// What the dialect layer turns into PostgreSQL's SQL.
  std::string_view postgresql_sql() const { return postgresql.empty() ? sql : postgresql; }
};

const std::vector<Migration>& migrations();

}  // namespace hydrocoef::store
