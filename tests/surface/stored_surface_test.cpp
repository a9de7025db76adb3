// Surfaces through the database: what is stored is what comes back, for grids
// and RBFs, and a damaged definition is refused naming the surface.
#include "src/surface/stored_surface.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "src/surface/surface_builder.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;
using test::TempDir;

/// A database with one body "sphere" and one run in it.
std::vector<StoredRun> seed(RunDatabase& db) {
  ImportBatch batch;
  batch.source = {"seed.csv", std::string(64, 'a'), 1, "test", "1"};
  ImportedRun run;
  run.key.body = "sphere";
  run.tau_b[0] = ForceComponent{-1.0, {}, {}};
  batch.runs.push_back(run);
  db.import({batch}, ConflictPolicy::Error);
  return db.runs();
}

CoefficientSurface makima_table() {
  std::vector<GridAxis> axes{{"u", {0.0, 0.2, 0.5, 0.9}, Extrapolation::Linear},
                             {"r", {-0.3, 0.0, 0.3}, Extrapolation::Clamp}};
  std::vector<double> values;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 2; ++k) values.push_back(std::sin(1.0 + i * 0.7 + j * 0.3 + k));
  return CoefficientSurface(GridTable(axes, {"X", "N"}, values, Interpolation::Akima));
}

TEST(StoredSurface, GridComesBackIdenticalFromTheDatabase) {
  TempDir dir;
  RunDatabase db(dir / "runs.db");
  const auto runs = seed(db);
  const CoefficientSurface surface = makima_table();
  SurfaceRecord record = record_from_surface(surface);
  record.name = "xn";
  record.body = "sphere";
  record.run_ids = {runs[0].id};
  db.save_surface(record);

  const StoredSurface stored = load_surface(db, "xn");
  EXPECT_EQ(stored.record.kind, "grid");
  EXPECT_EQ(stored.record.method, "makima");
  EXPECT_EQ(stored.surface.axis_names(), surface.axis_names());
  EXPECT_EQ(stored.surface.output_units(), (std::vector<std::string>{"N", "N m"}));
  EXPECT_EQ(stored.surface.out_of_range_name(0), "linear");
  EXPECT_EQ(stored.surface.out_of_range_name(1), "clamp");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> du(-0.2, 1.1), dr(-0.5, 0.5);
  double a[2], b[2];
  for (int i = 0; i < 200; ++i) {
    const double p[2] = {du(rng), dr(rng)};
    surface.evaluate(p, a);
    stored.surface.evaluate(p, b);
    EXPECT_EQ(a[0], b[0]);
    EXPECT_EQ(a[1], b[1]);
  }
}

TEST(StoredSurface, RbfIsRefactorizedFromItsSamples) {
  TempDir dir;
  RunDatabase db(dir / "runs.db");
  seed(db);
  std::vector<double> points, values;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  for (int i = 0; i < 25; ++i) {
    const double u = d(rng), v = d(rng);
    points.insert(points.end(), {u, v});
    values.push_back(std::cos(2 * u) * v);
  }
  RbfOptions options;
  options.kernel = RbfKernel::ThinPlate;
  options.smoothing = 1e-6;
  options.out_of_range = {RbfOutOfRange::Clamp, RbfOutOfRange::Extrapolate};
  const CoefficientSurface surface(RbfSurface(2, points, 1, values, options), {"u", "v"}, {"Y"});
  SurfaceRecord record = record_from_surface(surface, points, values);
  record.name = "y-rbf";
  record.body = "sphere";
  db.save_surface(record);
  const StoredSurface stored = load_surface(db, "y-rbf");
  ASSERT_NE(stored.surface.rbf(), nullptr);
  EXPECT_EQ(stored.surface.rbf()->kernel(), RbfKernel::ThinPlate);
  EXPECT_EQ(stored.surface.out_of_range_name(0), "clamp");
  EXPECT_EQ(stored.surface.out_of_range_name(1), "extrapolate");
  for (int i = 0; i < 100; ++i) {
    const double p[2] = {1.4 * d(rng) - 0.2, 1.4 * d(rng) - 0.2};
    double a = 0, b = 0;
    surface.evaluate(p, std::span<double>(&a, 1));
    stored.surface.evaluate(p, std::span<double>(&b, 1));
    EXPECT_NEAR(a, b, 1e-12);
  }
}

TEST(StoredSurface, DamagedDefinitionsAreRefusedNamingTheSurface) {
  SurfaceRecord record = record_from_surface(makima_table());
  record.name = "xn";
  SurfaceRecord bad = record;
  bad.definition = "{not json";
  expect_input_error([&] { surface_from_record(bad); }, {"surface 'xn'", "not JSON"});
  bad = record;
  bad.definition = R"({"axes": [{"name": "u"}], "outputs": [{"name": "X"}]})";
  expect_input_error([&] { surface_from_record(bad); }, {"surface 'xn'", "'unit'"});
  bad = record;
  bad.data.pop_back();
  expect_input_error([&] { surface_from_record(bad); }, {"surface 'xn'"});
  bad = record;
  bad.kind = "spline";
  expect_input_error([&] { surface_from_record(bad); }, {"surface 'xn'", "grid, rbf or gp"});
}

