// Tests of src/store/database: migrations, keyed runs, provenance, one
// transaction per import, fits, and refusal of damaged or foreign files.
#include "src/store/database.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstring>
#include <fstream>
#include <utility>

#include "src/core/error.hpp"
#include "src/store/migrations.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/sqlite_dump.hpp"

namespace hydrocoef {
namespace {

using test::dump_database;
using test::TempDir;

ImportedRun make_run(std::array<double, 6> nu, std::size_t component, double value, std::size_t line,
                     std::map<std::string, double> disturbances = {}) {
  ImportedRun run;
  run.key.body = "sphere";
  run.key.nu_b = nu;
  run.key.disturbances = std::move(disturbances);
  run.tau_b[component] = ForceComponent{value, std::nullopt, std::nullopt};
  run.source_line = line;
  return run;
}

ImportBatch make_batch(const std::string& path, char hash_digit, std::vector<ImportedRun> runs) {
  ImportBatch batch;
  batch.source.path = path;
  batch.source.sha256 = std::string(64, hash_digit);
  batch.source.size_bytes = 123;
  batch.source.importer = "test";
  batch.source.importer_version = "1";
  batch.runs = std::move(runs);
  return batch;
}

constexpr std::size_t kX = 0, kY = 1, kN = 5;

TEST(RunDatabase, NewFileGetsEveryMigrationRecordedInUserVersion) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  EXPECT_EQ(db.schema_version(), static_cast<int>(store::migrations().size()));
  EXPECT_GE(db.schema_version(), 1);
  EXPECT_EQ(db.integrity_check(), "ok");
  // Opening again applies nothing and keeps the content.
  const auto before = dump_database(dir / "runs.db");
  RunDatabase again(test::database_location(dir / "runs.db"));
  EXPECT_EQ(dump_database(dir / "runs.db"), before);
}

// The staleness triggers look up the runs of fits and surfaces by run id for
// every force row written: by an index, not by reading the whole table
// (replacing or deleting 40,000 runs a fit covers was quadratic: 145 s).
TEST(RunDatabase, FitAndSurfaceRunsAreFoundByRunThroughAnIndex) {
  if (test::on_postgresql()) GTEST_SKIP() << "SQLite's query plan";
  TempDir dir;
  { RunDatabase db(dir / "runs.db"); }
  sqlite3* handle = nullptr;
  ASSERT_EQ(sqlite3_open_v2((dir / "runs.db").c_str(), &handle, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  for (const auto& [table, index] :
       {std::pair{"fit_run", "fit_run_by_run"}, std::pair{"surface_run", "surface_run_by_run"}}) {
    const std::string sql = std::string("EXPLAIN QUERY PLAN SELECT * FROM ") + table + " WHERE run_id = 7";
    sqlite3_stmt* plan = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(handle, sql.c_str(), -1, &plan, nullptr), SQLITE_OK);
    std::string details;
    while (sqlite3_step(plan) == SQLITE_ROW) details += reinterpret_cast<const char*>(sqlite3_column_text(plan, 3));
    sqlite3_finalize(plan);
    EXPECT_NE(details.find(index), std::string::npos) << table << ": " << details;
    EXPECT_EQ(details.find("SCAN"), std::string::npos) << table << ": " << details;
  }
  sqlite3_close(handle);
}

TEST(RunDatabase, MustExistRefusesAMissingFileWithoutCreatingIt) {
  TempDir dir;
  EXPECT_THROW(RunDatabase(test::database_location(dir / "absent.db"), RunDatabase::OpenMode::MustExist), InputError);
  EXPECT_FALSE(test::database_exists(dir / "absent.db"));
}

TEST(RunDatabase, ImportsRunsAndFindsThemByKey) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  auto run = make_run({0.1, 0, 0, 0, 0, 0.2}, kX, -1.5, 3, {{"current_v", 0.05}});
  run.fluid.density_kg_m3 = 998.2;
  run.reference_point_b = {0.0, 0.0, 0.01};
  run.tau_b[kY] = ForceComponent{0.25, 0.2, 0.05};
  const auto outcomes = db.import({make_batch("a.csv", 'a', {run})}, ConflictPolicy::Error);
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_FALSE(outcomes[0].already_imported);
  EXPECT_EQ(outcomes[0].runs_created, 1u);
  EXPECT_EQ(outcomes[0].components_written, 2u);

  const auto found = db.find_run(run.key);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->key.nu_b, run.key.nu_b);
  EXPECT_EQ(found->key.disturbances, run.key.disturbances);
  EXPECT_EQ(found->fluid.density_kg_m3, 998.2);
  EXPECT_FALSE(found->fluid.kinematic_viscosity_m2_s.has_value());
  EXPECT_EQ(found->reference_point_b[2], 0.01);
  ASSERT_TRUE(found->tau_b[kX].has_value());
  EXPECT_EQ(found->tau_b[kX]->value.total, -1.5);
  EXPECT_FALSE(found->tau_b[kX]->value.pressure.has_value());
  ASSERT_TRUE(found->tau_b[kY].has_value());
  EXPECT_EQ(found->tau_b[kY]->value.pressure, 0.2);
  EXPECT_EQ(found->tau_b[kY]->value.viscous, 0.05);
  EXPECT_EQ(found->tau_b[kY]->source_path, "a.csv");
  EXPECT_EQ(found->tau_b[kY]->source_line, 3u);
  EXPECT_FALSE(found->tau_b[kN].has_value());

