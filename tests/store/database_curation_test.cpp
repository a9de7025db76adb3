// A database that can be corrected (src/store): an import is a file's bytes
// and its effective settings. The same bytes and settings add nothing; other
// settings are refused naming what differs, replaced with --replace (fits
// and surfaces built from the old runs become stale), or kept as a second
// reading with --also. Runs can be deleted (integrity ok, no orphan rows,
// fits and surfaces stale). Every refusal leaves the database as it was.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/store/database.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::dump_database;
using test::TempDir;

// A file of given bytes (hash digit) read with settings giving the run at speed u.
ImportBatch reading(char hash, double u, double x, const std::string& settings_value = "") {
  ImportedRun run;
  run.key.body = "sphere";
  run.key.nu_b = {u, 0, 0, 0, 0, 0};
  run.tau_b[0] = ForceComponent{x, std::nullopt, std::nullopt};
  run.source_line = 2;
  ImportBatch batch;
  batch.source.path = std::string("case-") + hash + ".csv";
  batch.source.sha256 = std::string(64, hash);
  batch.source.size_bytes = 10;
  batch.source.importer = "test";
  batch.source.importer_version = "1";
  const std::string value = settings_value.empty() ? std::to_string(u) : settings_value;
  batch.source.settings = nlohmann::json{{"u", {{"value", u}, {"source", "sidecar"}, {"where", "a.json"}}}}.dump();
  batch.source.settings_key = "u=" + value;
  batch.runs = {run};
  return batch;
}

// Rows whose foreign keys point nowhere. (PostgreSQL checks every foreign key
// at each write: none can be there.)
std::string foreign_key_problems(const std::filesystem::path& path) {
  if (test::on_postgresql()) return "";
  sqlite3* db = nullptr;
  sqlite3_open(path.c_str(), &db);
  sqlite3_stmt* statement = nullptr;
  sqlite3_prepare_v2(db, "PRAGMA foreign_key_check", -1, &statement, nullptr);
  std::string out;
  while (sqlite3_step(statement) == SQLITE_ROW) out += reinterpret_cast<const char*>(sqlite3_column_text(statement, 0));
  sqlite3_finalize(statement);
  sqlite3_close(db);
  return out;
}

FitRecord fit_of(const std::vector<StoredRun>& runs) {
  FitRecord fit;
  fit.name = "sphere:X(u|u|)";
  fit.body = "sphere";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u|u|";
  fit.loss = "squared";
  fit.n = runs.size();
  fit.rmse = 0.0;
  fit.r2 = 1.0;
  fit.coefficients = {{"u|u|", -11.0, std::nullopt}};
  for (const auto& run : runs) fit.run_ids.push_back(run.id);
  return fit;
}

TEST(DatabaseCuration, TheSameBytesAndSettingsAreANoOpOtherSettingsAreRefused) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({reading('a', 0.1, -0.11)}, ImportPolicy{});
  const auto again = db.import({reading('a', 0.1, -0.11)}, ImportPolicy{});
  ASSERT_EQ(again.size(), 1u);
  EXPECT_TRUE(again[0].already_imported);
  const auto before = dump_database(dir / "db");
  try {
    db.import({reading('a', 0.2, -0.44)}, ImportPolicy{});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("already imported"), std::string::npos) << message;
    EXPECT_NE(message.find("u: 0.1 (sidecar) then 0.2 (sidecar)"), std::string::npos) << message;
    EXPECT_NE(message.find("--replace"), std::string::npos) << message;
    EXPECT_NE(message.find("--also"), std::string::npos) << message;
  }
  EXPECT_EQ(dump_database(dir / "db"), before);
}

// 200 identical files given 200 different keys by their sidecars: never one
// run and 199 silent no-ops. Without --also they are refused, clearly.
TEST(DatabaseCuration, TwoHundredIdenticalFilesWithDifferentKeysAreNeverDroppedSilently) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  std::vector<ImportBatch> batches;
  for (int i = 0; i < 200; ++i) batches.push_back(reading('c', 0.01 * (i + 1), -1.0 * i));
  const auto before = dump_database(dir / "db");
  EXPECT_THROW(db.import(batches, ImportPolicy{}), InputError);
  EXPECT_EQ(dump_database(dir / "db"), before);
  EXPECT_TRUE(db.runs().empty());
}

