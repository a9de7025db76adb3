// The store's promises on both backends (src/store/connection.hpp): the same
// RunDatabase calls give the same rows on an SQLite file and on a PostgreSQL
// server (started by scripts/postgresql-test-server.sh): migrations, exact
// doubles and blobs, one transaction per write, no-op re-imports, refused
// conflicts that change nothing, staleness triggers, deletes, forced-
// oscillation records, the schema check, and writers that wait for each
// other.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <thread>

#include "src/core/error.hpp"
#include "src/store/database.hpp"
#include "src/store/dialect.hpp"
#include "src/store/migrations.hpp"
#include "src/store/pmm_record.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/test_database.hpp"

namespace hydrocoef {
namespace {

using test::TestDatabase;

ImportedRun make_run(std::array<double, 6> nu, std::size_t component, double value, std::size_t line = 1) {
  ImportedRun run;
  run.key.body = "sphere";
  run.key.nu_b = nu;
  run.tau_b[component] = ForceComponent{value, std::nullopt, std::nullopt};
  run.source_line = line;
  return run;
}

class StoreBackends : public testing::TestWithParam<store::Backend> {
 protected:
  TestDatabase db_{GetParam()};
};

TEST_P(StoreBackends, NewDatabaseGetsEveryMigrationAndOpeningAgainChangesNothing) {
  HYDROCOEF_NEED_DATABASE(db_);
  {
    RunDatabase db(db_.location());
    EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
    EXPECT_EQ(db.backend(), GetParam());
  }
  const std::string before = db_.dump();
  RunDatabase again(db_.location());
  EXPECT_EQ(again.schema_version(), RunDatabase::latest_schema_version());
  EXPECT_EQ(db_.dump(), before);
}

TEST_P(StoreBackends, DoublesComeBackBitForBit) {
  HYDROCOEF_NEED_DATABASE(db_);
  RunDatabase db(db_.location());
  // Values whose shortest decimal form needs 17 digits, subnormals, extremes.
  const std::vector<double> values = {
      0.1 + 0.2,           1.0 / 3.0,    4.9406564584124654e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
      -123456.78901234567, 6.02214076e23};
  std::vector<ImportBatch> batches;
  for (std::size_t i = 0; i < values.size(); ++i) {
    ImportedRun run = make_run({static_cast<double>(i) * 0.1 + 1e-17, 0, 0, 0, 0, 0}, 0, values[i]);
    run.fluid.density_kg_m3 = 998.2071234567891;
    batches.push_back(test::one_run_batch(static_cast<int>(i) + 1, run));
  }
  db.import(batches, ConflictPolicy::Error);
  const auto runs = db.runs();
  ASSERT_EQ(runs.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto found = db.find_run(batches[i].runs[0].key);
    ASSERT_TRUE(found) << i;
    EXPECT_EQ(found->key.nu_b[0], batches[i].runs[0].key.nu_b[0]) << i;
    ASSERT_TRUE(found->tau_b[0]);
    EXPECT_EQ(found->tau_b[0]->value.total, values[i]) << i;  // exact, not near
    EXPECT_EQ(*found->fluid.density_kg_m3, 998.2071234567891);
  }
}

TEST_P(StoreBackends, ReimportIsANoOpAndAConflictChangesNothing) {
  HYDROCOEF_NEED_DATABASE(db_);
  RunDatabase db(db_.location());
  const ImportBatch first = test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5, 3));
  const auto outcome = db.import({first}, ConflictPolicy::Error);
  ASSERT_EQ(outcome.size(), 1u);
  EXPECT_EQ(outcome[0].runs_created, 1u);
  const std::string before = db_.dump();

  const auto again = db.import({first}, ConflictPolicy::Error);
  EXPECT_TRUE(again[0].already_imported);
  EXPECT_EQ(db_.dump(), before);

  // Another file with X of the same run: refused, nothing of it stored (its
  // second run, which would be new, neither).
  ImportBatch conflicting = test::one_run_batch(2, make_run({0.7, 0, 0, 0, 0, 0}, 0, 1.0));
  conflicting.runs.push_back(make_run({0.5, 0, 0, 0, 0, 0}, 0, -13.0, 9));
  EXPECT_THROW(db.import({conflicting}, ConflictPolicy::Error), InputError);
  EXPECT_EQ(db_.dump(), before);
  // With Replace it supersedes the component.
  db.import({conflicting}, ConflictPolicy::Replace);
  const auto run = db.find_run(first.runs[0].key);
  ASSERT_TRUE(run && run->tau_b[0]);
  EXPECT_EQ(run->tau_b[0]->value.total, -13.0);
  EXPECT_EQ(run->tau_b[0]->source_path, "case-2.csv");
  EXPECT_EQ(db.runs().size(), 2u);
}