  // A different disturbance value, body or velocity is another key.
  RunKey other = run.key;
  other.disturbances["current_v"] = 0.06;
  EXPECT_FALSE(db.find_run(other).has_value());
  other = run.key;
  other.disturbances.clear();
  EXPECT_FALSE(db.find_run(other).has_value());
  other = run.key;
  other.body = "cube";
  EXPECT_FALSE(db.find_run(other).has_value());
  other = run.key;
  other.nu_b[1] = 1e-12;
  EXPECT_FALSE(db.find_run(other).has_value());
}

TEST(RunDatabase, SourceProvenanceIsKept) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  db.import({make_batch("tables/a.csv", 'b', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2)})}, ConflictPolicy::Error);
  const auto sources = db.sources();
  ASSERT_EQ(sources.size(), 1u);
  EXPECT_EQ(sources[0].provenance.path, "tables/a.csv");
  EXPECT_EQ(sources[0].provenance.sha256, std::string(64, 'b'));
  EXPECT_EQ(sources[0].provenance.size_bytes, 123u);
  EXPECT_EQ(sources[0].provenance.importer, "test");
  EXPECT_EQ(sources[0].imported_at.size(), 20u);  // 2026-11-22T10:04:05Z
  EXPECT_EQ(sources[0].imported_at.back(), 'Z');
}

TEST(RunDatabase, SameBytesTwiceIsANoOpThatSaysSo) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  const auto batch = make_batch("a.csv", 'c', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2)});
  db.import({batch}, ConflictPolicy::Error);
  const auto before = dump_database(dir / "runs.db");
  auto renamed = batch;
  renamed.source.path = "copy-of-a.csv";
  const auto outcomes = db.import({renamed}, ConflictPolicy::Error);
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_TRUE(outcomes[0].already_imported);
  EXPECT_EQ(outcomes[0].previous_path, "a.csv");
  EXPECT_EQ(outcomes[0].runs_created, 0u);
  EXPECT_EQ(dump_database(dir / "runs.db"), before);
  // The same file twice in one call is imported once.
  TempDir other_dir;
  RunDatabase other(test::database_location(other_dir / "runs.db"));
  const auto both = other.import({batch, batch}, ConflictPolicy::Error);
  EXPECT_FALSE(both[0].already_imported);
  EXPECT_TRUE(both[1].already_imported);
  EXPECT_EQ(other.runs().size(), 1u);
}

