// Where a database is: what --db, $HYDROCOEF_DB and the library's RunDatabase
// take. A path or "sqlite:PATH" is an SQLite file (the default); a
// "postgresql://" or "postgres://" URL is a PostgreSQL database, reached
// with libpq (its host, port, user, database and options, e.g.
// "postgresql:///team?host=/run/postgresql&options=-csearch_path%3Dhydro").
// A password never comes in the URL, where other users of the machine see it
// (ps, shell history): libpq reads it from ~/.pgpass, $PGPASSFILE or
// $PGPASSWORD.
#pragma once

#include <string>
#include <string_view>

#include "src/store/connection.hpp"

namespace hydrocoef::store {

struct DatabaseLocation {
  Backend backend = Backend::SQLite;
  std::string target;   ///< the file's path, or the libpq URL
  std::string display;  ///< how messages name it
};

/// InputError for an unknown scheme ("mysql://..."), an empty path, or a URL
/// that carries a password.
DatabaseLocation parse_database_location(std::string_view text);

}  // namespace hydrocoef::store