TEST_P(StoreBackends, FitsAndSurfacesBecomeStaleWhenTheirForcesChange) {
  HYDROCOEF_NEED_DATABASE(db_);
  RunDatabase db(db_.location());
  db.import({test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5))}, ConflictPolicy::Error);
  const auto run_id = db.runs().at(0).id;

  FitRecord fit;
  fit.name = "X(u)";
  fit.body = "sphere";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u|u|";
  fit.loss = "squared";
  fit.n = 1;
  fit.rmse = 0.0;
  fit.r2 = 1.0;
  fit.covariance = {0.25};
  fit.coefficients = {{"u|u|", -50.0, 0.5}};
  fit.run_ids = {run_id};
  db.save_fit(fit);
  EXPECT_THROW(db.save_fit(fit), InputError);  // the name is taken
  fit.coefficients[0].value = -49.0;
  db.save_fit(fit, RunDatabase::NameTaken::Replace);

  SurfaceRecord surface;
  surface.name = "X-surface";
  surface.body = "sphere";
  surface.kind = "grid";
  surface.method = "linear";
  surface.definition = "{}";
  surface.data = {1.5, -0.0, std::nextafter(1.0, 2.0), 1e-310};
  surface.quality = "{}";
  surface.run_ids = {run_id};
  db.save_surface(surface);
  SurfaceRecord empty = surface;
  empty.name = "empty";
  empty.data.clear();
  db.save_surface(empty);

  auto fits = db.fits();
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_FALSE(fits[0].stale);
  EXPECT_EQ(fits[0].coefficients.at(0).value, -49.0);
  EXPECT_EQ(fits[0].covariance, std::vector<double>{0.25});
  EXPECT_EQ(fits[0].run_ids, std::vector<std::int64_t>{run_id});
  const SurfaceRecord back = db.surface("X-surface");
  ASSERT_EQ(back.data.size(), surface.data.size());
  for (std::size_t i = 0; i < surface.data.size(); ++i)
    EXPECT_EQ(std::signbit(back.data[i]), std::signbit(surface.data[i])) << i;
  EXPECT_EQ(back.data, surface.data);
  EXPECT_TRUE(db.surface("empty").data.empty());
  EXPECT_FALSE(back.stale);

  // A new component of the run: the triggers mark both stale.
  db.import({test::one_run_batch(2, make_run({0.5, 0, 0, 0, 0, 0}, 1, 3.0))}, ConflictPolicy::Error);
  EXPECT_TRUE(db.fits().at(0).stale);
  EXPECT_TRUE(db.surface("X-surface").stale);
}

TEST_P(StoreBackends, DeletingRunsRemovesTheirImportsAndStalesTheirFits) {
  HYDROCOEF_NEED_DATABASE(db_);
  RunDatabase db(db_.location());
  db.import({test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5)),
             test::one_run_batch(2, make_run({0.9, 0, 0, 0, 0, 0}, 0, -40.0))},
            ConflictPolicy::Error);
  const auto runs = db.runs();
  ASSERT_EQ(runs.size(), 2u);
  const std::string before = db_.dump();
  EXPECT_THROW(db.delete_runs({runs[0].id, 999999}), InputError);
  EXPECT_EQ(db_.dump(), before);
  const DeleteOutcome outcome = db.delete_runs({runs[0].id});
  EXPECT_EQ(outcome.runs, 1u);
  EXPECT_EQ(outcome.imports_removed, 1u);
  EXPECT_EQ(db.runs().size(), 1u);
  EXPECT_EQ(db.sources().size(), 1u);
}

TEST_P(StoreBackends, ForcedOscillationRecordsComeBackWithTheirHistory) {
  HYDROCOEF_NEED_DATABASE(db_);
  RunDatabase db(db_.location());
  PmmRecord r;
  r.body = "ball";
  r.dof = 0;
  r.amplitude = 0.015;
  r.omega = M_PI;
  r.phase = 0.0;
  r.motion_source = "--motion";
  r.window_start = 2.0;
  r.window_end = 12.0;
  r.periods = 5;
  r.samples = 500;
  r.size = 0.3;
  r.source_path = "case";
  r.source_sha256 = std::string(64, 'b');
  r.importer = "openfoam-forces";
  r.history = {0.0, 1.0, 0, 0, 0, 0, 0, 0.01, 0.9999, 0, 0, 0, 0, 0};
  r.coefficients.push_back({0, 0.001, 7.2525, 3.7e-6, 0.686, 1e-4, 0.99999, {-1.0, 2.0}});
  const auto saved = db.save_pmm({r});
  ASSERT_EQ(saved.size(), 1u);
  EXPECT_FALSE(saved[0].replaced);
  EXPECT_TRUE(db.save_pmm({r}).at(0).replaced);
  const auto back = db.pmm_records("ball");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].history, r.history);
  EXPECT_EQ(back[0].omega, M_PI);
  ASSERT_EQ(back[0].coefficients.size(), 1u);
  EXPECT_EQ(back[0].coefficients[0].added_mass, 7.2525);
  EXPECT_EQ(back[0].coefficients[0].harmonics, (std::vector<double>{-1.0, 2.0}));
}