TEST(RunDatabase, TwoFilesMayGiveDifferentComponentsOfOneRun) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  db.import({make_batch("surge.csv", 'd', {make_run({}, kX, -0.0002, 2)})}, ConflictPolicy::Error);
  const auto outcomes = db.import({make_batch("yaw.csv", 'e', {make_run({}, kN, -0.00006, 2)})}, ConflictPolicy::Error);
  EXPECT_EQ(outcomes[0].runs_created, 0u);
  EXPECT_EQ(outcomes[0].runs_extended, 1u);
  const auto runs = db.runs();
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].tau_b[kX]->source_path, "surge.csv");
  EXPECT_EQ(runs[0].tau_b[kN]->source_path, "yaw.csv");
}

TEST(RunDatabase, ConflictingComponentFailsAndLeavesEverythingAsItWas) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  db.import({make_batch("first.csv", '1', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1.0, 2)})}, ConflictPolicy::Error);
  const auto before = dump_database(dir / "runs.db");
  // The batch list holds a good new file first and a conflicting one second:
  // neither may land.
  const auto good = make_batch("good.csv", '2', {make_run({0.2, 0, 0, 0, 0, 0}, kX, 4.0, 2)});
  const auto clash = make_batch(
      "second.csv", '3', {make_run({0.3, 0, 0, 0, 0, 0}, kX, 9.0, 2), make_run({0.1, 0, 0, 0, 0, 0}, kX, 1.1, 3)});
  try {
    db.import({good, clash}, ConflictPolicy::Error);
    FAIL() << "expected a conflict";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("second.csv:3"), std::string::npos) << message;
    EXPECT_NE(message.find("first.csv:2"), std::string::npos) << message;
    EXPECT_NE(message.find("--replace"), std::string::npos) << message;
  }
  EXPECT_EQ(dump_database(dir / "runs.db"), before);
  EXPECT_EQ(db.integrity_check(), "ok");

  // With Replace the newer value wins and names its source.
  db.import({clash}, ConflictPolicy::Replace);
  const auto run = db.find_run(make_run({0.1, 0, 0, 0, 0, 0}, kX, 0, 0).key);
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->tau_b[kX]->value.total, 1.1);
  EXPECT_EQ(run->tau_b[kX]->source_path, "second.csv");
}

TEST(RunDatabase, DifferentFluidOrReferencePointForOneRunIsRefused) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  auto first = make_run({0.1, 0, 0, 0, 0, 0}, kX, 1.0, 2);
  first.fluid.density_kg_m3 = 998.2;
  db.import({make_batch("a.csv", 'a', {first})}, ConflictPolicy::Error);
  const auto before = dump_database(dir / "runs.db");

  auto salt = make_run({0.1, 0, 0, 0, 0, 0}, kN, 0.1, 2);
  salt.fluid.density_kg_m3 = 1025.0;
  EXPECT_THROW(db.import({make_batch("b.csv", 'b', {salt})}, ConflictPolicy::Replace), InputError);
  auto moved = make_run({0.1, 0, 0, 0, 0, 0}, kN, 0.1, 2);
  moved.reference_point_b = {0.1, 0, 0};
  EXPECT_THROW(db.import({make_batch("c.csv", 'c', {moved})}, ConflictPolicy::Replace), InputError);
  EXPECT_EQ(dump_database(dir / "runs.db"), before);

  // Unknown fluid properties are filled in by a later source.
  auto viscous = make_run({0.1, 0, 0, 0, 0, 0}, kN, 0.1, 2);
  viscous.fluid.kinematic_viscosity_m2_s = 1.004e-6;
  db.import({make_batch("d.csv", 'd', {viscous})}, ConflictPolicy::Error);
  const auto run = db.runs().at(0);
  EXPECT_EQ(run.fluid.density_kg_m3, 998.2);
  EXPECT_EQ(run.fluid.kinematic_viscosity_m2_s, 1.004e-6);
}

