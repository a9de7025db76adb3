// Reading a database never writes it, and never reads less than it holds
// (src/store/database.cpp, src/store/run_store.cpp): a run whose stored key columns disagree with its
// disturbance rows is refused naming the table and row (a merge of such a
// shard changes nothing, instead of folding two runs into one); a -wal file
// that a read-only share keeps from being read is refused rather than left
// unread; and a database of an older schema is read through an upgraded
// private copy, the file staying byte for byte as it was, when it is read or
// merged as a shard.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <string>

#include "src/core/error.hpp"
#include "src/store/database.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/older_database.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::TempDir;

ImportedRun make_run(double u, double current_v, double x) {
  ImportedRun run;
  run.key.body = "hull";
  run.key.nu_b = {u, 0, 0, 0, 0, 0};
  run.key.disturbances = {{"current_v", current_v}};
  run.tau_b[0] = ForceComponent{x, std::nullopt, std::nullopt};
  run.source_line = 1;
  return run;
}

/// Three runs of hull, and a fit that lists them all.
void fill(RunDatabase& db) {
  db.import({test::one_run_batch(1, make_run(0.1, 0.05, -1.0)), test::one_run_batch(2, make_run(0.2, 0.05, -4.0)),
             test::one_run_batch(3, make_run(0.3, 0.05, -9.0))},
            ConflictPolicy::Error);
  FitRecord fit;
  fit.name = "hull:X(u)";
  fit.body = "hull";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u|u|";
  fit.loss = "squared";
  fit.n = 3;
  fit.coefficients = {{"u|u|", -100.0, 0.1}};
  for (const auto& run : db.runs()) fit.run_ids.push_back(run.id);
  db.save_fit(fit);
}

void tamper(const std::filesystem::path& path, const std::string& sql) {
  auto connection = test::connect_database(path);
  connection.execute(sql);
}

std::int64_t run_id_at(const std::filesystem::path& path, double u) {
  RunDatabase db(test::database_location(path), RunDatabase::OpenMode::ReadOnly);
  for (const auto& run : db.runs())
    if (run.key.nu_b[0] == u) return run.id;
  throw std::runtime_error("no run at that u");
}

// The trial's shard: one run given another run's velocity and a made-up
// disturbance key merged silently into that run (three runs in, two out),
// and the fit that listed both ended in an internal error.
TEST(ReceivedDatabaseReads, ARunWhoseKeyColumnDisagreesWithItsDisturbancesIsRefusedAndMergesNothing) {
  TempDir dir;
  {
    RunDatabase shard(test::database_location(dir / "shard.db"));
    fill(shard);
  }
  const std::int64_t tampered = run_id_at(dir / "shard.db", 0.2);
  tamper(dir / "shard.db", "UPDATE run SET u = 0.1, disturbance_key = 'junk' WHERE id = " + std::to_string(tampered));
  const std::string where = "table 'run', row " + std::to_string(tampered);
  {
    RunDatabase target(test::database_location(dir / "into.db"));
    target.import({test::one_run_batch(9, make_run(0.5, 0.0, -25.0))}, ConflictPolicy::Error);
  }
  const std::string rows = test::dump_database(dir / "into.db");
  const std::string bytes = test::on_postgresql() ? "" : test::read_bytes(dir / "into.db");
  {
    RunDatabase target(test::database_location(dir / "into.db"), RunDatabase::OpenMode::MustExist);
    test::expect_input_error(
        [&] { target.merge({test::database_location(dir / "shard.db")}); },
        {test::database_display(dir / "shard.db"), where, "disturbance_key", "'junk'", "'current_v=0.05'"});
  }
  EXPECT_EQ(test::dump_database(dir / "into.db"), rows);
  if (!test::on_postgresql()) EXPECT_EQ(test::read_bytes(dir / "into.db"), bytes);
  // Every reader refuses it the same way.
  RunDatabase shard(test::database_location(dir / "shard.db"), RunDatabase::OpenMode::ReadOnly);
  test::expect_input_error([&] { shard.runs(); }, {where, "disturbance_key"});
}

TEST(ReceivedDatabaseReads, ADisturbanceNamedAsAVelocityComponentOrNotFiniteIsRefused) {
  HYDROCOEF_SQLITE_FILE_ONLY("a REAL column holding an infinity, which PostgreSQL's CHECK-free double takes too");
  TempDir dir;
  {
    RunDatabase db(dir / "a.db");
    fill(db);
  }
  const std::int64_t id = run_id_at(dir / "a.db", 0.3);
  const std::string row = "table 'run_disturbance', row " + std::to_string(id);
  const auto copy = dir / "b.db";
  std::filesystem::copy_file(dir / "a.db", copy);
  tamper(copy, "UPDATE run_disturbance SET name = 'u' WHERE run_id = " + std::to_string(id));
  test::expect_input_error([&] { RunDatabase(copy, RunDatabase::OpenMode::ReadOnly).runs(); },
                           {row, "column 'name'", "not a velocity component"});
  std::filesystem::remove(copy);
  std::filesystem::copy_file(dir / "a.db", copy);
  tamper(copy, "UPDATE run_disturbance SET value = 1e999 WHERE run_id = " + std::to_string(id));
  test::expect_input_error([&] { RunDatabase(copy, RunDatabase::OpenMode::ReadOnly).runs(); },
                           {row, "column 'value'", "a finite number"});
}