TEST(DatabaseCuration, ReplaceCorrectsAnImportAndMakesItsFitsAndSurfacesStale) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({reading('a', 0.1, -0.11), reading('b', 0.2, -0.44)}, ImportPolicy{});
  db.save_fit(fit_of(db.runs()));
  SurfaceRecord surface;
  surface.name = "s";
  surface.body = "sphere";
  surface.kind = "grid";
  surface.method = "linear";
  surface.definition = "{}";
  surface.quality = "{}";
  surface.run_ids = {db.runs()[0].id, db.runs()[1].id};
  db.save_surface(surface);
  ASSERT_FALSE(db.fits()[0].stale);

  // File b was read with the wrong speed: corrected with --replace.
  ImportPolicy replace;
  replace.replace = true;
  replace.components = ConflictPolicy::Replace;
  const auto outcome = db.import({reading('b', 0.3, -0.99)}, replace);
  EXPECT_TRUE(outcome[0].replaced);
  const auto runs = db.runs();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].key.nu_b[0], 0.1);
  EXPECT_EQ(runs[1].key.nu_b[0], 0.3);  // the run at 0.2 is gone with its import
  EXPECT_EQ(runs[1].tau_b[0]->value.total, -0.99);
  EXPECT_TRUE(db.fits()[0].stale);
  EXPECT_TRUE(db.surfaces()[0].stale);
  EXPECT_EQ(db.integrity_check(), "ok");
  EXPECT_EQ(foreign_key_problems(dir / "db"), "");
  // The import records the new settings.
  const auto record = db.import_record(runs[1].tau_b[0]->import_id);
  ASSERT_TRUE(record);
  EXPECT_EQ(record->settings_key, "u=0.300000");
  EXPECT_FALSE(record->hydrocoef_version.empty());
}

TEST(DatabaseCuration, AlsoKeepsASecondReadingOfTheSameFile) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({reading('a', 0.1, -0.11)}, ImportPolicy{});
  ImportPolicy also;
  also.also = "mean";
  const auto outcome = db.import({reading('a', 0.15, -0.2)}, also);
  EXPECT_FALSE(outcome[0].already_imported);
  EXPECT_EQ(outcome[0].reading, "mean");
  EXPECT_EQ(db.runs().size(), 2u);
  also.also = "not an identifier";
  EXPECT_THROW(db.import({reading('a', 0.15, -0.2)}, also), InputError);
}

TEST(DatabaseCuration, DeletingRunsLeavesNoOrphansAndMakesFitsStale) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({reading('a', 0.1, -0.11), reading('b', 0.2, -0.44), reading('c', 0.3, -0.99)}, ImportPolicy{});
  db.save_fit(fit_of(db.runs()));
  const auto before = dump_database(dir / "db");
  EXPECT_THROW(db.delete_runs({db.runs()[0].id, 12345}), InputError);
  EXPECT_EQ(dump_database(dir / "db"), before);

  const auto outcome = db.delete_runs({db.runs()[1].id});
  EXPECT_EQ(outcome.runs, 1u);
  EXPECT_EQ(outcome.components, 1u);
  EXPECT_EQ(outcome.fits_made_stale, 1u);
  EXPECT_EQ(outcome.imports_removed, 1u);
  EXPECT_EQ(db.runs().size(), 2u);
  EXPECT_EQ(db.integrity_check(), "ok");
  EXPECT_EQ(foreign_key_problems(dir / "db"), "");
  const auto fits = db.fits();
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_TRUE(fits[0].stale);
  EXPECT_EQ(fits[0].run_ids.size(), 3u);  // still says what it was built from
  // The deleted file can be imported again: its import went with its run.
  EXPECT_FALSE(db.import({reading('b', 0.2, -0.44)}, ImportPolicy{})[0].already_imported);
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