TEST(RunDatabase, FiltersByBodyComponentValueAndDisturbance) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  std::vector<ImportedRun> runs;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j)
      runs.push_back(make_run({0.1 * i, 0, 0, 0, 0, 0}, i % 2 ? kX : kN, i + j, 2 + static_cast<std::size_t>(3 * i + j),
                              {{"current_v", 0.05 * j}}));
  db.import({make_batch("grid.csv", 'f', runs)}, ConflictPolicy::Error);
  EXPECT_EQ(db.runs().size(), 12u);
  EXPECT_EQ(db.runs({.body = "sphere"}).size(), 12u);
  EXPECT_EQ(db.runs({.body = "cube"}).size(), 0u);
  EXPECT_EQ(db.runs({.with_force = kX}).size(), 6u);
  EXPECT_EQ(db.runs({.equal = {{"current_v", 0.1}}}).size(), 4u);
  EXPECT_EQ(db.runs({.equal = {{"current_v", 0.1}, {"u", 0.2}}}).size(), 1u);
  EXPECT_EQ(db.runs({.equal = {{"u", 0.2 + 1e-12}}}).size(), 3u);  // tolerance 1e-9
  EXPECT_EQ(db.runs({.equal = {{"u", 0.2001}}}).size(), 0u);
  EXPECT_EQ(db.runs({.equal = {{"wave_height", 0.0}}}).size(), 0u);
  EXPECT_EQ(db.bodies(), std::vector<std::string>{"sphere"});
}

TEST(RunDatabase, FitsAreStoredWithTheirRunsAndReplacedByName) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  db.import(
      {make_batch("a.csv", 'a', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2), make_run({0.2, 0, 0, 0, 0, 0}, kX, 2, 3)})},
      ConflictPolicy::Error);
  const auto runs = db.runs();
  FitRecord fit;
  fit.name = "sphere:X";
  fit.body = "sphere";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u,u|u|";
  fit.loss = "squared";
  fit.sign = SignConvention::OpposingMotion;
  fit.n = 2;
  fit.rmse = 0.5;
  fit.r2 = 0.9;
  fit.coefficients = {{"u", 1.5, 0.1}, {"u|u|", 10.0, std::nullopt}};
  fit.run_ids = {runs[0].id, runs[1].id};
  db.save_fit(fit);
  fit.rmse = 0.25;
  // A taken name is refused (nothing written) unless the caller replaces it.
  const auto stored = dump_database(dir / "runs.db");
  EXPECT_THROW(db.save_fit(fit), InputError);
  EXPECT_EQ(dump_database(dir / "runs.db"), stored);
  db.save_fit(fit, RunDatabase::NameTaken::Replace);
  const auto fits = db.fits("sphere");
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].rmse, 0.25);
  EXPECT_EQ(fits[0].sign, SignConvention::OpposingMotion);
  ASSERT_EQ(fits[0].coefficients.size(), 2u);
  EXPECT_EQ(fits[0].coefficients[0].term, "u");
  EXPECT_EQ(fits[0].coefficients[0].std_error, 0.1);
  EXPECT_FALSE(fits[0].coefficients[1].std_error.has_value());
  EXPECT_EQ(fits[0].run_ids.size(), 2u);
  EXPECT_TRUE(db.fits("cube").empty());

  fit.body = "cube";  // no such body: refused, nothing written
  const auto before = dump_database(dir / "runs.db");
  EXPECT_THROW(db.save_fit(fit), InputError);
  EXPECT_EQ(dump_database(dir / "runs.db"), before);
}

