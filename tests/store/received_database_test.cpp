// A database received from someone else is untrusted input (src/store):
// impossible schema versions, a schema that differs from the migrations'
// (a foreign trigger that would run on the next import, a dropped column),
// values of the wrong type or range, and names that break the name rule are
// refused with one line naming the file, table and row, and the file is left
// byte for byte as it was. Also: migrating a version-3 database keeps its
// fits (and makes R^2 optional), fits with undefined statistics round-trip,
// read-only opening never writes and falls back to immutable reading where
// SQLite cannot make its -shm file, and several fits are stored all or none.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <fstream>
#include <string>

#include "src/core/error.hpp"
#include "src/core/source_file.hpp"
#include "src/store/database.hpp"
#include "src/store/migrations.hpp"
#include "src/store/schema_check.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::TempDir;

std::string file_bytes_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return sha256_hex(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
}

void exec(const std::filesystem::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error);
  const std::string message = error ? error : "";
  sqlite3_free(error);
  sqlite3_close(db);
  ASSERT_EQ(rc, SQLITE_OK) << sql << ": " << message;
}

ImportBatch one_run_batch(const std::string& body = "sphere", char hash = 'a') {
  ImportedRun run;
  run.key.body = body;
  run.key.nu_b = {0.2, 0, 0, 0, 0, 0};
  run.tau_b[0] = ForceComponent{-1.5, std::nullopt, std::nullopt};
  run.source_line = 2;
  ImportBatch batch;
  batch.source.path = "a.csv";
  batch.source.sha256 = std::string(64, hash);
  batch.source.size_bytes = 10;
  batch.source.importer = "test";
  batch.source.importer_version = "1";
  batch.runs = {run};
  return batch;
}

FitRecord a_fit(const std::string& name, std::int64_t run_id) {
  FitRecord fit;
  fit.name = name;
  fit.body = "sphere";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u";
  fit.loss = "squared";
  fit.n = 1;
  fit.rmse = 0.0;
  fit.r2 = std::nan("");
  fit.coefficients = {{"u", -7.5, std::nullopt}};
  fit.run_ids = {run_id};
  return fit;
}

// A good database with one run and one fit, closed (WAL folded in).
std::filesystem::path good_database(const TempDir& dir) {
  const auto path = dir / "good.db";
  {
    RunDatabase db(path);
    db.import({one_run_batch()}, ConflictPolicy::Error);
    db.save_fit(a_fit("sphere:X(u)", db.runs().front().id));
  }
  exec(path, "PRAGMA journal_mode = DELETE");
  return path;
}

// Opens `path` (read-only and for writing): both must refuse with an
// InputError containing every piece, and leave the file's bytes unchanged.
void expect_refused(const std::filesystem::path& path, const std::vector<std::string>& pieces, bool on_read = false) {
  const std::string before = file_bytes_hash(path);
  for (const auto mode : {RunDatabase::OpenMode::ReadOnly, RunDatabase::OpenMode::MustExist}) {
    bool opened = false;
    try {
      RunDatabase db(path, mode);
      opened = true;
      if (!on_read) FAIL() << "opened";
      (void)db.runs();
      (void)db.fits();
      (void)db.surfaces();
      FAIL() << "read without an error";
    } catch (const InputError& e) {
      const std::string message = e.what();
      for (const auto& piece : pieces) EXPECT_NE(message.find(piece), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    }
    // A reader never writes; a writer refused at open writes nothing (a
    // writer that opened switches the file to WAL mode: other bytes).
    if (mode == RunDatabase::OpenMode::ReadOnly || !opened) {
      EXPECT_EQ(file_bytes_hash(path), before);
    }
  }
}

TEST(ReceivedDatabase, SchemaVersionsOutsideTheKnownRangeAreRefused) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a received SQLite file, whose bytes must stay as they were (PostgreSQL schema checks: "
      "tests/store/store_backends_test.cpp)");
  TempDir dir;
  const auto path = good_database(dir);
  exec(path, "PRAGMA user_version = -1");
  expect_refused(path, {"schema version -1", "expected 0 to"});
  exec(path, "PRAGMA user_version = 99");
  expect_refused(path, {"schema version 99", "newer hydrocoef"});
  // A version lower than its schema: the schema is not that version's.
  exec(path, "PRAGMA user_version = 2");
  expect_refused(path, {"schema version 2", "does not create"});
}