TEST_P(StoreBackends, ASchemaChangedByAnotherProgramIsRefused) {
  HYDROCOEF_NEED_DATABASE(db_);
  { RunDatabase db(db_.location()); }
  {
    auto connection = db_.connect();
    connection.execute("ALTER TABLE run ADD COLUMN note TEXT");
  }
  try {
    RunDatabase db(db_.location());
    FAIL() << "a database with an added column was opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run"), std::string::npos) << e.what();
  }
  if (GetParam() != store::Backend::PostgreSQL) return;
  // A trigger switched off (fits would stay fresh after their forces change),
  // or calling a function of another schema (someone else's code), is
  // refused too.
  db_.connect().execute("ALTER TABLE run DROP COLUMN note");
  { RunDatabase db(db_.location()); }
  db_.connect().execute("ALTER TABLE run_force DISABLE TRIGGER run_force_insert_stales_fits");
  test::expect_input_error([&] { RunDatabase db(db_.location()); }, {"run_force_insert_stales_fits", "(disabled)"});
  db_.connect().execute(
      "ALTER TABLE run_force ENABLE TRIGGER run_force_insert_stales_fits; CREATE SCHEMA IF NOT EXISTS "
      "hc_elsewhere; CREATE OR REPLACE FUNCTION hc_elsewhere.f() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN "
      "RETURN NEW; END $$; DROP TRIGGER run_force_insert_stales_fits ON run_force; CREATE TRIGGER "
      "run_force_insert_stales_fits AFTER INSERT ON run_force FOR EACH ROW EXECUTE FUNCTION hc_elsewhere.f()");
  test::expect_input_error([&] { RunDatabase db(db_.location()); }, {"another schema"});
  db_.connect().execute("DROP SCHEMA hc_elsewhere CASCADE");
}

// Keys, indexes, foreign keys, CHECK constraints, defaults, identities and
// collations are compared too: each change below is refused when the
// database is opened, in one line naming what differs, and the database is
// left as it was.
TEST_P(StoreBackends, AKeyIndexOrConstraintChangedByAnotherProgramIsRefused) {
  HYDROCOEF_NEED_DATABASE(db_);
  if (GetParam() != store::Backend::PostgreSQL) GTEST_SKIP() << "SQLite's schema is compared as its SQL text";
  struct Change {
    std::string sql;
    std::vector<std::string> expected;
  };
  const std::vector<Change> changes = {
      // One sweep could store a key twice, or one run a force component twice.
      {"ALTER TABLE run DROP CONSTRAINT %unique(run)%",
       {"lacks table run: unique index (body_id, u, v, w, p, q, r, disturbance_key)"}},
      {"ALTER TABLE run_force DROP CONSTRAINT run_force_pkey",
       {"lacks table run_force: primary key (run_id, component)"}},
      // Deleting a run would leave its forces behind.
      {"ALTER TABLE run_force DROP CONSTRAINT run_force_run_id_fkey; ALTER TABLE run_force ADD FOREIGN KEY (run_id) "
       "REFERENCES run(id)",
       {"has table run_force: foreign key (run_id) references run (id) on update no action on delete no action "
        "where hydrocoef creates",
        "on delete cascade"}},
      {"ALTER TABLE run_force DROP CONSTRAINT %check(run_force)%",
       {"check constraints where hydrocoef creates table run_force: "}},
      {"CREATE INDEX extra ON run (u)", {"has table run: index (u)", "does not create"}},
      {"CREATE UNIQUE INDEX extra ON run (body_id, u) WHERE u > 0",
       {"has table run: unique index (body_id, u) (partial)"}},
      {"ALTER TABLE run ALTER COLUMN u DROP DEFAULT",
       {"has table run: column u double precision not null where hydrocoef creates", "not null default"}},
      {"ALTER TABLE run ALTER COLUMN id DROP IDENTITY",
       {"has table run: column id bigint not null where hydrocoef creates", "id bigint not null identity"}},
      // Another collation sorts and compares names otherwise.
      {"ALTER TABLE body ALTER COLUMN name TYPE text COLLATE \"POSIX\"",
       {"has table body: column name text collate POSIX not null where hydrocoef creates"}},
  };
  for (const Change& change : changes) {
    SCOPED_TRACE(change.sql);
    TestDatabase db(GetParam());
    { RunDatabase created(db.location()); }
    auto connection = db.connect();
    // Constraint names PostgreSQL chose: %kind(table)% is the table's first of that kind.
    std::string sql = change.sql;
    for (const auto& [marker, type] : {std::pair<std::string, std::string>{"%unique(", "u"}, {"%check(", "c"}}) {
      const std::size_t at = sql.find(marker);
      if (at == std::string::npos) continue;
      const std::size_t end = sql.find(")%", at);
      const std::string table = sql.substr(at + marker.size(), end - at - marker.size());
      auto name = connection.prepare(
          "SELECT conname FROM pg_constraint WHERE conrelid = ?1::regclass AND contype = ?2 ORDER BY conname");
      name.bind(1, table);
      name.bind(2, type);
      ASSERT_TRUE(name.step()) << table << " has no constraint of type " << type;
      sql.replace(at, end + 2 - at, name.get_text(0));
    }
    connection.execute(sql);
    const std::string before = db.dump();
    test::expect_input_error([&] { RunDatabase opened(db.location()); }, change.expected);
    EXPECT_EQ(db.dump(), before);
  }
}