TEST(RunDatabase, RefusesFilesThatAreNotItsDatabases) {
  HYDROCOEF_SQLITE_FILE_ONLY("an SQLite file that is not a database, or of another program");
  TempDir dir;
  {
    std::ofstream garbage(dir / "garbage.db", std::ios::binary);
    for (int i = 0; i < 4096; ++i) garbage.put(static_cast<char>((i * 131 + 7) % 256));
  }
  try {
    RunDatabase db(test::database_location(dir / "garbage.db"));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("garbage.db"), std::string::npos) << error.what();
  }

  // Another program's SQLite database.
  sqlite3* foreign = nullptr;
  ASSERT_EQ(sqlite3_open((dir / "foreign.db").c_str(), &foreign), SQLITE_OK);
  sqlite3_exec(foreign, "CREATE TABLE t(x); INSERT INTO t VALUES (1);", nullptr, nullptr, nullptr);
  sqlite3_close(foreign);
  const auto foreign_before = dump_database(dir / "foreign.db");
  EXPECT_THROW(RunDatabase(test::database_location(dir / "foreign.db")), InputError);
  EXPECT_EQ(dump_database(dir / "foreign.db"), foreign_before);

  // A database from a newer hydrocoef.
  { RunDatabase db(test::database_location(dir / "newer.db")); }
  sqlite3* newer = nullptr;
  ASSERT_EQ(sqlite3_open((dir / "newer.db").c_str(), &newer), SQLITE_OK);
  sqlite3_exec(newer, "PRAGMA user_version = 999", nullptr, nullptr, nullptr);
  sqlite3_close(newer);
  try {
    RunDatabase db(test::database_location(dir / "newer.db"));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("999"), std::string::npos) << error.what();
  }
}

TEST(RunDatabase, DetectsACorruptedPage) {
  HYDROCOEF_SQLITE_FILE_ONLY("a damaged page of an SQLite file");
  TempDir dir;
  {
    RunDatabase db(test::database_location(dir / "runs.db"));
    std::vector<ImportedRun> runs;
    for (int i = 0; i < 400; ++i)
      runs.push_back(make_run({0.001 * i, 0, 0, 0, 0, 0}, kX, i, 2 + static_cast<std::size_t>(i)));
    db.import({make_batch("many.csv", 'a', runs)}, ConflictPolicy::Error);
  }
  // Overwrite the middle of the file (past the header page) with garbage.
  const auto size = std::filesystem::file_size(dir / "runs.db");
  ASSERT_GT(size, 3 * 4096u);
  {
    std::fstream file(dir / "runs.db", std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(size / 2));
    for (int i = 0; i < 4096; ++i) file.put(static_cast<char>(0xA5));
  }
  EXPECT_THROW(RunDatabase(test::database_location(dir / "runs.db")), InputError);
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

SurfaceRecord make_surface(const std::string& name, const std::string& body, std::vector<std::int64_t> runs) {
  SurfaceRecord s;
  s.name = name;
  s.body = body;
  s.kind = "grid";
  s.method = "pchip";
  s.definition = R"({"axes":[{"name":"u","breakpoints":[0,0.1,0.2]}],"outputs":["X"]})";
  s.data = {0.0, -0.1, -0.45, 1e-300, -0.0};
  s.quality = R"({"X":{"loo_max":0.01,"loo_rms":0.004}})";
  s.run_ids = std::move(runs);
  return s;
}

TEST(DatabaseSurfaces, RoundTripBitForBitWithTheirRuns) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  db.import(
      {make_batch("a.csv", 'a', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2), make_run({0.2, 0, 0, 0, 0, 0}, kX, 2, 3)})},
      ConflictPolicy::Error);
  const auto runs = db.runs();
  db.save_surface(make_surface("sphere-X", "sphere", {runs[0].id, runs[1].id}));
  const SurfaceRecord back = db.surface("sphere-X");
  const SurfaceRecord sent = make_surface("sphere-X", "sphere", {});
  EXPECT_EQ(back.body, "sphere");
  EXPECT_EQ(back.kind, "grid");
  EXPECT_EQ(back.method, "pchip");
  EXPECT_EQ(back.definition, sent.definition);
  EXPECT_EQ(back.quality, sent.quality);
  ASSERT_EQ(back.data.size(), sent.data.size());
  for (std::size_t i = 0; i < sent.data.size(); ++i)
    EXPECT_EQ(std::memcmp(&back.data[i], &sent.data[i], sizeof(double)), 0) << i;  // -0 and subnormals kept
  EXPECT_EQ(back.run_ids, (std::vector<std::int64_t>{runs[0].id, runs[1].id}));
  EXPECT_FALSE(back.stale);
  EXPECT_EQ(db.surfaces("sphere").size(), 1u);
  EXPECT_TRUE(db.surfaces("cube").empty());
}