TEST(ReceivedDatabase, AForeignTriggerViewOrIndexIsRefusedAndNeverRuns) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a received SQLite file, whose bytes must stay as they were (PostgreSQL schema checks: "
      "tests/store/store_backends_test.cpp)");
  TempDir dir;
  const auto path = good_database(dir);
  exec(path, "CREATE TRIGGER evil AFTER INSERT ON run_force BEGIN DELETE FROM fit; END;");
  expect_refused(path, {"trigger 'evil' on table 'run_force'", "does not create"});
  // Not even a writer gets through, so the trigger never fires.
  EXPECT_THROW(RunDatabase(path).import({one_run_batch("other", 'b')}, ConflictPolicy::Error), InputError);
  exec(path, "DROP TRIGGER evil; CREATE VIEW v AS SELECT * FROM run;");
  expect_refused(path, {"view 'v'"});
  exec(path, "DROP VIEW v; CREATE INDEX run_u ON run(u);");
  expect_refused(path, {"index 'run_u'"});
  exec(path, "DROP INDEX run_u;");
  EXPECT_NO_THROW(RunDatabase(path, RunDatabase::OpenMode::ReadOnly).fits());
}

TEST(ReceivedDatabase, ADroppedOrAddedColumnOrTableIsRefused) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a received SQLite file, whose bytes must stay as they were (PostgreSQL schema checks: "
      "tests/store/store_backends_test.cpp)");
  TempDir dir;
  const auto path = good_database(dir);
  exec(path, "ALTER TABLE run DROP COLUMN ref_z");
  expect_refused(path, {"table 'run'", "differs"});
  std::filesystem::remove(path);
  const auto path2 = good_database(dir);  // a fresh good copy
  exec(path2, "DROP TABLE surface_run");
  expect_refused(path2, {"lacks a table 'surface_run'"});
}

TEST(ReceivedDatabase, ValuesOfTheWrongTypeOrRangeNameTheTableRowAndColumn) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a received SQLite file, whose bytes must stay as they were (PostgreSQL schema checks: "
      "tests/store/store_backends_test.cpp)");
  TempDir dir;
  const auto path = good_database(dir);
  exec(path, "UPDATE run SET u = 'fast'");
  expect_refused(path, {"table 'run', row 1, column 'u'", "found the text 'fast'", "expected a finite number"}, true);
  exec(path, "UPDATE run SET u = 0.2; UPDATE fit_coefficient SET value = 'abc'");
  expect_refused(path, {"table 'fit_coefficient'", "'value'", "'abc'"}, true);
  exec(path, "UPDATE fit_coefficient SET value = -7.5; UPDATE run_force SET total = -9e999");
  expect_refused(path, {"table 'run_force'", "-infinity"}, true);
  exec(path, "UPDATE run_force SET total = -1.5; UPDATE run SET density = -2");
  expect_refused(path, {"column 'density'", "a number > 0"}, true);
}

TEST(ReceivedDatabase, NamesThatBreakTheNameRuleAreRefusedOnRead) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a received SQLite file, whose bytes must stay as they were (PostgreSQL schema checks: "
      "tests/store/store_backends_test.cpp)");
  TempDir dir;
  const auto path = good_database(dir);
  exec(path, "UPDATE body SET name = 'a' || char(10) || 'system(\"touch x\")'");
  expect_refused(path, {"table 'body'", "control"}, true);
  exec(path, "UPDATE body SET name = 'sphere'; UPDATE fit SET name = CAST(X'FF41' AS TEXT)");
  expect_refused(path, {"table 'fit'", "not valid UTF-8"}, true);
}

TEST(ReceivedDatabase, TheLibraryRefusesToStoreNamesThatBreakTheRule) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({one_run_batch()}, ConflictPolicy::Error);
  const auto before = test::dump_database(dir / "db");
  EXPECT_THROW(db.import({one_run_batch("a\nb", 'b')}, ConflictPolicy::Error), InputError);
  EXPECT_THROW(db.save_fit(a_fit("x`y`\x01", db.runs().front().id)), InputError);
  EXPECT_EQ(test::dump_database(dir / "db"), before);
}