// A reading whose X is a mean over a force history, with its statistics.
ImportBatch averaged_reading(char hash, double u, double x, double standard_error, std::vector<std::string> flags) {
  ImportBatch batch = reading(hash, u, x);
  RunStatistics statistics;
  statistics.abscissa = "time";
  statistics.convergence = "transient-window";
  statistics.flags = flags;
  statistics.components[0] = ComponentStatistics{standard_error, 0.07, -0.001, 42.5};
  statistics.windows[0] = ComponentWindow{"MSER-5 (White 1997)", 2.5, 10.0, 751, std::move(flags)};
  batch.runs.front().statistics = statistics;
  return batch;
}

TEST(DatabaseCuration, ForceStatisticsAreStoredWithTheirComponentAndGoWithIt) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "db"));
  db.import({averaged_reading('a', 0.1, -0.11, 0.002, {}), averaged_reading('b', 0.2, -0.44, 0.01, {"drifting"}),
             reading('c', 0.3, -0.99)},
            ImportPolicy{});
  auto runs = db.runs();
  ASSERT_EQ(runs.size(), 3u);
  ASSERT_TRUE(runs[0].tau_b[0]->statistics);
  const StoredStatistics& st = *runs[0].tau_b[0]->statistics;
  EXPECT_EQ(st.abscissa, "time");
  EXPECT_EQ(st.window_method, "MSER-5 (White 1997)");
  EXPECT_EQ(st.window_first, 2.5);
  EXPECT_EQ(st.window_last, 10.0);
  EXPECT_EQ(st.samples, 751u);
  EXPECT_EQ(st.values.standard_error, 0.002);
  EXPECT_EQ(st.values.spread, 0.07);
  EXPECT_EQ(st.values.drift, -0.001);
  EXPECT_EQ(st.values.effective_samples, 42.5);
  EXPECT_TRUE(st.flags.empty());
  EXPECT_TRUE(run_flags(runs[0]).empty());
  EXPECT_EQ(run_flags(runs[1]), std::vector<std::string>{"drifting"});
  EXPECT_FALSE(runs[2].tau_b[0]->statistics);  // a value without a history has none

  // Replaced by a reading without statistics: none of the old ones is left.
  ImportPolicy replace;
  replace.replace = true;
  db.import({reading('b', 0.2, -0.45, "0.2 corrected")}, replace);
  runs = db.runs();
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[1].tau_b[0]->value.total, -0.45);
  EXPECT_FALSE(runs[1].tau_b[0]->statistics);
  EXPECT_TRUE(run_flags(runs[1]).empty());

  // Deleted with their run: no orphan rows.
  db.delete_runs({runs[0].id});
  {
    auto raw = test::connect_database(dir / "db");
    auto count = raw.prepare("SELECT count(*) FROM run_force_statistics");
    ASSERT_TRUE(count.step());
    EXPECT_EQ(count.get_int(0), 0);
  }
  EXPECT_EQ(foreign_key_problems(dir / "db"), "");
}

TEST(DatabaseCuration, StatisticsOfAComponentTheRunLacksAreRefusedOnRead) {
  TempDir dir;
  {
    RunDatabase db(test::database_location(dir / "db"));
    db.import({averaged_reading('a', 0.1, -0.11, 0.002, {})}, ImportPolicy{});
  }
  test::connect_database(dir / "db")
      .execute(
          "INSERT INTO run_force_statistics SELECT run_id, 'Y', abscissa, window_method, window_first, "
          "window_last, samples, flags, standard_error, spread, drift, effective_samples, convergence, "
          "convergence_reason FROM "
          "run_force_statistics");
  RunDatabase db(test::database_location(dir / "db"), RunDatabase::OpenMode::ReadOnly);
  try {
    (void)db.runs();
    FAIL() << "statistics of a missing component were read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("run_force_statistics"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("statistics of Y"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace hydrocoef
