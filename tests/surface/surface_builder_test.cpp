// Surfaces built from runs: grids found in the runs' keys, signs made
// on-body, leave-one-out figures checked against hand-computed values, RBF for
// scattered runs and its resampling, and every refusal named.
#include "src/surface/surface_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "src/core/error.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

StoredRun make_run(std::int64_t id, double u, double current_v, std::optional<double> x, std::optional<double> n = {},
                   SignConvention sign = SignConvention::OnBody) {
  StoredRun run;
  run.id = id;
  run.key.body = "sphere";
  run.key.nu_b[0] = u;
  run.key.disturbances["current_v"] = current_v;
  if (x) run.tau_b[0] = StoredForce{{*x, {}, {}}, sign, 1, "f.csv", 0};
  if (n) run.tau_b[5] = StoredForce{{*n, {}, {}}, sign, 1, "f.csv", 0};
  return run;
}

double bilinear(double u, double v) { return 1.5 - 2.0 * u + 0.75 * v + 3.0 * u * v; }

std::vector<StoredRun> grid_runs(double (*f)(double, double)) {
  std::vector<StoredRun> runs;
  std::int64_t id = 1;
  for (double v : {0.0, 0.05, 0.1})
    for (double u : {0.1, 0.2, 0.4, 0.8}) runs.push_back(make_run(id++, u, v, f(u, v), -f(u, v)));
  return runs;
}

TEST(SurfaceBuilder, GridFromRunsReproducesAMultilinearForceOffTheGrid) {
  SurfaceSpec spec{{"u", "current_v"}, {"X", "N"}, "linear"};
  const BuiltSurface built = build_surface(grid_runs(bilinear), spec);
  ASSERT_EQ(built.surface.kind(), CoefficientSurface::Kind::Grid);
  EXPECT_EQ(built.surface.grid()->axes()[0].breakpoints, (std::vector<double>{0.1, 0.2, 0.4, 0.8}));
  EXPECT_EQ(built.surface.grid()->axes()[1].breakpoints, (std::vector<double>{0.0, 0.05, 0.1}));
  EXPECT_EQ(built.run_ids.size(), 12u);
  EXPECT_EQ(built.surface.axis_units(), (std::vector<std::string>{"m/s", ""}));
  EXPECT_EQ(built.surface.output_units(), (std::vector<std::string>{"N", "N m"}));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> du(0.1, 0.8), dv(0.0, 0.1);
  double out[2];
  for (int i = 0; i < 100; ++i) {
    const double p[2] = {du(rng), dv(rng)};
    built.surface.evaluate(p, out);
    EXPECT_NEAR(out[0], bilinear(p[0], p[1]), 1e-12);
    EXPECT_NEAR(out[1], -bilinear(p[0], p[1]), 1e-12);
  }
  // A multilinear field is linear along every grid line, so each node is
  // predicted exactly from its lines: the leave-one-out error vanishes.
  EXPECT_EQ(built.quality.method, "grid-lines");
  EXPECT_EQ(built.quality.loo_defined, 12u);
  EXPECT_LT(built.quality.loo_max[0], 1e-12);
  EXPECT_LT(built.quality.loo_max[1], 1e-12);
}

TEST(SurfaceBuilder, GridLineLeaveOneOutMatchesTheHandComputedErrors) {
  // X = u^2 at u = 0, 1, 2, linear: the middle node is predicted as the mean
  // of its neighbours (2, error -1); each end by the straight line through the
  // other two (-2 at u = 0 and 2 at u = 2, errors +2 and +2).
  std::vector<StoredRun> runs{make_run(1, 0.0, 0.0, 0.0), make_run(2, 1.0, 0.0, 1.0), make_run(3, 2.0, 0.0, 4.0)};
  const BuiltSurface built = build_surface(runs, {{"u"}, {"X"}, "linear"});
  EXPECT_NEAR(built.quality.loo_max[0], 2.0, 1e-14);
  EXPECT_NEAR(built.quality.loo_rms[0], std::sqrt(3.0), 1e-14);
  EXPECT_EQ(built.quality.loo_defined, 3u);
}

TEST(SurfaceBuilder, DampingMagnitudesBecomeForcesOnTheBody) {
  std::vector<StoredRun> runs{make_run(1, 0.1, 0, 0.11, {}, SignConvention::OpposingMotion),
                              make_run(2, 0.2, 0, 0.44, {}, SignConvention::OpposingMotion)};
  const BuiltSurface built = build_surface(runs, {{"u"}, {"X"}, "linear"});
  EXPECT_EQ(built.surface.grid()->values(), (std::vector<double>{-0.11, -0.44}));
}

