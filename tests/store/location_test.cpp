// Tests of src/store/location: what --db and $HYDROCOEF_DB accept.
#include "src/store/location.hpp"

#include <gtest/gtest.h>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef::store {
namespace {

TEST(DatabaseLocation, APathOrSqlitePathIsAnSQLiteFile) {
  auto a = parse_database_location("runs/hydrocoef.db");
  EXPECT_EQ(a.backend, Backend::SQLite);
  EXPECT_EQ(a.target, "runs/hydrocoef.db");
  auto b = parse_database_location("sqlite:/data/team.db");
  EXPECT_EQ(b.backend, Backend::SQLite);
  EXPECT_EQ(b.target, "/data/team.db");
  EXPECT_EQ(parse_database_location("sqlite://relative.db").target, "relative.db");
  EXPECT_EQ(parse_database_location("C:runs.db").target, "C:runs.db");  // no '//': a file name
}

TEST(DatabaseLocation, APostgreSQLUrlIsKeptForLibpq) {
  const auto a = parse_database_location("postgresql://cfd@db.lab:5433/team?sslmode=require");
  EXPECT_EQ(a.backend, Backend::PostgreSQL);
  EXPECT_EQ(a.target, "postgresql://cfd@db.lab:5433/team?sslmode=require");
  EXPECT_EQ(parse_database_location("postgres:///team?host=/run/postgresql").backend, Backend::PostgreSQL);
}

TEST(DatabaseLocation, APasswordInTheUrlIsRefused) {
  test::expect_input_error([] { (void)parse_database_location("postgresql://cfd:secret@db.lab/team"); }, {".pgpass"});
  test::expect_input_error([] { (void)parse_database_location("postgresql:///team?user=cfd&password=secret"); },
                           {".pgpass"});
  test::expect_input_error([] { (void)parse_database_location("postgresql:///team?PassWord=secret"); }, {".pgpass"});
  // As libpq reads them: user information up to the '@' before the first '/'
  // ('?' included), percent-encoded parameter names, a key's passphrase.
  test::expect_input_error([] { (void)parse_database_location("postgresql://alice:pa?ss@db/team"); }, {".pgpass"});
  test::expect_input_error([] { (void)parse_database_location("postgresql:///team?pass%77ord=secret"); }, {".pgpass"});
  test::expect_input_error([] { (void)parse_database_location("postgresql://db?sslpassword=secret"); }, {".pgpass"});
  test::expect_input_error([] { (void)parse_database_location("postgresql://db?password=secret"); }, {".pgpass"});
  // A user without a password, and an '@' in a parameter, are no password.
  EXPECT_EQ(parse_database_location("postgresql://alice@db/team?application_name=a:b").backend, Backend::PostgreSQL);
  EXPECT_EQ(parse_database_location("postgresql:///team?host=/run/postgresql&user=a").backend, Backend::PostgreSQL);
}

TEST(DatabaseLocation, UnknownSchemesAndEmptyPathsAreRefused) {
  test::expect_input_error([] { (void)parse_database_location("mysql://db/team"); }, {"unknown scheme 'mysql'"});
  test::expect_input_error([] { (void)parse_database_location("sqlite:"); }, {"empty"});
  test::expect_input_error([] { (void)parse_database_location(""); }, {"empty"});
}

}  // namespace
}  // namespace hydrocoef::store