/// Leaves `path` with a committed import in its -wal file: the writer closes
/// while another connection still has the file open, so nothing checkpoints
/// it; then copies the database and its -wal (not its -shm) to `copy`.
void copy_with_committed_wal(const std::filesystem::path& path, const std::filesystem::path& copy) {
  {
    RunDatabase db(path);
    fill(db);
  }
  sqlite3* reader = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &reader), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(reader, "SELECT count(*) FROM run", nullptr, nullptr, nullptr), SQLITE_OK);
  {
    RunDatabase db(path);
    db.import({test::one_run_batch(7, make_run(0.4, 0.05, -16.0))}, ConflictPolicy::Error);
  }
  ASSERT_GT(std::filesystem::file_size(path.string() + "-wal"), 0u);
  std::filesystem::copy_file(path, copy);
  std::filesystem::copy_file(path.string() + "-wal", copy.string() + "-wal");
  sqlite3_close(reader);
}

/// Where a read-only folder keeps SQLite from making or opening the -shm
/// file, even for root: a dangling link there (SQLite opens it with
/// O_NOFOLLOW). (A directory would not do: SQLite opens it read-only and
/// reads the WAL with an index in memory.)
void block_shm(const std::filesystem::path& database) {
  std::filesystem::create_symlink("/nonexistent/hydrocoef-shm", database.string() + "-shm");
}

// The trial's share: a read-only folder with the database and its -wal but
// no -shm listed 3 runs of 4.
TEST(ReceivedDatabaseReads, AWalFileThatCannotBeReadIsRefusedNotIgnored) {
  HYDROCOEF_SQLITE_FILE_ONLY("SQLite's WAL and -shm files");
  TempDir dir;
  std::filesystem::create_directory(dir / "share");
  const auto copy = dir / "share" / "runs.db";
  copy_with_committed_wal(dir / "runs.db", copy);
  block_shm(copy);
  const std::string bytes = test::read_bytes(copy), wal = test::read_bytes(copy.string() + "-wal");
  test::expect_input_error([&] { RunDatabase db(copy, RunDatabase::OpenMode::ReadOnly); },
                           {copy.string(), "runs.db-wal", "cannot be read here", "wal_checkpoint(TRUNCATE)"});
  EXPECT_EQ(test::read_bytes(copy), bytes);
  EXPECT_EQ(test::read_bytes(copy.string() + "-wal"), wal);
  // Where the -shm file can be made, every run is read.
  std::filesystem::remove(copy.string() + "-shm");
  RunDatabase db(copy, RunDatabase::OpenMode::ReadOnly);
  EXPECT_EQ(db.runs().size(), 4u);
}

// An empty -wal file holds nothing to lose: read as immutable, as before.
TEST(ReceivedDatabaseReads, AnEmptyWalFileBesideAReadOnlyShareIsNoObstacle) {
  HYDROCOEF_SQLITE_FILE_ONLY("SQLite's WAL and -shm files");
  TempDir dir;
  {
    RunDatabase db(dir / "runs.db");
    fill(db);
  }
  test::write_bytes(dir / "runs.db-wal", "");
  block_shm(dir / "runs.db");
  RunDatabase db(dir / "runs.db", RunDatabase::OpenMode::ReadOnly);
  EXPECT_EQ(db.runs().size(), 3u);
}

// Reading an older database upgrades a private copy; the file keeps its
// bytes and its version, whether it is read or merged as a shard.
TEST(ReceivedDatabaseReads, AnOlderDatabaseIsReadAndMergedWithoutBeingWritten) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a database of an older schema version (PostgreSQL databases begin at the version that brought PostgreSQL)");
  TempDir dir;
  {
    RunDatabase db(dir / "current.db");
    fill(db);
  }
  const auto old = dir / "v11.db";
  test::copy_as_schema_version(dir / "current.db", old, 11);
  const std::string bytes = test::read_bytes(old);
  {
    RunDatabase db(old, RunDatabase::OpenMode::ReadOnly);
    EXPECT_EQ(db.opened_at_version(), 11);
    EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
    EXPECT_EQ(db.runs().size(), 3u);
    EXPECT_EQ(db.fits().size(), 1u);
    // The copy takes no write: it would be lost when it closes.
    EXPECT_THROW(db.import({test::one_run_batch(8, make_run(0.6, 0.0, -1.0))}, ConflictPolicy::Error), InputError);
  }
  EXPECT_EQ(test::read_bytes(old), bytes);
  EXPECT_FALSE(std::filesystem::exists(old.string() + "-wal"));
  {
    RunDatabase into(dir / "into.db");
    const auto outcomes = into.merge({old.string()});
    ASSERT_EQ(outcomes.size(), 1u);
    EXPECT_EQ(outcomes[0].runs_created, 3u);
    EXPECT_EQ(outcomes[0].fits_added, 1u);
    EXPECT_EQ(into.runs().size(), 3u);
  }
  EXPECT_EQ(test::read_bytes(old), bytes);
  // A writing opening upgrades it in place.
  {
    RunDatabase db(old, RunDatabase::OpenMode::MustExist);
    EXPECT_EQ(db.opened_at_version(), 11);
  }
  EXPECT_EQ(RunDatabase(old, RunDatabase::OpenMode::ReadOnly).opened_at_version(),
            RunDatabase::latest_schema_version());
}

}  // namespace
}  // namespace hydrocoef