TEST(SurfaceBuilder, RunsWithoutAnOutputAreSkippedAndCounted) {
  auto runs = grid_runs(bilinear);
  runs.push_back(make_run(99, 0.3, 0.0, {}, 1.0));  // has N only
  const BuiltSurface built = build_surface(runs, {{"u", "current_v"}, {"X"}, "pchip"});
  EXPECT_EQ(built.runs_skipped, 1u);
  EXPECT_EQ(built.run_ids.size(), 12u);
}

TEST(SurfaceBuilder, AGapInTheGridIsRefusedNamingTheMissingPoint) {
  auto runs = grid_runs(bilinear);
  runs.erase(runs.begin() + 5);  // u = 0.2, current_v = 0.05
  expect_input_error(
      [&] {
        build_surface(runs, {{"u", "current_v"}, {"X"}, "linear"});
      },
      {"do not fill a grid", "u=0.2 current_v=0.05", "--method rbf"});
}

TEST(SurfaceBuilder, TwoRunsAtOnePointAreRefusedNamingBoth) {
  std::vector<StoredRun> runs{make_run(7, 0.1, 0.0, 1.0), make_run(8, 0.2, 0.0, 2.0), make_run(9, 0.2, 0.05, 2.5)};
  expect_input_error([&] { build_surface(runs, {{"u"}, {"X"}, "linear"}); }, {"run 8", "run 9", "--where"});
}

TEST(SurfaceBuilder, UnknownNamesAreRefused) {
  const auto runs = grid_runs(bilinear);
  expect_input_error([&] { build_surface(runs, {{"u"}, {"F"}, "linear"}); }, {"output 'F'", "X, Y, Z, K, M or N"});
  expect_input_error(
      [&] {
        build_surface(runs, {{"u", "current_w"}, {"X"}, "linear"});
      },
      {"no disturbance 'current_w'"});
  expect_input_error([&] { build_surface(runs, {{"u", "u"}, {"X"}, "linear"}); }, {"axis 'u' is given twice"});
  expect_input_error([&] { build_surface(runs, {{"u", "current_v"}, {"X"}, "cubic"}); }, {"cubic"});
}

TEST(SurfaceBuilder, ScatteredRunsGiveAnRbfThatReproducesALinearForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> du(0.0, 1.0), dv(-0.2, 0.2);
  const auto f = [](double u, double v) { return 0.5 - 3.0 * u + 2.0 * v; };
  std::vector<StoredRun> runs;
  for (int i = 0; i < 30; ++i) {
    const double u = du(rng), v = dv(rng);
    runs.push_back(make_run(i + 1, u, v, f(u, v)));
  }
  SurfaceSpec spec{{"u", "current_v"}, {"X"}, "rbf"};
  spec.rbf.polynomial_degree = 1;
  const BuiltSurface built = build_surface(runs, spec);
  ASSERT_EQ(built.surface.kind(), CoefficientSurface::Kind::Rbf);
  EXPECT_EQ(built.quality.method, "rbf-exact");
  EXPECT_EQ(built.rbf_points.size(), 60u);
  // Degree-1 polynomial: a linear field is reproduced, with and without each run.
  EXPECT_LT(built.quality.loo_max[0], 1e-9);
  double out = 0.0;
  const double p[2] = {0.5, 0.0};
  built.surface.evaluate(p, std::span<double>(&out, 1));
  EXPECT_NEAR(out, f(0.5, 0.0), 1e-10);
}

TEST(SurfaceBuilder, ResampledRbfIsAGridAndReportsPointsFarFromRuns) {
  // Runs only in the lower-left quarter of the unit square (scaled range is
  // that quarter); the resampling grid reaches far beyond it.
  std::vector<StoredRun> runs;
  std::int64_t id = 1;
  for (double u : {0.0, 0.1, 0.2, 0.3})
    for (double v : {0.0, 0.1, 0.2}) runs.push_back(make_run(id++, u, v, 1.0 + u - v));
  SurfaceSpec spec{{"u", "current_v"}, {"X"}, "rbf", {"extrapolate"}};
  spec.resample = std::vector<std::vector<double>>{{0.0, 0.3, 0.6, 0.9}, {0.0, 0.2}};
  spec.resample_method = "linear";
  spec.far_threshold = 0.5;
  const BuiltSurface built = build_surface(runs, spec);
  ASSERT_EQ(built.surface.kind(), CoefficientSurface::Kind::Grid);
  EXPECT_EQ(built.quality.grid_points, 8u);
  // Scaled distances: u is divided by 0.3, so u = 0.6 is 1.0 and u = 0.9 is
  // 2.0 scaled units from the nearest run (u = 0.3): 4 grid points.
  EXPECT_EQ(built.quality.far_from_data, (std::vector<std::size_t>{2, 3, 6, 7}));
  double out = 0.0;
  const double p[2] = {0.15, 0.1};
  built.surface.evaluate(p, std::span<double>(&out, 1));
  EXPECT_NEAR(out, 1.0 + 0.15 - 0.1, 1e-10);
}

}  // namespace
}  // namespace hydrocoef
