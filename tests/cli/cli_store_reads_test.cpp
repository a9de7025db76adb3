// What the CLI does with databases it only reads (src/store/database.cpp, src/store/run_store.cpp):
// a shard whose run key columns disagree with its disturbances, a -wal file
// a read-only share keeps from being read, and the refusal of an older
// PostgreSQL database are each one line and exit 2, the target left byte for
// byte as it was; an older SQLite database is listed and merged without
// being written, and `hydrocoef migrate` upgrades it in place.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "src/store/database.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/older_database.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

ImportedRun make_run(double u, double x) {
  ImportedRun run;
  run.key.body = "hull";
  run.key.nu_b = {u, 0, 0, 0, 0, 0};
  run.key.disturbances = {{"current_v", 0.05}};
  run.tau_b[0] = ForceComponent{x, std::nullopt, std::nullopt};
  run.source_line = 1;
  return run;
}

void fill(const std::filesystem::path& path, int first_id = 1) {
  RunDatabase db(path);
  db.import(
      {test::one_run_batch(first_id, make_run(0.1, -1.0)), test::one_run_batch(first_id + 1, make_run(0.2, -4.0))},
      ConflictPolicy::Error);
}

void expect_one_line_refusal(const test::CliResult& result, const std::vector<std::string>& pieces) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
  for (const auto& piece : pieces) EXPECT_NE(result.err.find(piece), std::string::npos) << result.err;
}

std::size_t runs_listed(const std::filesystem::path& dir, const std::string& db) {
  const auto result = run_cli({"--db", db, "runs", "--json"}, dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(result.out).size();
}

TEST(CliStoreReads, AShardWithAMadeUpRunKeyIsRefusedAndTheTargetKeepsItsBytes) {
  HYDROCOEF_SQLITE_FILE_ONLY("the target's bytes");
  TempDir dir;
  fill(dir / "shard.db");
  fill(dir / "into.db", 10);
  {
    store::Connection shard((dir / "shard.db").string(), store::Access::ReadWrite);
    shard.execute("UPDATE run SET u = 0.1, disturbance_key = 'junk' WHERE u = 0.2");
  }
  const std::string before = test::read_bytes(dir / "into.db");
  const auto result = run_cli({"merge", "shard.db", "--into", "into.db"}, dir.path());
  expect_one_line_refusal(result, {"shard.db", "table 'run', row 2", "disturbance_key", "junk"});
  EXPECT_EQ(test::read_bytes(dir / "into.db"), before);
}

TEST(CliStoreReads, AWalFileLeftUnreadableOnAShareIsRefusedInOneLine) {
  HYDROCOEF_SQLITE_FILE_ONLY("SQLite's WAL and -shm files");
  TempDir dir;
  fill(dir / "runs.db");
  // Another connection keeps the next writer from checkpointing its import.
  sqlite3* reader = nullptr;
  ASSERT_EQ(sqlite3_open((dir / "runs.db").c_str(), &reader), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(reader, "SELECT count(*) FROM run", nullptr, nullptr, nullptr), SQLITE_OK);
  {
    RunDatabase db(dir / "runs.db");
    db.import({test::one_run_batch(5, make_run(0.3, -9.0))}, ConflictPolicy::Error);
  }
  std::filesystem::create_directory(dir / "share");
  std::filesystem::copy_file(dir / "runs.db", dir / "share" / "runs.db");
  std::filesystem::copy_file(dir / "runs.db-wal", dir / "share" / "runs.db-wal");
  sqlite3_close(reader);
  // Where a read-only folder would refuse the -shm file, even to root: a
  // dangling link (SQLite opens it with O_NOFOLLOW).
  std::filesystem::create_symlink("/nonexistent/hydrocoef-shm", dir / "share" / "runs.db-shm");
  const std::string before = test::read_bytes(dir / "share" / "runs.db");
  const auto result = run_cli({"--db", "share/runs.db", "runs"}, dir.path());
  expect_one_line_refusal(result, {"share/runs.db", "runs.db-wal", "wal_checkpoint(TRUNCATE)"});
  EXPECT_EQ(test::read_bytes(dir / "share" / "runs.db"), before);
  std::filesystem::remove(dir / "share" / "runs.db-shm");
  EXPECT_EQ(runs_listed(dir.path(), "share/runs.db"), 3u);
}

TEST(CliStoreReads, AnOlderDatabaseIsListedAndMergedUnchangedAndMigrateUpgradesIt) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a database of an older schema version (PostgreSQL databases begin at the version that brought PostgreSQL)");
  TempDir dir;
  fill(dir / "current.db");
  test::copy_as_schema_version(dir / "current.db", dir / "old.db", 11);
  const std::string before = test::read_bytes(dir / "old.db");
  EXPECT_EQ(runs_listed(dir.path(), "old.db"), 2u);
  EXPECT_EQ(run_cli({"--db", "old.db", "runs", "show", "1"}, dir.path()).exit_code, 0);
  EXPECT_EQ(run_cli({"--db", "old.db", "fits"}, dir.path()).exit_code, 0);
  EXPECT_EQ(test::read_bytes(dir / "old.db"), before);
  const auto merged = run_cli({"merge", "old.db", "--into", "into.db"}, dir.path());
  EXPECT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(test::read_bytes(dir / "old.db"), before);
  EXPECT_EQ(runs_listed(dir.path(), "into.db"), 2u);

  const auto migrated = run_cli({"--db", "old.db", "migrate", "--json"}, dir.path());
  ASSERT_EQ(migrated.exit_code, 0) << migrated.err;
  const auto json = nlohmann::json::parse(migrated.out);
  EXPECT_EQ(json.at("from"), 11);
  EXPECT_EQ(json.at("to"), RunDatabase::latest_schema_version());
  EXPECT_NE(test::read_bytes(dir / "old.db"), before);
  const auto again = run_cli({"--db", "old.db", "migrate"}, dir.path());
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("already"), std::string::npos) << again.out;
  // No database there: refused, nothing made.
  expect_one_line_refusal(run_cli({"--db", "none.db", "migrate"}, dir.path()), {"none.db", "no database here"});
  EXPECT_FALSE(std::filesystem::exists(dir / "none.db"));
}

}  // namespace
}  // namespace hydrocoef
