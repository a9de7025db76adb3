// Migration 11 (numerical uncertainty of mesh studies): a database of
// schema 10 opens at 11 with its runs and no stored study; stored results
// apply to the runs of their key on the finest mesh alone, combine with the
// other uncertainties in quadrature, and a second save of a key replaces it.
#include <gtest/gtest.h>

#include <cmath>

#include "src/pipeline/grid_convergence_runs.hpp"
#include "src/store/database.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/older_database.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

ImportedRun mesh_run(double u, double mesh, double cell_size, double x, double current = 0.0) {
  ImportedRun run;
  run.key.body = "hull";
  run.key.nu_b[0] = u;
  run.key.disturbances = {{"mesh", mesh}, {"cell_size", cell_size}};
  if (current != 0.0) run.key.disturbances["current_v"] = current;
  ForceComponent force;
  force.total = x;
  force.uncertainty = 0.03;
  run.tau_b[0] = force;
  return run;
}

void fill(RunDatabase& database) {
  int id = 0;
  for (const double current : {0.0, 0.05}) {
    database.import({test::one_run_batch(++id, mesh_run(0.2, 1, 0.01, -2.0, current))}, ConflictPolicy::Error);
    database.import({test::one_run_batch(++id, mesh_run(0.2, 2, 0.02, -2.1, current))}, ConflictPolicy::Error);
    database.import({test::one_run_batch(++id, mesh_run(0.2, 3, 0.04, -2.5, current))}, ConflictPolicy::Error);
  }
}

const StoredRun& run_at(const std::vector<StoredRun>& runs, double mesh, double current) {
  for (const auto& run : runs) {
    const auto c = run.key.disturbances.find("current_v");
    if (run.key.disturbances.at("mesh") == mesh && (c == run.key.disturbances.end() ? 0.0 : c->second) == current)
      return run;
  }
  throw std::runtime_error("no such run");
}

TEST(NumericalUncertainty, ADatabaseOfSchema10OpensAtTheLatestWithItsRuns) {
  HYDROCOEF_SQLITE_FILE_ONLY(
      "a database of an older schema version (PostgreSQL databases begin at the version that brought PostgreSQL)");
  test::TempDir dir;
  const auto current = dir / "current.db";
  {
    RunDatabase database(current);
    fill(database);
  }
  test::copy_as_schema_version(current, dir / "v10.db", 10);
  RunDatabase database(test::database_location(dir / "v10.db"));
  EXPECT_EQ(database.schema_version(), RunDatabase::latest_schema_version());
  EXPECT_GE(RunDatabase::latest_schema_version(), 11);
  EXPECT_EQ(database.runs().size(), 6u);
  EXPECT_TRUE(database.numerical_uncertainties().empty());
  EXPECT_EQ(database.integrity_check(), "ok");
  // The migrated database takes a study like a new one.
  GridConvergenceRequest request;
  request.body = "hull";
  database.save_numerical_uncertainties(numerical_uncertainty_records(grid_convergence_of_runs(database, request)));
  EXPECT_EQ(database.numerical_uncertainties("hull").size(), 2u);
}

TEST(NumericalUncertainty, AppliesToTheFinestMeshOfItsKeyAndCombinesInQuadrature) {
  test::TempDir dir;
  RunDatabase database(test::database_location(dir / "db.sqlite"));
  fill(database);
  GridConvergenceRequest request;
  request.body = "hull";
  const auto study = grid_convergence_of_runs(database, request);
  ASSERT_EQ(study.keys.size(), 2u);  // current_v = 0 and 0.05: two physical keys
  database.save_numerical_uncertainties(numerical_uncertainty_records(study));
  const auto stored = database.numerical_uncertainties();
  ASSERT_EQ(stored.size(), 2u);
  EXPECT_EQ(stored[0].mesh_parameter, "mesh");
  EXPECT_EQ(stored[0].fine_level, 1.0);
  EXPECT_EQ(stored[0].levels, 3u);
  EXPECT_EQ(stored[0].h, (std::array<double, 3>{0.01, 0.02, 0.04}));
  EXPECT_EQ(stored[0].phi, (std::array<double, 3>{-2.0, -2.1, -2.5}));
  EXPECT_EQ(stored[0].convergence, "monotonic");
  ASSERT_TRUE(stored[0].gci_fine && stored[0].numerical_uncertainty);
  // e21 = -0.1, e32 = -0.4, r = 2: p = 2, phi_ext = (4 (-2) + 2.1) / 3.
  EXPECT_NEAR(*stored[0].apparent_order, 2.0, 1e-12);
  EXPECT_NEAR(*stored[0].extrapolated, (4 * -2.0 + 2.1) / 3.0, 1e-12);
  EXPECT_NEAR(*stored[0].gci_fine, 1.25 * 0.05 / 3.0, 1e-12);
  EXPECT_NEAR(*stored[0].numerical_uncertainty, 1.25 * 0.05 / 3.0 * 2.0 / 2.0, 1e-12);

  const auto runs = database.runs();
  for (const double current : {0.0, 0.05}) {
    const auto& fine = *run_at(runs, 1, current).tau_b[0];
    ASSERT_TRUE(fine.numerical_uncertainty);
    EXPECT_NEAR(*fine.numerical_uncertainty, *stored[0].numerical_uncertainty, 1e-15);
    EXPECT_NEAR(fine.standard_uncertainty(), std::hypot(0.03, *fine.numerical_uncertainty), 1e-15);
    EXPECT_FALSE(run_at(runs, 2, current).tau_b[0]->numerical_uncertainty);
    EXPECT_FALSE(run_at(runs, 3, current).tau_b[0]->numerical_uncertainty);
    EXPECT_EQ(run_at(runs, 2, current).tau_b[0]->standard_uncertainty(), 0.03);
  }
  // find_run loads the same.
  EXPECT_TRUE(database.find_run(run_at(runs, 1, 0.05).key)->tau_b[0]->numerical_uncertainty);

  // Saving a key again replaces its rows; the other key keeps its own.
  auto again = numerical_uncertainty_records(study);
  again.resize(1);
  again[0].numerical_uncertainty = 0.5;
  database.save_numerical_uncertainties(again);
  const auto replaced = database.numerical_uncertainties();
  ASSERT_EQ(replaced.size(), 2u);
  EXPECT_EQ(*replaced[0].numerical_uncertainty, 0.5);
  EXPECT_NEAR(*replaced[1].numerical_uncertainty, *stored[1].numerical_uncertainty, 1e-15);
}

}  // namespace
}  // namespace hydrocoef
