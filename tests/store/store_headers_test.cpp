// What including the store costs its users: database.hpp (and the sqlite.hpp
// it includes) declare SQLite's handles themselves and leave <sqlite3.h> to
// src/store's sources, so code that only uses a Database never sees SQLite's
// C API. This file includes nothing else before the store's header.
#include "src/store/database.hpp"

#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

namespace hydrocoef {
namespace {

#ifdef SQLITE_VERSION
constexpr bool kSqliteHeaderIncluded = true;
#else
constexpr bool kSqliteHeaderIncluded = false;
#endif

TEST(StoreHeaders, DatabaseHeaderDoesNotIncludeSqlite) {
  EXPECT_FALSE(kSqliteHeaderIncluded) << "src/store/database.hpp pulls in <sqlite3.h>";
  // The connection still holds SQLite's handle type, only declared.
  EXPECT_TRUE((std::is_same_v<decltype(std::declval<store::Connection&>().handle()), sqlite3*>));
}

}  // namespace
}  // namespace hydrocoef