TEST_P(StoreBackends, ASecondWriterWaitsThenSaysTheDatabaseIsBusy) {
  HYDROCOEF_NEED_DATABASE(db_);
  { RunDatabase db(db_.location()); }
  auto holder = db_.connect();
  holder.begin_write();
  holder.execute("INSERT INTO body(name) VALUES ('held')");
  setenv("HYDROCOEF_DB_TIMEOUT", "1", 1);
  const auto start = std::chrono::steady_clock::now();
  try {
    RunDatabase db(db_.location());
    db.import({test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5))}, ConflictPolicy::Error);
    ADD_FAILURE() << "an import ran beside another writer's transaction";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("busy"), std::string::npos) << e.what();
  }
  unsetenv("HYDROCOEF_DB_TIMEOUT");
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(900));
  holder.rollback();
  // Once the other writer has finished, the import goes through.
  RunDatabase db(db_.location());
  db.import({test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5))}, ConflictPolicy::Error);
  EXPECT_EQ(db.runs().size(), 1u);
  EXPECT_EQ(db.bodies(), std::vector<std::string>{"sphere"});
}

TEST_P(StoreBackends, TwoProcessesCreatingOneDatabaseAtOnceBothSucceed) {
  HYDROCOEF_NEED_DATABASE(db_);
  std::vector<std::thread> threads;
  std::atomic<int> failures{0};
  for (int i = 0; i < 4; ++i)
    threads.emplace_back([&, i] {
      try {
        RunDatabase db(db_.location());
        db.import({test::one_run_batch(i + 1, make_run({0.1 * (i + 1), 0, 0, 0, 0, 0}, 0, 1.0))},
                  ConflictPolicy::Error);
      } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        ++failures;
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(failures.load(), 0);
  RunDatabase db(db_.location());
  EXPECT_EQ(db.runs().size(), 4u);
}

/// Runs of 20 files, one per shard as 20 cluster jobs would write them.
std::vector<ImportBatch> sweep_batches() {
  std::vector<ImportBatch> out;
  for (int i = 0; i < 20; ++i) {
    ImportedRun run = make_run({0.05 * (i % 10), i < 10 ? 0.0 : 0.1, 0, 0, 0, 0}, i % 3 == 0 ? 5 : 0, -3.0 * i - 0.1,
                               static_cast<std::size_t>(i + 2));
    run.fluid.density_kg_m3 = 998.2;
    run.key.disturbances["mesh"] = 1.0 + (i % 2);
    RunStatistics statistics;
    statistics.abscissa = "iteration";
    statistics.convergence = "steady-window";
    statistics.components[i % 3 == 0 ? 5 : 0] = ComponentStatistics{0.01 * i, 0.2, 1e-4, 40.0};
    statistics.windows[i % 3 == 0 ? 5 : 0] = ComponentWindow{"MSER-5 (White 1997)", 500, 1000, 501, {}};
    run.statistics = statistics;
    ImportBatch batch = test::one_run_batch(i + 1, run);
    batch.source.settings = "{\"rho\":{\"value\":998.2,\"source\":\"command line\"}}";
    out.push_back(batch);
  }
  return out;
}

const std::set<std::string> kTimes = {"imported_at", "created_at"};

TEST_P(StoreBackends, MergingShardsEqualsImportingTheirFilesAndTwiceAddsNothing) {
  HYDROCOEF_NEED_DATABASE(db_);
  const auto batches = sweep_batches();
  std::vector<std::string> shards;
  for (std::size_t i = 0; i < batches.size(); ++i) {
    shards.push_back((db_.dir() / ("shard-" + std::to_string(i) + ".db")).string());
    RunDatabase shard(shards.back());
    shard.import({batches[i]}, ConflictPolicy::Error);
  }
  TestDatabase direct(store::Backend::SQLite);
  {
    RunDatabase db(direct.location());
    for (const auto& batch : batches) db.import({batch}, ConflictPolicy::Error);
  }
  RunDatabase db(db_.location());
  std::size_t seen = 0;
  const auto outcomes = db.merge(shards, [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(done, ++seen);
    EXPECT_EQ(total, shards.size());
  });
  ASSERT_EQ(outcomes.size(), 20u);
  for (const auto& o : outcomes) {
    EXPECT_EQ(o.imports_added, 1u);
    EXPECT_EQ(o.components, 1u);
  }
  EXPECT_EQ(db_.dump(kTimes), direct.dump(kTimes));
  // Provenance as recorded, time included: the shard's import time.
  const auto run = db.find_run(batches[7].runs[0].key);
  ASSERT_TRUE(run && run->tau_b[0] && run->tau_b[0]->statistics);
  EXPECT_EQ(run->tau_b[0]->source_line, 9u);
  EXPECT_EQ(db.import_record(run->tau_b[0]->import_id)->imported_at,
            RunDatabase(shards[7], RunDatabase::OpenMode::ReadOnly).import_record(1)->imported_at);

  const std::string before = db_.dump();
  const auto again = db.merge(shards);
  for (const auto& o : again) {
    EXPECT_EQ(o.imports_added, 0u);
    EXPECT_EQ(o.imports_already, 1u);
  }
  EXPECT_EQ(db_.dump(), before);
}

TEST_P(StoreBackends, AMergeConflictIsRefusedAndNothingOfAnyShardIsMerged) {
  HYDROCOEF_NEED_DATABASE(db_);
  const std::string good = (db_.dir() / "good.db").string(), bad = (db_.dir() / "bad.db").string();
  RunDatabase(good).import({test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5))}, ConflictPolicy::Error);
  // Another file with X of the same run: a conflict once both are merged.
  RunDatabase(bad).import({test::one_run_batch(2, make_run({0.5, 0, 0, 0, 0, 0}, 0, -13.0))}, ConflictPolicy::Error);
  RunDatabase db(db_.location());
  db.import({test::one_run_batch(3, make_run({0.9, 0, 0, 0, 0, 0}, 0, 1.0))}, ConflictPolicy::Error);
  const std::string before = db_.dump();
  try {
    db.merge({good, bad});
    FAIL() << "a conflicting shard was merged";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.db"), std::string::npos) << message;
    EXPECT_NE(message.find("case-1.csv"), std::string::npos) << message;
  }
  EXPECT_EQ(db_.dump(), before);
  // A fit of one name with other coefficients is a conflict too.
  FitRecord fit;
  fit.name = "X(u)";
  fit.body = "sphere";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u";
  fit.loss = "squared";
  fit.n = 1;
  fit.coefficients = {{"u", -25.0, std::nullopt}};
  db.save_fit(fit);
  fit.coefficients[0].value = -26.0;
  RunDatabase(good).save_fit(fit);
  const std::string with_fit = db_.dump();
  EXPECT_THROW(db.merge({good}), InputError);
  EXPECT_EQ(db_.dump(), with_fit);
}