TEST(ReceivedDatabase, AVersion3DatabaseMigratesKeepingItsFitsAndR2BecomesOptional) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a database of an older schema version (PostgreSQL databases begin at the version that brought PostgreSQL)");
  TempDir dir;
  const auto path = dir / "v3.db";
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  for (int i = 0; i < 3; ++i) {
    const std::string sql(store::migrations()[static_cast<std::size_t>(i)].sql);
    ASSERT_EQ(sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  }
  const char* rows =
      "INSERT INTO body(id, name) VALUES (1, 'sphere');"
      "INSERT INTO source_file VALUES (1, 'a.csv', '"
      "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"
      "', 1, 't', '1', 'now');"
      "INSERT INTO run(id, body_id, u) VALUES (1, 1, 0.2);"
      "INSERT INTO run_force VALUES (1, 'X', -1.5, NULL, NULL, 'on-body', 1, 2);"
      "INSERT INTO fit VALUES (1, 'sphere:X(u)', 1, 'X', 'u', 'u', 'squared', '', 'on-body', 1, 0.5, 0.9, 'now');"
      "INSERT INTO fit_coefficient VALUES (1, 0, 'u', -7.5, NULL);"
      "INSERT INTO fit_run VALUES (1, 1);"
      "PRAGMA user_version = 3;";
  ASSERT_EQ(sqlite3_exec(raw, rows, nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(raw);

  RunDatabase db(path);
  EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
  const auto fits = db.fits();
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].name, "sphere:X(u)");
  EXPECT_EQ(fits[0].r2, 0.9);
  EXPECT_EQ(fits[0].run_ids, std::vector<std::int64_t>{1});
  EXPECT_EQ(fits[0].coefficients.at(0).value, -7.5);
  EXPECT_EQ(db.integrity_check(), "ok");
  // Undefined R^2 is stored as absent and read back as NaN.
  db.save_fit(a_fit("constant", 1));
  for (const auto& fit : db.fits()) {
    if (fit.name == "constant") {
      EXPECT_TRUE(std::isnan(fit.r2));
    }
  }
  // The migrated schema is exactly what a new database gets.
  RunDatabase fresh(test::database_location(dir / "fresh.db"));
  store::Connection a(path.string(), store::Access::ReadOnly);
  store::Connection b((dir / "fresh.db").string(), store::Access::ReadOnly);
  EXPECT_FALSE(store::schema_difference(store::schema_of(b), store::schema_of(a)).has_value());
}

TEST(ReceivedDatabase, ReadOnlyOpeningNeverWritesAndReadsWhereNoShmFileCanBeMade) {
  HYDROCOEF_SQLITE_FILE_ONLY("SQLite's WAL and -shm files");
  TempDir dir;
  const auto path = dir / "wal.db";
  {
    RunDatabase db(path);
    db.import({one_run_batch()}, ConflictPolicy::Error);
  }
  // The WAL folded in, WAL mode kept in the file; then nothing may be
  // created beside it: a directory stands where SQLite would put -shm.
  exec(path, "PRAGMA wal_checkpoint(TRUNCATE)");
  std::filesystem::remove(dir / "wal.db-wal");
  std::filesystem::remove(dir / "wal.db-shm");
  std::filesystem::create_directory(dir / "wal.db-shm");
  const std::string before = file_bytes_hash(path);
  RunDatabase db(path, RunDatabase::OpenMode::ReadOnly);
  EXPECT_TRUE(db.read_only());
  ASSERT_EQ(db.runs().size(), 1u);
  EXPECT_EQ(db.runs().front().tau_b[0]->value.total, -1.5);
  EXPECT_EQ(file_bytes_hash(path), before);
}

TEST(ReceivedDatabase, AnEmptyFileIsNotReadAsADatabaseAndStaysEmpty) {
  TempDir dir;
  { std::ofstream(dir / "empty.db"); }
  try {
    RunDatabase db(test::database_location(dir / "empty.db"), RunDatabase::OpenMode::ReadOnly);
    FAIL() << "opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty database"), std::string::npos) << e.what();
  }
  EXPECT_EQ(std::filesystem::file_size(dir / "empty.db"), 0u);
}

TEST(ReceivedDatabase, SeveralFitsAreStoredAllOrNone) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({one_run_batch()}, ConflictPolicy::Error);
  const auto run = db.runs().front().id;
  FitRecord bad = a_fit("second", run);
  bad.body = "no such body";
  const auto before = test::dump_database(dir / "db");
  EXPECT_THROW(db.save_fits({a_fit("first", run), bad}), InputError);
  EXPECT_EQ(test::dump_database(dir / "db"), before);
  EXPECT_EQ(db.save_fits({a_fit("first", run), a_fit("second", run)}).size(), 2u);
  EXPECT_EQ(db.fits().size(), 2u);
}

}  // namespace
}  // namespace hydrocoef
