// Surfaces built, stored and rebuilt through the library alone
// (src/pipeline/surface_build), their stored build specification
// (src/surface/surface_build_spec) and migration 7, which turns the command
// line's own strings that older databases kept into that specification.
#include "src/pipeline/surface_build.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "src/store/connection.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/older_database.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using nlohmann::json;
using test::expect_input_error;
using test::TempDir;

double surge(double u, double v) { return -0.3 - 2.0 * u - 10.0 * u * std::abs(u) + 4.0 * v * v; }

ImportBatch run_file(int id, double u, double v) {
  ImportedRun run;
  run.key.body = "boat";
  run.key.nu_b = {u, v, 0, 0, 0, 0};
  run.tau_b[0] = ForceComponent{surge(u, v), std::nullopt, std::nullopt};
  return test::one_run_batch(id, run);
}

// Runs on the grid u in {0, 0.1, 0.2, 0.3} x v in {-0.1, 0, 0.1}.
void fill(RunDatabase& database) {
  int id = 1;
  for (const double u : {0.0, 0.1, 0.2, 0.3})
    for (const double v : {-0.1, 0.0, 0.1}) database.import({run_file(id++, u, v)}, ImportPolicy{});
}

SurfaceBuildSpec grid_spec() {
  SurfaceBuildSpec spec;
  spec.surface.axes = {"u", "v"};
  spec.surface.outputs = {"X"};
  spec.surface.method = "linear";
  spec.surface.out_of_range = {"error", "clamp"};
  return spec;
}

TEST(SurfaceBuild, BuildsStoresAndAnswersAtTheRunsWithTheLibraryAlone) {
  TempDir dir;
  RunDatabase database(dir / "runs.db");
  fill(database);
  const auto result = build_and_store_surface(database, "surge", "boat", grid_spec());
  EXPECT_EQ(result.runs_measured, 12u);
  EXPECT_EQ(result.stored.record.run_ids.size(), 12u);
  const StoredSurface loaded = load_surface(database, "surge");
  std::vector<double> out(1);
  for (const double u : {0.0, 0.1, 0.2, 0.3})
    for (const double v : {-0.1, 0.0, 0.1}) {
      loaded.surface.evaluate(std::vector<double>{u, v}, out);
      EXPECT_NEAR(out[0], surge(u, v), 1e-12) << u << " " << v;
    }
  // Linear between the nodes, clamped in v as asked.
  loaded.surface.evaluate(std::vector<double>{0.05, 0.5}, out);
  EXPECT_NEAR(out[0], 0.5 * (surge(0.0, 0.1) + surge(0.1, 0.1)), 1e-12);
  // The name is taken: refused unless replacing.
  expect_input_error([&] { build_and_store_surface(database, "surge", "boat", grid_spec()); },
                     {"a surface named 'surge' exists", "--replace"});
  EXPECT_NO_THROW(build_and_store_surface(database, "surge", "boat", grid_spec(), RunDatabase::NameTaken::Replace));
}

TEST(SurfaceBuild, RebuildUsesTheStoredSpecificationOnTheCurrentRuns) {
  TempDir dir;
  RunDatabase database(dir / "runs.db");
  fill(database);
  SurfaceBuildSpec spec = grid_spec();
  spec.where = {"u<=0.2"};
  build_and_store_surface(database, "low", "boat", spec);
  EXPECT_EQ(built_from(database.surface("low")), "u<=0.2");
  // A run of the selection changes: the surface goes stale, the rebuild has the new value.
  ImportBatch changed = run_file(100, 0.1, 0.0);
  changed.runs[0].tau_b[0]->total = 7.0;
  ImportPolicy replace;
  replace.components = ConflictPolicy::Replace;
  database.import({changed}, replace);
  ASSERT_TRUE(database.surface("low").stale);
  const auto targets = surfaces_to_rebuild(database, std::nullopt, std::nullopt, true);
  ASSERT_EQ(targets.size(), 1u);
  const auto result = rebuild_surface(database, targets[0]);
  EXPECT_FALSE(result.stored.record.stale);
  EXPECT_EQ(result.stored.record.run_ids.size(), 9u);  // u <= 0.2 still
  std::vector<double> out(1);
  result.stored.surface.evaluate(std::vector<double>{0.1, 0.0}, out);
  EXPECT_EQ(out[0], 7.0);
  const SurfaceBuildSpec stored = stored_build_spec(result.stored.record);
  EXPECT_EQ(stored.where, spec.where);
  EXPECT_EQ(stored.surface.out_of_range, spec.surface.out_of_range);
}

