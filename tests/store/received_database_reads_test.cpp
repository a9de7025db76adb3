// Reading a database never writes it, and never reads less than it holds
// (src/store/database.cpp): a run whose stored key columns disagree with its
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
void fill(Database& db) {
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
  Database db(test::database_location(path), Database::OpenMode::ReadOnly);
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
    Database shard(test::database_location(dir / "shard.db"));
    fill(shard);
  }
  const std::int64_t tampered = run_id_at(dir / "shard.db", 0.2);
  tamper(dir / "shard.db", "UPDATE run SET u = 0.1, disturbance_key = 'junk' WHERE id = " + std::to_string(tampered));
  const std::string where = "table 'run', row " + std::to_string(tampered);
  {
    Database target(test::database_location(dir / "into.db"));
    target.import({test::one_run_batch(9, make_run(0.5, 0.0, -25.0))}, ConflictPolicy::Error);
  }
  const std::string rows = test::dump_database(dir / "into.db");
  const std::string bytes = test::on_postgresql() ? "" : test::read_bytes(dir / "into.db");
  {
    Database target(test::database_location(dir / "into.db"), Database::OpenMode::MustExist);
    test::expect_input_error(
        [&] { target.merge({test::database_location(dir / "shard.db")}); },
        {test::database_display(dir / "shard.db"), where, "disturbance_key", "'junk'", "'current_v=0.05'"});
  }
  EXPECT_EQ(test::dump_database(dir / "into.db"), rows);
  if (!test::on_postgresql()) EXPECT_EQ(test::read_bytes(dir / "into.db"), bytes);
  // Every reader refuses it the same way.
  Database shard(test::database_location(dir / "shard.db"), Database::OpenMode::ReadOnly);
  test::expect_input_error([&] { shard.runs(); }, {where, "disturbance_key"});
}

TEST(ReceivedDatabaseReads, ADisturbanceNamedAsAVelocityComponentOrNotFiniteIsRefused) {
  HYDROCOEF_SQLITE_FILE_ONLY("a REAL column holding an infinity, which PostgreSQL's CHECK-free double takes too");
  TempDir dir;
  {
    Database db(dir / "a.db");
    fill(db);
  }
  const std::int64_t id = run_id_at(dir / "a.db", 0.3);
  const std::string row = "table 'run_disturbance', row " + std::to_string(id);
  const auto copy = dir / "b.db";
  std::filesystem::copy_file(dir / "a.db", copy);
  tamper(copy, "UPDATE run_disturbance SET name = 'u' WHERE run_id = " + std::to_string(id));
  test::expect_input_error([&] { Database(copy, Database::OpenMode::ReadOnly).runs(); },
                           {row, "column 'name'", "not a velocity component"});
  std::filesystem::remove(copy);
  std::filesystem::copy_file(dir / "a.db", copy);
  tamper(copy, "UPDATE run_disturbance SET value = 1e999 WHERE run_id = " + std::to_string(id));
  test::expect_input_error([&] { Database(copy, Database::OpenMode::ReadOnly).runs(); },
                           {row, "column 'value'", "a finite number"});
}

}  // namespace
}  // namespace hydrocoef