TEST(DatabaseSurfaces, AChangeToTheBodysForcesMarksItsSurfacesStale) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  auto other = make_run({0.1, 0, 0, 0, 0, 0}, kX, 5, 2);
  other.key.body = "cube";
  db.import({make_batch("a.csv", 'a', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2)}), make_batch("c.csv", 'c', {other})},
            ConflictPolicy::Error);
  db.save_surface(make_surface("sphere-X", "sphere", {}));
  db.save_surface(make_surface("cube-X", "cube", {}));
  // A new run of the sphere: its surface is stale, the cube's is not.
  db.import({make_batch("b.csv", 'b', {make_run({0.3, 0, 0, 0, 0, 0}, kX, 3, 2)})}, ConflictPolicy::Error);
  EXPECT_TRUE(db.surface("sphere-X").stale);
  EXPECT_FALSE(db.surface("cube-X").stale);
  // Rebuilding (saving again) clears it; replacing a force stales it again.
  db.save_surface(make_surface("sphere-X", "sphere", {}));
  EXPECT_FALSE(db.surface("sphere-X").stale);
  db.import({make_batch("d.csv", 'd', {make_run({0.3, 0, 0, 0, 0, 0}, kX, 3.5, 2)})}, ConflictPolicy::Replace);
  EXPECT_TRUE(db.surface("sphere-X").stale);
  // A re-import of the same bytes changes nothing.
  db.save_surface(make_surface("sphere-X", "sphere", {}));
  db.import({make_batch("d.csv", 'd', {make_run({0.3, 0, 0, 0, 0, 0}, kX, 3.5, 2)})}, ConflictPolicy::Replace);
  EXPECT_FALSE(db.surface("sphere-X").stale);
}

TEST(DatabaseSurfaces, MissingNamesAndBodiesAreInputErrorsThatChangeNothing) {
  TempDir dir;
  RunDatabase db(test::database_location(dir / "runs.db"));
  db.import({make_batch("a.csv", 'a', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2)})}, ConflictPolicy::Error);
  db.save_surface(make_surface("sphere-X", "sphere", {}));
  try {
    db.surface("sphere-N");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("'sphere-X'"), std::string::npos) << error.what();
  }
  const auto before = dump_database(dir / "runs.db");
  EXPECT_THROW(db.save_surface(make_surface("boat-X", "boat", {})), InputError);
  EXPECT_EQ(dump_database(dir / "runs.db"), before);
}

TEST(DatabaseSurfaces, AnOlderDatabaseIsMigratedOnOpen) {
  HYDROCOEF_SQLITE_FILE_ONLY("an SQLite file of schema version 2 (PostgreSQL support starts at the latest)");
  TempDir dir;
  // A database as an earlier hydrocoef left it: migrations 1 and 2 only.
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open((dir / "old.db").c_str(), &raw), SQLITE_OK);
  for (int i = 0; i < 2; ++i) {
    const std::string sql(store::migrations()[static_cast<std::size_t>(i)].sql);
    ASSERT_EQ(sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  }
  sqlite3_exec(raw, "PRAGMA user_version = 2", nullptr, nullptr, nullptr);
  sqlite3_close(raw);
  RunDatabase db(test::database_location(dir / "old.db"));
  EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
  EXPECT_GE(RunDatabase::latest_schema_version(), 3);
  db.import({make_batch("a.csv", 'a', {make_run({0.1, 0, 0, 0, 0, 0}, kX, 1, 2)})}, ConflictPolicy::Error);
  db.save_surface(make_surface("sphere-X", "sphere", {}));
  EXPECT_EQ(db.surfaces().size(), 1u);
  EXPECT_EQ(db.integrity_check(), "ok");
}

}  // namespace
}  // namespace hydrocoef
