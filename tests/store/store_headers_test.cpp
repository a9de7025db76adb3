// What including the store costs its users: database.hpp (and the
// connection.hpp it includes) leave both backends' C headers (<sqlite3.h>,
// <libpq-fe.h>) to src/store's sources, so code that only uses a RunDatabase
// never sees SQLite's or libpq's C API. This file includes nothing else
// before the store's header.
#include "src/store/database.hpp"

#include <gtest/gtest.h>

namespace hydrocoef {
namespace {

#ifdef SQLITE_VERSION
constexpr bool kSqliteHeaderIncluded = true;
#else
constexpr bool kSqliteHeaderIncluded = false;
#endif
#ifdef LIBPQ_FE_H
constexpr bool kLibpqHeaderIncluded = true;
#else
constexpr bool kLibpqHeaderIncluded = false;
#endif

TEST(StoreHeaders, DatabaseHeaderIncludesNeitherBackendsHeader) {
  EXPECT_FALSE(kSqliteHeaderIncluded) << "src/store/database.hpp pulls in <sqlite3.h>";
  EXPECT_FALSE(kLibpqHeaderIncluded) << "src/store/database.hpp pulls in <libpq-fe.h>";
}

}  // namespace
}  // namespace hydrocoef
