// Forced-oscillation records in the database (migrations 12 and 14): stored
// and read back exactly with their restoring coefficient, replaced when the
// same file is analysed with the same motion again, deleted by id (all or
// nothing), schema-11 and schema-13 databases migrated, and a received
// database's damaged values refused naming the table, row and column.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <optional>

#include "src/core/error.hpp"
#include "src/store/database.hpp"
#include "src/store/pmm_record.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/older_database.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

PmmRecord sample_record() {
  PmmRecord r;
  r.body = "ball";
  r.nu_b = {0.1, 0, 0, 0, 0, 0};
  r.dof = 5;
  r.amplitude = 0.2;
  r.omega = 3.25;
  r.phase = -0.5;
  r.medium = PmmMedium::StillWater;
  r.motion_source = "case/constant/dynamicMeshDict:7";
  r.window_start = 1.5;
  r.window_end = 9.25;
  r.periods = 4;
  r.transient_periods = 1;
  r.samples = 800;
  r.harmonics = 2;
  r.size = 0.3;
  r.kinematic_viscosity = 1e-6;
  r.stokes_number = 45000.0;
  r.rho = 998.2;
  r.source_path = "case";
  r.source_sha256 = std::string(64, 'a');
  r.importer = "openfoam-forces 1";
  r.history = {1.5, 1, 2, 3, 4, 5, 6, 1.6, 1.1, 2.1, 3.1, 4.1, 5.1, 6.1};
  PmmCoefficient n;
  n.component = 5;
  n.mean = 0.01;
  n.added_mass = 0.125;
  n.added_mass_se = 0.001;
  n.damping = 0.5;
  n.damping_se = 0.002;
  n.explained = 0.999;
  n.harmonics = {0.1, 0.2, 0.003, 0.004};
  r.coefficients = {n};
  return r;
}

TEST(PmmStore, RoundTripAndReplacement) {
  test::TempDir dir;
  RunDatabase db(test::database_location(dir / "a.db"));
  const PmmRecord r = sample_record();
  const auto saved = db.save_pmm({r});
  ASSERT_EQ(saved.size(), 1u);
  EXPECT_FALSE(saved[0].replaced);
  const auto back = db.pmm_records();
  ASSERT_EQ(back.size(), 1u);
  const PmmRecord& b = back[0];
  EXPECT_EQ(b.body, "ball");
  EXPECT_EQ(b.nu_b, r.nu_b);
  EXPECT_EQ(b.dof, 5u);
  EXPECT_EQ(b.phase, -0.5);
  EXPECT_EQ(b.window_end, 9.25);
  EXPECT_EQ(b.harmonics, 2);
  EXPECT_EQ(b.stokes_number, 45000.0);
  EXPECT_FALSE(b.keulegan_carpenter);
  EXPECT_EQ(b.history, r.history);
  ASSERT_EQ(b.coefficients.size(), 1u);
  EXPECT_EQ(b.coefficients[0].component, 5u);
  EXPECT_EQ(b.coefficients[0].harmonics, r.coefficients[0].harmonics);
  EXPECT_EQ(b.coefficients[0].damping_se, 0.002);
  EXPECT_TRUE(db.pmm_records("ball", false)[0].history.empty());
  EXPECT_TRUE(db.pmm_records("other").empty());
  // The same file and motion again replaces; another amplitude is another record.
  EXPECT_TRUE(db.save_pmm({r})[0].replaced);
  PmmRecord other = r;
  other.amplitude = 0.3;
  EXPECT_FALSE(db.save_pmm({other})[0].replaced);
  EXPECT_EQ(db.pmm_records().size(), 2u);
  EXPECT_FALSE(db.pmm_records()[0].restoring);
  // The restoring coefficient removed before the fit is kept (migration 14).
  PmmRecord floating = r;
  floating.dof = 2;
  floating.restoring = 9810.5;
  db.save_pmm({floating});
  std::optional<double> restoring;
  for (const auto& stored : db.pmm_records())
    if (stored.dof == 2) restoring = stored.restoring;
  EXPECT_EQ(restoring, 9810.5);
}