TEST_P(StoreBackends, AShardWithATextItCannotHoldOrABrokenLinkIsRefusedWhole) {
  HYDROCOEF_NEED_DATABASE(db_);
  const std::string shard = (db_.dir() / "shard.db").string();
  RunDatabase(shard).import({test::one_run_batch(1, make_run({0.5, 0, 0, 0, 0, 0}, 0, -12.5))}, ConflictPolicy::Error);
  RunDatabase db(db_.location());
  const std::string before = db_.dump();
  {
    // A settings key with a NUL byte (SQLite holds it; PostgreSQL cannot).
    store::Connection raw(shard, store::Access::ReadWrite);
    raw.execute("UPDATE import SET settings_key = 'k' || char(0) || 'x'");
  }
  if (GetParam() == store::Backend::PostgreSQL) {
    test::expect_input_error([&] { db.merge({shard}); }, {"NUL byte"});
    EXPECT_EQ(db_.dump(), before);
  }
  {
    // A force that names an import the shard does not hold.
    store::Connection raw(shard, store::Access::ReadWrite);
    raw.execute("UPDATE import SET settings_key = 'k'; PRAGMA foreign_keys = OFF; UPDATE run_force SET import_id = 99");
  }
  test::expect_input_error([&] { db.merge({shard}); }, {"shard.db", "import 99"});
  EXPECT_EQ(db_.dump(), before);
}

