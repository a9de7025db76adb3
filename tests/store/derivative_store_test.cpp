// Derivative models in the database (schema/0018_derivative_models.sql), on
// SQLite and, as postgresql.derivative_store_test, on PostgreSQL: stored and
// read back exactly (coefficients, undefined statistics as absent, the
// covariance, warnings, runs), a taken name refused or replaced, names that
// are data (quotes, SQL) kept as they are, a model made stale when a force of
// its runs changes, deleted by name (an unknown name refused listing the
// stored ones, nothing deleted), merged from a shard with its runs (once; a
// model of its name that differs is a conflict), and a damaged stored value refused naming
// the table and row.
#include <gtest/gtest.h>

#include "src/core/error.hpp"
#include "src/store/database.hpp"
#include "src/store/derivative_store.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

ImportedRun sway_run(double v, double y) {
  ImportedRun run;
  run.key.body = "ship";
  run.key.nu_b = {1.0, v, 0, 0, 0, 0.0};
  run.tau_b[1] = ForceComponent{y, std::nullopt, std::nullopt};
  return run;
}

DerivativeModelRecord sample_model(const std::string& name) {
  DerivativeModelRecord m;
  m.name = name;
  m.body = "ship";
  m.output = "Y";
  m.terms = "v, v*|v|";
  m.run_filter = "u=1";
  m.weighting = "none";
  m.n = 3;
  m.rmse = 0.25;
  m.r2 = std::nullopt;
  m.condition_number = 4.5;
  m.chi2_reduced = std::nullopt;
  m.covariance_scale = 1.0;
  m.interval_factor = 12.706204736174698;
  m.covariance = {0.01, -0.002, -0.002, 0.04};
  m.warnings = {{"ill-conditioned", "terms 'v' and \"v*|v|\" hardly differ"}};
  m.coefficients = {{"v", -1.5, 0.1, -2.7706, -0.2294, 3.25}, {"v*|v|", -0.125, 0.2, std::nullopt, std::nullopt, 3.25}};
  m.run_ids = {2, 1};
  return m;
}

class DerivativeStore : public ::testing::Test {
 protected:
  void SetUp() override {
    db_.import({test::one_run_batch(1, sway_run(0.1, -0.2)), test::one_run_batch(2, sway_run(0.2, -0.4))},
               ConflictPolicy::Error);
  }
  test::TempDir dir_;
  RunDatabase db_{test::database_location(dir_ / "d.db")};
};

TEST_F(DerivativeStore, AModelIsReadBackAsStored) {
  const DerivativeModelRecord m = sample_model("ship:Y('quoted'); DROP TABLE run; --)");
  const std::int64_t id = db_.save_derivative_model(m);
  const auto back = db_.derivative_models();
  ASSERT_EQ(back.size(), 1u);
  const auto& b = back[0];
  EXPECT_EQ(b.id, id);
  EXPECT_EQ(b.name, m.name);
  EXPECT_EQ(b.body, "ship");
  EXPECT_EQ(b.output, "Y");
  EXPECT_EQ(b.terms, "v, v*|v|");
  EXPECT_EQ(b.run_filter, "u=1");
  EXPECT_EQ(b.n, 3u);
  EXPECT_EQ(b.rmse, 0.25);
  EXPECT_FALSE(b.r2);
  EXPECT_FALSE(b.chi2_reduced);
  EXPECT_EQ(b.interval_factor, m.interval_factor);
  EXPECT_EQ(b.condition_number, 4.5);
  EXPECT_EQ(b.covariance, m.covariance);
  ASSERT_EQ(b.warnings.size(), 1u);
  EXPECT_EQ(b.warnings[0].message, m.warnings[0].message);
  ASSERT_EQ(b.coefficients.size(), 2u);
  EXPECT_EQ(b.coefficients[1].term, "v*|v|");
  EXPECT_EQ(b.coefficients[0].value, -1.5);
  EXPECT_EQ(b.coefficients[0].interval_low, -2.7706);
  EXPECT_FALSE(b.coefficients[1].interval_low);
  EXPECT_EQ(b.coefficients[1].vif, 3.25);
  EXPECT_EQ(b.run_ids, (std::vector<std::int64_t>{1, 2}));
  EXPECT_FALSE(b.stale);
  EXPECT_FALSE(b.created_at.empty());
  EXPECT_EQ(db_.runs().size(), 2u);  // the name stayed data
  EXPECT_TRUE(db_.derivative_models("other").empty());
}