TEST(PmmStore, DeleteRemovesRunsAndTheirCoefficientsOrNothing) {
  test::TempDir dir;
  RunDatabase db(test::database_location(dir / "a.db"));
  PmmRecord other = sample_record();
  other.amplitude = 0.3;
  const auto saved = db.save_pmm({sample_record(), other});
  // An id that is not stored: nothing is deleted, not even the ids before it.
  test::expect_input_error(
      [&] {
        db.delete_pmm_runs({saved[0].id, saved[1].id + 100});
      },
      {"no forced-oscillation run " + std::to_string(saved[1].id + 100), "nothing was deleted"});
  EXPECT_EQ(db.pmm_records().size(), 2u);
  const auto deleted = db.delete_pmm_runs({saved[0].id, saved[0].id});  // an id twice counts once
  ASSERT_EQ(deleted.size(), 1u);
  EXPECT_EQ(deleted[0].id, saved[0].id);
  EXPECT_EQ(deleted[0].body, "ball");
  EXPECT_EQ(deleted[0].dof, 5);
  EXPECT_EQ(deleted[0].source_path, "case");
  const auto left = db.pmm_records();
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].id, saved[1].id);
  EXPECT_EQ(left[0].coefficients.size(), 1u);
}

TEST(PmmStore, ASchema11DatabaseOpensAtTheLatestWithNoRecords) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a database of an older schema version (PostgreSQL databases begin at the version that brought PostgreSQL)");
  test::TempDir dir;
  {
    RunDatabase db(test::database_location(dir / "current.db"));
    db.save_pmm({sample_record()});
  }
  test::copy_as_schema_version(dir / "current.db", dir / "v11.db", 11);
  RunDatabase db(test::database_location(dir / "v11.db"));
  EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
  EXPECT_TRUE(db.pmm_records().empty());
  db.save_pmm({sample_record()});
  EXPECT_EQ(db.pmm_records().size(), 1u);
}

TEST(PmmStore, ASchema13DatabaseKeepsItsRecordsWithNoRestoringForce) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a database of an older schema version (PostgreSQL databases begin at the version that brought PostgreSQL)");
  test::TempDir dir;
  {
    RunDatabase db(test::database_location(dir / "current.db"));
    db.save_pmm({sample_record()});
  }
  // Schema 13 has no restoring column: drop it from the copy of the current one.
  test::copy_as_schema_version(dir / "current.db", dir / "v13.db", 13);
  RunDatabase db(test::database_location(dir / "v13.db"));
  EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
  const auto records = db.pmm_records();
  ASSERT_EQ(records.size(), 1u);
  EXPECT_FALSE(records[0].restoring);
  EXPECT_EQ(records[0].coefficients[0].added_mass, 0.125);
}

TEST(PmmStore, DamagedValuesAreRefusedNamingTheTableRowAndColumn) {
  HYDROCOEF_SQLITE_FILE_ONLY("values that break CHECK constraints and column types, which PostgreSQL always enforces");
  const std::vector<std::pair<std::string, std::vector<std::string>>> damage = {
      {"UPDATE pmm_coefficient SET added_mass = 'heavy'", {"pmm_coefficient", "added_mass"}},
      {"UPDATE pmm_coefficient SET harmonics = '[1, 2]'", {"pmm_coefficient", "harmonics"}},
      {"UPDATE pmm_run SET history = x'00'", {"pmm_run", "history"}},
      {"UPDATE pmm_run SET window_end = 0", {"pmm_run", "window_end"}},
      {"UPDATE pmm_run SET keulegan_carpenter = -1", {"pmm_run", "keulegan_carpenter"}},
  };
  for (const auto& [sql, expected] : damage) {
    test::TempDir dir;
    {
      RunDatabase db(test::database_location(dir / "a.db"));
      db.save_pmm({sample_record()});
    }
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open((dir / "a.db").string().c_str(), &raw), SQLITE_OK);
    // The CHECK constraints guard what hydrocoef writes; a received file may have none.
    ASSERT_EQ(sqlite3_exec(raw, ("PRAGMA ignore_check_constraints = 1; " + sql).c_str(), nullptr, nullptr, nullptr),
              SQLITE_OK)
        << sql;
    sqlite3_close(raw);
    RunDatabase db(test::database_location(dir / "a.db"), RunDatabase::OpenMode::ReadOnly);
    test::expect_input_error([&] { db.pmm_records(); }, expected);
  }
}

}  // namespace
}  // namespace hydrocoef