TEST_P(StoreBackends, ARunsSurfaceIntegralsFromAnotherFileAreAMergeConflict) {
  HYDROCOEF_NEED_DATABASE(db_);
  const auto with_surface = [](int file, std::size_t component, double value, double area) {
    ImportedRun run = make_run({0.4, 0, 0, 0, 0, 0}, component, value);
    SurfaceIntegrals g;
    g.faces = 100;
    g.area = area;
    g.pressure_array = "p";
    g.pressure_kind = "static";
    g.shear_convention = "on-wall";
    g.axes = "x,y,z";
    run.surface = g;
    return test::one_run_batch(file, run);
  };
  RunDatabase db(db_.location());
  db.import({with_surface(1, 0, -2.0, 0.28)}, ConflictPolicy::Error);
  // The shard's file gives another component of the same run (no force
  // conflict) with other surface integrals.
  const std::string shard = (db_.dir() / "shard.db").string();
  RunDatabase(shard).import({with_surface(2, 1, 0.5, 0.31)}, ConflictPolicy::Error);
  const std::string before = db_.dump();
  test::expect_input_error([&] { db.merge({shard}); }, {"shard.db", "surface integrals from another file"});
  EXPECT_EQ(db_.dump(), before);
}

TEST_P(StoreBackends, ACopyOfASourceWithAValueOfTheWrongTypeIsRefusedBeforeARowIsCopied) {
  HYDROCOEF_NEED_DATABASE(db_);
  TestDatabase original(store::Backend::SQLite);
  RunDatabase(original.location()).import(sweep_batches(), ConflictPolicy::Error);
  original.connect().execute("UPDATE run SET u = 'fast' WHERE id = 2");
  { RunDatabase target(db_.location()); }
  const std::string before = db_.dump();
  {
    RunDatabase source(original.location(), RunDatabase::OpenMode::ReadOnly);
    RunDatabase target(db_.location());
    test::expect_input_error([&] { target.copy_from(source); }, {"table 'run', row 2, column 'u'", "'fast'"});
  }
  EXPECT_EQ(db_.dump(), before);
}

TEST_P(StoreBackends, ASearchPathNamingNoSchemaIsRefusedInOneLine) {
  if (GetParam() != store::Backend::PostgreSQL) GTEST_SKIP() << "a PostgreSQL URL's search_path";
  const auto server = test::postgresql_test_server();
  if (!server) {
    if (std::getenv("HYDROCOEF_TEST_POSTGRESQL_REQUIRED")) FAIL() << "HYDROCOEF_TEST_POSTGRESQL is not set";
    GTEST_SKIP() << "no PostgreSQL test server";
  }
  const std::string url = test::url_with_schema(*server, "no_such_schema");
  test::expect_input_error([&] { RunDatabase db(url); }, {"no schema that exists", "CREATE SCHEMA"});
}

TEST_P(StoreBackends, ACopyAndACopyBackHoldTheOriginalsRows) {
  HYDROCOEF_NEED_DATABASE(db_);
  TestDatabase original(store::Backend::SQLite);
  {
    RunDatabase db(original.location());
    db.import(sweep_batches(), ConflictPolicy::Error);
    const auto runs = db.runs();
    db.delete_runs({runs.at(3).id});  // a gap in the ids
    FitRecord fit;
    fit.name = "N(r)";
    fit.body = "sphere";
    fit.dof = "N";
    fit.variable = "r";
    fit.terms = "r";
    fit.loss = "squared";
    fit.n = 2;
    fit.coefficients = {{"r", -0.5, 0.01}};
    fit.run_ids = {runs.at(0).id, runs.at(5).id};
    db.save_fit(fit);
    SurfaceRecord surface;
    surface.name = "s";
    surface.body = "sphere";
    surface.kind = "grid";
    surface.method = "linear";
    surface.definition = "{\"axes\":[]}";
    surface.data = {0.1, 0.2, -0.0};
    surface.quality = "{}";
    surface.run_ids = {runs.at(1).id};
    db.save_surface(surface);
    // A new component after the surface: it becomes stale.
    db.import({test::one_run_batch(99, make_run(runs.at(1).key.nu_b, 1, 7.0))}, ConflictPolicy::Error);
  }
  const std::string rows = original.dump();
  {
    RunDatabase source(original.location(), RunDatabase::OpenMode::ReadOnly);
    RunDatabase target(db_.location());
    const auto copied = target.copy_from(source);
    EXPECT_FALSE(copied.empty());
  }
  EXPECT_EQ(db_.dump(), rows);
  TestDatabase back(store::Backend::SQLite);
  {
    RunDatabase source(db_.location(), RunDatabase::OpenMode::ReadOnly);
    RunDatabase target(back.location());
    target.copy_from(source);
    // Not into a database that holds data.
    EXPECT_THROW(target.copy_from(source), InputError);
    // A new run gets the next id after the copied ones.
    target.import({test::one_run_batch(500, make_run({3, 0, 0, 0, 0, 0}, 0, 1.0))}, ConflictPolicy::Error);
  }
  {
    RunDatabase copy(db_.location());
    copy.import({test::one_run_batch(500, make_run({3, 0, 0, 0, 0, 0}, 0, 1.0))}, ConflictPolicy::Error);
  }
  EXPECT_EQ(back.dump(kTimes), db_.dump(kTimes));
}

