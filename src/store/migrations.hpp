// The database schema as an ordered list of SQL migrations (schema/NNNN_*.sql,
// compiled in). Migration i (1-based) brings a database to user_version i.
#pragma once

#include <string_view>
#include <vector>

namespace hydrocoef::store {

struct Migration {
  std::string_view file;  ///< e.g. "0001_initial.sql"
  std::string_view sql;
};

const std::vector<Migration>& migrations();

}  // namespace hydrocoef::store