TEST_F(DerivativeStore, ATakenNameIsRefusedOrReplaced) {
  db_.save_derivative_model(sample_model("m"));
  DerivativeModelRecord again = sample_model("m");
  again.rmse = 0.5;
  test::expect_input_error([&] { db_.save_derivative_model(again); },
                           {"a derivative model named 'm' exists", "give --replace"});
  EXPECT_EQ(db_.derivative_models()[0].rmse, 0.25);
  db_.save_derivative_model(again, RunDatabase::NameTaken::Replace);
  ASSERT_EQ(db_.derivative_models().size(), 1u);
  EXPECT_EQ(db_.derivative_models()[0].rmse, 0.5);
}

TEST_F(DerivativeStore, AChangedForceMakesTheModelStaleAndDeletingTakesItAway) {
  db_.save_derivative_model(sample_model("m"));
  db_.save_derivative_model(sample_model("n"));
  db_.delete_runs({2});
  for (const auto& model : db_.derivative_models()) {
    EXPECT_TRUE(model.stale) << model.name;
    EXPECT_EQ(model.run_ids, (std::vector<std::int64_t>{1, 2}));  // what it was made from, still
  }
  test::expect_input_error([&] { db_.delete_derivative_model("x"); },
                           {"no derivative model 'x'", "expected one of: 'm', 'n'"});
  EXPECT_EQ(db_.derivative_models().size(), 2u);
  db_.delete_derivative_model("m");
  ASSERT_EQ(db_.derivative_models().size(), 1u);
  EXPECT_EQ(db_.derivative_models()[0].name, "n");
}

TEST_F(DerivativeStore, AMergeBringsAShardsModelWithItsRunsOnceAndRefusesAnotherOfItsName) {
  const auto shard_path = test::database_location(dir_ / "shard.db");
  {
    RunDatabase shard(shard_path);
    shard.import({test::one_run_batch(7, sway_run(0.3, -0.6)), test::one_run_batch(2, sway_run(0.2, -0.4))},
                 ConflictPolicy::Error);
    DerivativeModelRecord m = sample_model("from-shard");
    m.run_ids.clear();
    for (const auto& run : shard.runs()) m.run_ids.push_back(run.id);
    shard.save_derivative_model(m);
  }
  const auto first = db_.merge({shard_path});
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].derivative_models_added, 1u);
  EXPECT_EQ(first[0].derivative_models_already, 0u);
  const auto second = db_.merge({shard_path});  // twice adds nothing, and says so
  EXPECT_EQ(second[0].derivative_models_added, 0u);
  EXPECT_EQ(second[0].derivative_models_already, 1u);
  const auto models = db_.derivative_models();
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(models[0].name, "from-shard");
  EXPECT_EQ(models[0].coefficients.size(), 2u);
  std::vector<std::int64_t> here;  // the runs of v = 0.2 and 0.3 in this database
  for (const auto& run : db_.runs())
    if (run.key.nu_b[1] > 0.15) here.push_back(run.id);
  EXPECT_EQ(models[0].run_ids, here);
  DerivativeModelRecord other = sample_model("from-shard");
  other.coefficients[0].value = -1.25;
  db_.save_derivative_model(other, RunDatabase::NameTaken::Replace);
  test::expect_input_error([&] { db_.merge({shard_path}); },
                           {"derivative model 'from-shard' is here already with other terms or coefficients"});
}

TEST_F(DerivativeStore, ADamagedValueIsRefusedNamingTheTableAndRow) {
  DerivativeModelRecord uneven = sample_model("u");
  uneven.covariance = {1.0, 2.0, 3.0};
  db_.save_derivative_model(uneven);
  test::expect_input_error([&] { db_.derivative_models(); },
                           {"table 'derivative_model', row", "2 coefficients and 3 covariance numbers"});
}

}  // namespace
}  // namespace hydrocoef