// A server that takes the connection but never answers (here a socket that
// listens and reads nothing) is given up after HYDROCOEF_DB_TIMEOUT (libpq's
// minimum, 2 s, here) in one line, instead of waiting for ever; a
// connect_timeout in the URL, or $PGCONNECT_TIMEOUT, still decides.
TEST(PostgreSqlConnection, AServerThatDoesNotAnswerIsGivenUpAfterTheTimeout) {
  const int listener = socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(listener, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(listen(listener, 4), 0);
  socklen_t length = sizeof address;
  ASSERT_EQ(getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length), 0);
  const std::string url = "postgresql://127.0.0.1:" + std::to_string(ntohs(address.sin_port)) + "/silent";
  unsetenv("PGCONNECT_TIMEOUT");
  setenv("HYDROCOEF_DB_TIMEOUT", "1", 1);
  const auto start = std::chrono::steady_clock::now();
  test::expect_input_error([&] { RunDatabase db(url); }, {"cannot connect to the PostgreSQL server", "timeout"});
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(waited, 1.5);
  EXPECT_LT(waited, 20.0);
  // The URL's own value is read after the default, so it wins (here: refused as not a number).
  test::expect_input_error([&] { RunDatabase db(url + "?connect_timeout=soon"); }, {"connect_timeout", "soon"});
  setenv("PGCONNECT_TIMEOUT", "later", 1);
  test::expect_input_error([&] { RunDatabase db(url); }, {"connect_timeout", "later"});
  unsetenv("PGCONNECT_TIMEOUT");
  unsetenv("HYDROCOEF_DB_TIMEOUT");
  close(listener);
}

/// Two schemas of the test server's own, dropped at the end: the data's and
/// an attacker's, whose functions share names with PostgreSQL's built-ins.
class PlantedSchemas {
 public:
  explicit PlantedSchemas(std::string server) : server_(std::move(server)) {
    const std::string id = std::to_string(::getpid());
    data_ = "hcdata_" + id;
    evil_ = "hcevil_" + id;
    admin().execute("DROP SCHEMA IF EXISTS " + data_ + " CASCADE; CREATE SCHEMA " + data_ + "; DROP SCHEMA IF EXISTS " +
                    evil_ + " CASCADE; CREATE SCHEMA " + evil_);
  }
  ~PlantedSchemas() {
    try {
      admin().execute("DROP SCHEMA IF EXISTS " + data_ + " CASCADE; DROP SCHEMA IF EXISTS " + evil_ + " CASCADE");
    } catch (...) {}
  }
  PlantedSchemas(const PlantedSchemas&) = delete;
  PlantedSchemas& operator=(const PlantedSchemas&) = delete;
  store::Connection admin() const { return store::Connection::postgresql(server_, server_, store::Access::ReadWrite); }
  const std::string& data() const { return data_; }
  const std::string& evil() const { return evil_; }

 private:
  std::string server_, data_, evil_;
};

