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

// --- Stated uncertainty of grid and RBF surfaces ---------------------------
// sd_k(x)^2 = (sum_i a_i(x) sigma_ik)^2 + loo_rms_k^2 with a_i(x) the
// surface's own interpolation weights (CoefficientSurface::with_run_uncertainty).

/// Run `id` at (u, current_v) with X = x, stating a standard uncertainty
/// sigma: given at import, or as a history's standard error and a given
/// part in quadrature when both are > 0.
StoredRun run_with_sigma(std::int64_t id, double u, double v, double x, double sigma, double standard_error = 0.0) {
  StoredRun run = make_run(id, u, v, x);
  run.tau_b[0]->value.uncertainty = sigma;
  if (standard_error > 0.0) {
    StoredStatistics statistics;
    statistics.values.standard_error = standard_error;
    run.tau_b[0]->statistics = statistics;
  }
  return run;
}

double sd_at(const CoefficientSurface& surface, double u, double v) {
  const double p[2] = {u, v};
  double value = 0.0, sd = 0.0;
  surface.evaluate_with_standard_deviation(p, std::span<double>(&value, 1), std::span<double>(&sd, 1));
  return sd;
}

TEST(SurfaceUncertainty, LinearGridStatesTheBilinearlyInterpolatedRunSigmaWhereLeaveOneOutVanishes) {
  // A bilinear X on a 3 x 3 grid: every node is predicted exactly from its
  // grid lines (LOO 0), so the stated sd is the runs' part alone.
  const double us[3] = {0.0, 1.0, 2.0}, vs[3] = {0.0, 0.5, 1.0};
  std::vector<StoredRun> runs;
  std::int64_t id = 1;
  const auto sigma_of = [](int i, int j) { return 0.01 * (1 + i + 3 * j); };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      runs.push_back(run_with_sigma(id++, us[i], vs[j], bilinear(us[i], vs[j]), sigma_of(i, j)));
  const BuiltSurface built = build_surface(runs, {{"u", "current_v"}, {"X"}, "linear"});
  ASSERT_TRUE(built.surface.has_standard_deviation());
  ASSERT_LT(built.quality.loo_max[0], 1e-12);
  EXPECT_EQ(built.surface.loo_standard_deviation()[0], built.quality.loo_rms[0]);
  // At a node: that run's own sigma.
  EXPECT_NEAR(sd_at(built.surface, 1.0, 0.5), sigma_of(1, 1), 1e-15);
  EXPECT_NEAR(sd_at(built.surface, 2.0, 1.0), sigma_of(2, 2), 1e-15);
  // In the cell [1, 2] x [0.5, 1] at (1.25, 0.6): bilinear weights
  // tu = 0.25, tv = 0.2 of the four corners, applied to their sigmas.
  const double tu = 0.25, tv = 0.2;
  const double expected = (1 - tu) * (1 - tv) * sigma_of(1, 1) + tu * (1 - tv) * sigma_of(2, 1) +
                          (1 - tu) * tv * sigma_of(1, 2) + tu * tv * sigma_of(2, 2);
  EXPECT_NEAR(sd_at(built.surface, 1.25, 0.6), std::hypot(expected, built.quality.loo_rms[0]), 1e-14);
  // ... which is more than independent errors would give (all weights >= 0).
  const double independent =
      std::sqrt(std::pow((1 - tu) * (1 - tv) * sigma_of(1, 1), 2) + std::pow(tu * (1 - tv) * sigma_of(2, 1), 2) +
                std::pow((1 - tu) * tv * sigma_of(1, 2), 2) + std::pow(tu * tv * sigma_of(2, 2), 2));
  EXPECT_GT(sd_at(built.surface, 1.25, 0.6), independent * 1.2);
}

TEST(SurfaceUncertainty, GridAddsTheLeaveOneOutRmsInQuadrature) {
  // X = u^2 at u = 0, 1, 2, linear: LOO RMS sqrt(3) (hand-computed above).
  std::vector<StoredRun> runs{run_with_sigma(1, 0.0, 0.0, 0.0, 0.1), run_with_sigma(2, 1.0, 0.0, 1.0, 0.2),
                              run_with_sigma(3, 2.0, 0.0, 4.0, 0.4, 0.3)};
  const BuiltSurface built = build_surface(runs, {{"u"}, {"X"}, "linear"});
  ASSERT_TRUE(built.surface.has_standard_deviation());
  const auto sd1 = [&](double u) {
    double value = 0.0, sd = 0.0;
    built.surface.evaluate_with_standard_deviation(std::span<const double>(&u, 1), std::span<double>(&value, 1),
                                                   std::span<double>(&sd, 1));
    EXPECT_NEAR(value, u <= 1.0 ? u : 1.0 + 3.0 * (u - 1.0), 1e-14);
    return sd;
  };
  EXPECT_NEAR(sd1(0.5), std::sqrt(0.15 * 0.15 + 3.0), 1e-14);
  EXPECT_NEAR(sd1(1.0), std::sqrt(0.2 * 0.2 + 3.0), 1e-14);
  // Run 3's sigma is its standard error 0.3 and the given 0.4 in quadrature: 0.5.
  EXPECT_NEAR(sd1(2.0), std::sqrt(0.5 * 0.5 + 3.0), 1e-14);
  EXPECT_NEAR(sd1(1.5), std::sqrt(0.35 * 0.35 + 3.0), 1e-14);
  // The gradient comes with it, as evaluate_with_gradient's.
  const double u = 1.5;
  double value = 0.0, sd = 0.0, gradient = 0.0;
  built.surface.evaluate_with_standard_deviation(std::span<const double>(&u, 1), std::span<double>(&value, 1),
                                                 std::span<double>(&sd, 1), std::span<double>(&gradient, 1));
  EXPECT_NEAR(gradient, 3.0, 1e-14);
}