TEST(StoredSurface, AMissingSurfaceIsNamed) {
  TempDir dir;
  RunDatabase db(dir / "runs.db");
  expect_input_error([&] { load_surface(db, "nope"); }, {"nope"});
}

/// Runs on a 4 x 3 grid of (u, current_v) with X and its stated uncertainty.
std::vector<StoredRun> runs_with_sigma() {
  std::vector<StoredRun> runs;
  std::int64_t id = 1;
  for (double v : {0.0, 0.1, 0.3})
    for (double u : {0.1, 0.2, 0.4, 0.8}) {
      StoredRun run;
      run.id = id++;
      run.key.body = "sphere";
      run.key.nu_b[0] = u;
      run.key.disturbances["current_v"] = v;
      run.tau_b[0] = StoredForce{
          {std::sin(3 * u) + v * u, {}, {}, 0.01 + 0.1 * u * (1 + v)}, SignConvention::OnBody, 1, "f.csv", 0};
      runs.push_back(run);
    }
  return runs;
}

void expect_same_sd(const CoefficientSurface& a, const CoefficientSurface& b, double tolerance) {
  ASSERT_TRUE(b.has_standard_deviation());
  EXPECT_EQ(a.loo_standard_deviation(), b.loo_standard_deviation());
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> du(0.1, 0.8), dv(0.0, 0.3);
  for (int i = 0; i < 100; ++i) {
    const double p[2] = {du(rng), dv(rng)};
    double va = 0, vb = 0, sa = 0, sb = 0;
    a.evaluate_with_standard_deviation(p, std::span<double>(&va, 1), std::span<double>(&sa, 1));
    b.evaluate_with_standard_deviation(p, std::span<double>(&vb, 1), std::span<double>(&sb, 1));
    EXPECT_NEAR(va, vb, tolerance);
    EXPECT_NEAR(sa, sb, tolerance);
    EXPECT_GT(sb, 0.0);
  }
}

TEST(StoredSurface, GridAndRbfUncertaintyComeBackFromTheDatabase) {
  TempDir dir;
  RunDatabase db(dir / "runs.db");
  seed(db);
  for (const std::string method : {"pchip", "rbf"}) {
    const BuiltSurface built = build_surface(runs_with_sigma(), {{"u", "current_v"}, {"X"}, method});
    ASSERT_TRUE(built.surface.has_standard_deviation()) << method;
    SurfaceRecord record = built.record("s-" + method, "sphere");
    record.run_ids.clear();
    db.save_surface(record);
    const StoredSurface stored = load_surface(db, "s-" + method);
    expect_same_sd(built.surface, stored.surface, method == "rbf" ? 1e-12 : 0.0);
    EXPECT_EQ(stored.surface.run_uncertainty_rbf() != nullptr, method == "rbf");
  }
}

TEST(StoredSurface, ASurfaceStoredWithoutUncertaintyStatesNone) {
  // As an older hydrocoef stored it: no "uncertainty" in the definition.
  const CoefficientSurface plain = makima_table();
  ASSERT_FALSE(plain.has_standard_deviation());
  SurfaceRecord record = record_from_surface(plain);
  record.name = "old";
  EXPECT_EQ(record.definition.find("uncertainty"), std::string::npos);
  const CoefficientSurface loaded = surface_from_record(record);
  EXPECT_FALSE(loaded.has_standard_deviation());
  const double p[2] = {0.3, 0.1};
  double out[2], sd[2];
  expect_input_error([&] { loaded.evaluate_with_standard_deviation(p, out, sd); },
                     {"no standard deviation", "surface rebuild"});
}

TEST(StoredSurface, DamagedUncertaintyIsRefusedNamingTheSurface) {
  const BuiltSurface built = build_surface(runs_with_sigma(), {{"u", "current_v"}, {"X"}, "linear"});
  SurfaceRecord record = built.record("xs", "sphere");
  auto definition = nlohmann::json::parse(record.definition);
  ASSERT_TRUE(definition.contains("uncertainty"));
  auto bad_definition = definition;
  bad_definition["uncertainty"]["run_sd"].erase(0);
  SurfaceRecord bad = record;
  bad.definition = bad_definition.dump();
  expect_input_error([&] { surface_from_record(bad); }, {"surface 'xs'", "run_sd", "expected 12"});
  bad_definition = definition;
  bad_definition["uncertainty"]["loo_sd"][0] = -1.0;
  bad.definition = bad_definition.dump();
  expect_input_error([&] { surface_from_record(bad); }, {"surface 'xs'", "loo_sd", ">= 0"});
}

}  // namespace
}  // namespace hydrocoef