// CVE-2018-1058: a function planted in a schema of the user's search_path
// that matches a call's argument types better than the built-in (setval(text,
// bigint) for the text pg_get_serial_sequence gives) would run as the user
// who copies. The copy's calls are pg_catalog's, and the session's
// search_path is the data's schema alone.
TEST(PostgreSqlConnection, AFunctionPlantedOnTheSearchPathIsNeverCalled) {
  const auto server = test::postgresql_test_server();
  if (!server) {
    if (std::getenv("HYDROCOEF_TEST_POSTGRESQL_REQUIRED")) FAIL() << "HYDROCOEF_TEST_POSTGRESQL is not set";
    GTEST_SKIP() << "no PostgreSQL test server";
  }
  PlantedSchemas schemas(*server);
  const std::string evil = schemas.evil();
  schemas.admin().execute("CREATE TABLE " + evil + ".calls (name text); CREATE FUNCTION " + evil +
                          ".setval(text, bigint) RETURNS bigint LANGUAGE sql AS $$ INSERT INTO " + evil +
                          ".calls VALUES ('setval'); SELECT $2 $$; CREATE FUNCTION " + evil +
                          ".current_schema() RETURNS name LANGUAGE sql AS $$ INSERT INTO " + evil +
                          ".calls VALUES ('current_schema'); SELECT 'x'::name $$; CREATE FUNCTION " + evil +
                          ".hashtext(name) RETURNS integer LANGUAGE sql AS $$ INSERT INTO " + evil +
                          ".calls VALUES ('hashtext'); SELECT 1 $$");
  TestDatabase source(store::Backend::SQLite);
  {
    RunDatabase db(source.location());
    db.import(sweep_batches(), ConflictPolicy::Error);
  }
  const std::string url = test::url_with_schema(*server, schemas.data() + "%2C" + evil);
  {
    RunDatabase from(source.location(), RunDatabase::OpenMode::ReadOnly);
    RunDatabase target(url);
    EXPECT_FALSE(target.copy_from(from).empty());
    // A write after the copy: the next id comes after the copied ones.
    target.import({test::one_run_batch(500, make_run({3, 0, 0, 0, 0, 0}, 0, 1.0))}, ConflictPolicy::Error);
    EXPECT_EQ(target.runs().size(), sweep_batches().size() + 1);
  }
  auto admin = schemas.admin();
  auto calls = admin.prepare("SELECT name FROM " + evil + ".calls");
  std::string called;
  while (calls.step()) called += calls.get_text(0) + " ";
  EXPECT_EQ(called, "");
}

// session_replication_role = replica switches off every ordinary trigger,
// among them those that mark fits and surfaces stale: refused on connecting.
TEST(PostgreSqlConnection, ASessionThatSwitchesOffTriggersIsRefused) {
  const auto server = test::postgresql_test_server();
  if (!server) {
    if (std::getenv("HYDROCOEF_TEST_POSTGRESQL_REQUIRED")) FAIL() << "HYDROCOEF_TEST_POSTGRESQL is not set";
    GTEST_SKIP() << "no PostgreSQL test server";
  }
  PlantedSchemas schemas(*server);
  const std::string url = test::url_with_schema(*server, schemas.data() + "%20-csession_replication_role%3Dreplica");
  for (const auto mode : {RunDatabase::OpenMode::CreateIfMissing, RunDatabase::OpenMode::ReadOnly})
    test::expect_input_error([&] { RunDatabase db(url, mode); },
                             {"session_replication_role is 'replica'", "stale", "expected 'origin'"});
  // Nothing was made in the schema.
  auto admin = schemas.admin();
  auto tables = admin.prepare("SELECT count(*) FROM pg_catalog.pg_tables WHERE schemaname = ?");
  tables.bind(1, schemas.data());
  ASSERT_TRUE(tables.step());
  EXPECT_EQ(tables.get_int(0), 0);
}

// A reading command never upgrades a database: one of an older schema on a
// server is refused saying how to upgrade it, and `migrate` (a writing
// opening) does.
TEST(PostgreSqlConnection, AnOlderDatabaseIsRefusedByReadersAndUpgradedByAWriter) {
  const auto server = test::postgresql_test_server();
  if (!server) {
    if (std::getenv("HYDROCOEF_TEST_POSTGRESQL_REQUIRED")) FAIL() << "HYDROCOEF_TEST_POSTGRESQL is not set";
    GTEST_SKIP() << "no PostgreSQL test server";
  }
  PlantedSchemas schemas(*server);
  const std::string url = test::url_with_schema(*server, schemas.data());
  const int older = RunDatabase::latest_schema_version() - 1;
  {
    auto connection = store::Connection::postgresql(url, url, store::Access::ReadWrite);
    connection.execute("CREATE TABLE hydrocoef_schema (version BIGINT NOT NULL)");
    for (int i = 0; i < older; ++i)
      connection.execute(
          store::postgresql_migration(store::migrations()[static_cast<std::size_t>(i)].postgresql_sql()));
    connection.execute("INSERT INTO hydrocoef_schema VALUES (" + std::to_string(older) + ")");
  }
  test::expect_input_error([&] { RunDatabase db(url, RunDatabase::OpenMode::ReadOnly); },
                           {"schema version " + std::to_string(older), "does not upgrade it", "migrate"});
  {
    auto admin = schemas.admin();
    auto version = admin.prepare("SELECT version FROM " + schemas.data() + ".hydrocoef_schema");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.get_int(0), older);
  }
  RunDatabase db(url, RunDatabase::OpenMode::MustExist);
  EXPECT_EQ(db.opened_at_version(), older);
  EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreBackends, testing::Values(store::Backend::SQLite, store::Backend::PostgreSQL),
                         [](const testing::TestParamInfo<store::Backend>& param) {
                           return std::string(test::backend_name(param.param));
                         });

}  // namespace
}  // namespace hydrocoef