TEST(SurfaceUncertainty, OutsideTheRangeTheRunsPartIsTheNearestEdgeOne) {
  std::vector<StoredRun> runs{run_with_sigma(1, 0.0, 0.0, 0.0, 0.1), run_with_sigma(2, 1.0, 0.0, 1.0, 0.2),
                              run_with_sigma(3, 2.0, 0.0, 4.0, 0.4)};
  SurfaceSpec spec{{"u"}, {"X"}, "linear", {"linear"}};
  const BuiltSurface built = build_surface(runs, spec);
  const double u = 3.0;
  double value = 0.0, sd = 0.0;
  built.surface.evaluate_with_standard_deviation(std::span<const double>(&u, 1), std::span<double>(&value, 1),
                                                 std::span<double>(&sd, 1));
  EXPECT_NEAR(value, 7.0, 1e-14);  // extrapolated linearly
  EXPECT_NEAR(sd, std::sqrt(0.4 * 0.4 + 3.0), 1e-14);
}

TEST(SurfaceUncertainty, AGridWithoutLeaveOneOutStatesNone) {
  // Two breakpoints per axis: no node has a grid line of 3, no LOO error.
  std::vector<StoredRun> runs;
  std::int64_t id = 1;
  for (double v : {0.0, 1.0})
    for (double u : {0.0, 1.0}) runs.push_back(run_with_sigma(id++, u, v, u + v, 0.1));
  const BuiltSurface built = build_surface(runs, {{"u", "current_v"}, {"X"}, "linear"});
  EXPECT_EQ(built.quality.loo_defined, 0u);
  EXPECT_FALSE(built.surface.has_standard_deviation());
  expect_input_error([&] { sd_at(built.surface, 0.5, 0.5); }, {"no standard deviation", "linear"});
}

TEST(SurfaceUncertainty, RbfStatesItsRunsSigmaAtTheRunsAndTheirInterpolantBetween) {
  std::vector<StoredRun> runs;
  std::vector<double> sigma;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  for (int i = 0; i < 20; ++i) {
    const double u = d(rng), v = d(rng);
    sigma.push_back(0.05 + 0.1 * d(rng));
    runs.push_back(run_with_sigma(i + 1, u, v, std::sin(3 * u) + v * v, sigma.back()));
  }
  SurfaceSpec spec{{"u", "current_v"}, {"X"}, "rbf"};
  const BuiltSurface built = build_surface(runs, spec);
  ASSERT_TRUE(built.surface.has_standard_deviation());
  ASSERT_NE(built.surface.run_uncertainty_rbf(), nullptr);
  const double loo = built.quality.loo_rms[0];
  ASSERT_GT(loo, 0.0);
  // An interpolating RBF reproduces its data: at a run, that run's sigma.
  for (std::size_t i = 0; i < runs.size(); ++i)
    EXPECT_NEAR(sd_at(built.surface, runs[i].key.nu_b[0], runs[i].key.disturbances.at("current_v")),
                std::hypot(sigma[i], loo), 1e-9);
  // Between runs: the same RBF through the sigmas (same kernel, polynomial, scaling).
  RbfOptions options;
  options.out_of_range = {RbfOutOfRange::Clamp, RbfOutOfRange::Clamp};
  const RbfSurface through_sigma(2, built.rbf_points, 1, sigma, options);
  for (int i = 0; i < 50; ++i) {
    const double p[2] = {0.2 + 0.6 * d(rng), 0.2 + 0.6 * d(rng)};
    double s = 0.0;
    through_sigma.evaluate(p, std::span<double>(&s, 1));
    EXPECT_NEAR(sd_at(built.surface, p[0], p[1]), std::hypot(std::max(0.0, s), loo), 1e-12);
  }
}

TEST(SurfaceUncertainty, EqualRunSigmasGiveThatSigmaEverywhereOnAnRbfAndItsResampledGrid) {
  // The polynomial part reproduces constants: equal sigmas c interpolate to c.
  std::vector<StoredRun> runs;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  for (int i = 0; i < 16; ++i) {
    const double u = d(rng), v = d(rng);
    runs.push_back(run_with_sigma(i + 1, u, v, std::exp(u) - v, 0.07));
  }
  SurfaceSpec spec{{"u", "current_v"}, {"X"}, "rbf", {"clamp"}};
  const BuiltSurface rbf = build_surface(runs, spec);
  const double loo = rbf.quality.loo_rms[0];
  for (int i = 0; i < 30; ++i) EXPECT_NEAR(sd_at(rbf.surface, d(rng), d(rng)), std::hypot(0.07, loo), 1e-10);
  spec.resample = std::vector<std::vector<double>>{{0.2, 0.5, 0.8}, {0.3, 0.7}};
  const BuiltSurface grid = build_surface(runs, spec);
  ASSERT_EQ(grid.surface.kind(), CoefficientSurface::Kind::Grid);
  ASSERT_TRUE(grid.surface.has_standard_deviation());
  EXPECT_NEAR(sd_at(grid.surface, 0.35, 0.5), std::hypot(0.07, loo), 1e-10);
}

}  // namespace
}  // namespace hydrocoef