TEST(SurfaceBuildSpec, StoredFormReadsBackAndDamagedFormsAreRefused) {
  SurfaceBuildSpec spec = grid_spec();
  spec.surface.method = "rbf";
  spec.surface.rbf.kernel = RbfKernel::ThinPlate;
  spec.surface.rbf.polynomial_degree = 2;
  spec.surface.rbf.smoothing = 0.125;
  spec.surface.resample = std::vector<std::vector<double>>{{0, 0.15, 0.3}, {-0.1, 0.1}};
  spec.surface.resample_method = "pchip";
  spec.surface.far_threshold = 0.4;
  spec.exclude_runs = {3, 9};
  spec.mirror_planes = {"v"};
  spec.mirror_odd = {"current_v"};
  const json stored = build_spec_json(spec);
  const SurfaceBuildSpec back = parse_build_spec(stored, "surface 's'");
  EXPECT_EQ(build_spec_json(back), stored);
  EXPECT_EQ(back.surface.rbf.kernel, RbfKernel::ThinPlate);
  EXPECT_EQ(*back.surface.resample, *spec.surface.resample);

  const auto damaged = [&](const std::function<void(json&)>& change, const std::vector<std::string>& expected) {
    json copy = stored;
    change(copy);
    expect_input_error([&] { parse_build_spec(copy, "surface 's'"); }, expected);
  };
  damaged([](json& j) { j["version"] = 2; }, {"surface 's'", "version 2", "expected 1"});
  damaged([](json& j) { j.erase("axes"); }, {"no 'axes'"});
  damaged([](json& j) { j["axes"] = json::array({1}); }, {"'axes'", "non-text"});
  damaged([](json& j) { j["out_of_range"] = json::array({"error"}); }, {"1 out-of-range policies for 2 axes"});
  damaged([](json& j) { j["rbf"]["degree"] = 7; }, {"RBF degree 7"});
  damaged([](json& j) { j["rbf"]["smoothing"] = -1; }, {"smoothing"});
  damaged([](json& j) { j["rbf"]["kernel"] = "gaussian"; }, {"gaussian"});
  damaged([](json& j) { j["resample"] = json::array({json::array({0.0})}); }, {"one list per axis"});
  damaged([](json& j) { j["resample"][0] = json::array({0.0}); }, {"2 to 100000"});
  damaged([](json& j) { j["exclude_runs"] = json::array({"x"}); }, {"expected run ids"});
  damaged([](json& j) { j["far_threshold"] = 0; }, {"threshold"});
  damaged([](json& j) { j["resample_method"] = "cubic-ish"; }, {"cubic-ish"});
}

// A database made before migration 7: its surface keeps the command line's
// strings. Made by storing the legacy definition and copying the rows into a
// database of schema version 6 (tests/support/older_database.hpp).
TEST(SurfaceBuildMigration, CommandLineOptionsBecomeTheBuildSpecification) {
  TempDir dir;
  const auto path = dir / "old.db";
  {
    RunDatabase database(path);
    fill(database);
    SurfaceBuildSpec spec = grid_spec();
    spec.surface.method = "rbf";
    spec.surface.out_of_range = {"clamp", "clamp"};
    build_and_store_surface(database, "rbf", "boat", spec);
  }
  const json legacy = {{"outputs", {"X"}},
                       {"axes", {"u", "v"}},
                       {"method", "rbf"},
                       {"extrapolate", {"extrapolate", "v=clamp"}},
                       {"where", {"u>=0.1"}},
                       {"exclude_runs", {4}},
                       {"kernel", "linear"},
                       {"degree", 0},
                       {"smoothing", 0.5},
                       {"resample", {"v=-0.1,0.1", "u=0:0.3:4"}},
                       {"resample_method", "pchip"},
                       {"far_threshold", 0.3},
                       {"mirror", {"v"}},
                       {"mirror_odd", json::array()}};
  {
    store::Connection connection(path.string(), store::Access::ReadWrite);
    auto read = connection.prepare("SELECT definition FROM surface WHERE name = 'rbf'");
    ASSERT_TRUE(read.step());
    json definition = json::parse(read.get_text(0));
    read.reset();
    definition.erase("build_spec");
    definition["build"] = legacy;
    connection.prepare("UPDATE surface SET definition = ? WHERE name = 'rbf'").bind(1, definition.dump()).run();
  }
  test::copy_as_schema_version(path, dir / "v6.db", 6);
  RunDatabase database(dir / "v6.db");
  const SurfaceBuildSpec spec = stored_build_spec(database.surface("rbf"));
  EXPECT_EQ(spec.surface.method, "rbf");
  EXPECT_EQ(spec.surface.out_of_range, (std::vector<std::string>{"extrapolate", "clamp"}));
  EXPECT_EQ(spec.where, std::vector<std::string>{"u>=0.1"});
  EXPECT_EQ(spec.exclude_runs, std::vector<std::int64_t>{4});
  EXPECT_EQ(spec.surface.rbf.kernel, RbfKernel::Linear);
  EXPECT_EQ(spec.surface.rbf.polynomial_degree, 0);
  EXPECT_EQ(spec.surface.rbf.smoothing, 0.5);
  ASSERT_TRUE(spec.surface.resample);
  EXPECT_EQ((*spec.surface.resample)[0], (std::vector<double>{0.0, 0.1, 0.2, 0.3}));
  EXPECT_EQ((*spec.surface.resample)[1], (std::vector<double>{-0.1, 0.1}));
  EXPECT_EQ(spec.surface.resample_method, "pchip");
  EXPECT_EQ(spec.mirror_planes, std::vector<std::string>{"v"});
  const json definition = json::parse(database.surface("rbf").definition);
  EXPECT_FALSE(definition.contains("build"));
  EXPECT_EQ(built_from(database.surface("rbf")), "u>=0.1 exclude-run 4, mirror v");
}

TEST(SurfaceBuildMigration, UnreadableOptionsStopTheMigrationAndLeaveTheDatabaseAsItWas) {
  TempDir dir;
  const auto path = dir / "old.db";
  {
    RunDatabase database(path);
    fill(database);
    build_and_store_surface(database, "surge", "boat", grid_spec());
  }
  {
    store::Connection connection(path.string(), store::Access::ReadWrite);
    connection.execute(
        "UPDATE surface SET definition = json_set(json_remove(definition, '$.build_spec'), '$.build', "
        "json('{\"axes\": [\"u\", \"v\"], \"resample\": [\"u=0:1\"]}'))");
  }
  const auto old = dir / "v6.db";
  test::copy_as_schema_version(path, old, 6);
  expect_input_error([&] { RunDatabase database(old); }, {"surface 'surge'", "build options are incomplete"});
  store::Connection connection(old.string(), store::Access::ReadOnly);
  auto version = connection.prepare("PRAGMA user_version");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.get_int(0), 6);
}

}  // namespace
}  // namespace hydrocoef
