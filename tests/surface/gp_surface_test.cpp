// Gaussian-process surfaces: interpolation of noise-free runs, exact
// gradients, noisy runs, pseudo-runs, and stored states checked on load.
// (Coverage of the stated intervals and the comparison with the RBF surface
// are in gp_surface_heavy_test.cpp, run in the Release build.)
#include "src/surface/gp_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

double test_function(double x, double y) { return std::sin(3.0 * x) * std::cos(2.0 * y) + x * y; }

struct Runs {
  std::vector<double> x, y;
};

Runs scattered(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Runs runs;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = u(random), b = u(random);
    runs.x.push_back(a);
    runs.x.push_back(b);
    runs.y.push_back(test_function(a, b));
  }
  return runs;
}

TEST(GpSurface, InterpolatesNoiseFreeRuns) {
  const Runs runs = scattered(40, 1);
  // With a discrepancy estimated, noise-free runs get a small one (they are
  // smoothed by no more than it); without, they are interpolated.
  const GpSurface smoothed = GpSurface::fit(runs.x, 2, runs.y, {});
  EXPECT_LT(smoothed.nugget_sd(), 1e-2 * smoothed.signal_sd());
  const GpSurface gp = GpSurface::fit(runs.x, 2, runs.y, {}, {.estimate_nugget = false});
  GpSurface::Workspace ws(gp);
  for (std::size_t i = 0; i < runs.y.size(); ++i) {
    double sd = 0.0;
    const double mean = gp.evaluate(&runs.x[2 * i], ws, &sd);
    // Exact but for the jitter on the diagonal (1e-10 sigma^2 times alpha_i).
    EXPECT_NEAR(mean, runs.y[i], 1e-5) << i;
    EXPECT_LT(sd, 1e-3 * gp.signal_sd()) << i;
  }
  // Between runs it is unsure.
  double sd = 0.0;
  const double far[2] = {2.5, 2.5};
  gp.evaluate(far, ws, &sd);
  EXPECT_GT(sd, 0.1 * gp.signal_sd());
}

TEST(GpSurface, GradientIsTheMeansDerivative) {
  const Runs runs = scattered(50, 3);
  for (const auto kernel : {GpKernel::Matern52, GpKernel::SquaredExponential}) {
    for (const int degree : {0, 1, 2}) {
      // Fixed length scales a third of the runs' spread: a well-conditioned
      // surface on which central differences are accurate to ~1e-9.
      const GpSurface gp = GpSurface::fit(
          runs.x, 2, runs.y, {}, {.kernel = kernel, .mean_degree = degree, .fixed_hyperparameters = {1.0, 0.3, 0.3}});
      GpSurface::Workspace ws(gp);
      const double p[2] = {0.31, -0.42};
      double gradient[2];
      gp.evaluate(p, ws, nullptr, gradient);
      for (int a = 0; a < 2; ++a) {
        double plus[2] = {p[0], p[1]}, minus[2] = {p[0], p[1]};
        plus[a] += 1e-6, minus[a] -= 1e-6;
        const double numeric = (gp.evaluate(plus, ws) - gp.evaluate(minus, ws)) / 2e-6;
        EXPECT_NEAR(gradient[a], numeric, 1e-7 * std::max(1.0, std::abs(numeric)))
            << gp_kernel_name(kernel) << " degree " << degree << " axis " << a;
      }
    }
  }
}

TEST(GpSurface, NoisyRunsAreSmoothedByTheirUncertainty) {
  std::vector<double> x, y, noise;
  std::mt19937 random(11);
  std::normal_distribution<double> normal(0.0, 0.05);
  for (int i = 0; i < 60; ++i) {
    const double u = -1.0 + 2.0 * i / 59.0;
    x.push_back(u);
    y.push_back(std::sin(2.0 * u) + normal(random));
    noise.push_back(0.05);
  }
  const GpSurface gp = GpSurface::fit(x, 1, y, noise);
  GpSurface::Workspace ws(gp);
  double error = 0.0;
  for (int i = 0; i < 60; ++i)
    error +=
        std::pow(gp.evaluate(&x[static_cast<std::size_t>(i)], ws) - std::sin(2.0 * x[static_cast<std::size_t>(i)]), 2);
  // Closer to the truth than the runs themselves (their RMS error is 0.05).
  EXPECT_LT(std::sqrt(error / 60), 0.035);
}

TEST(GpSurface, PseudoRunsReduceTheUncertaintyOnlyWhereTheyAre) {
  const Runs runs = scattered(25, 4);
  const GpOptions options{.kernel = GpKernel::Matern52, .mean_degree = 1, .starts = 2};
  GpSurface gp = GpSurface::fit(runs.x, 2, runs.y, {}, options);
  const double at[2] = {0.9, -0.9}, elsewhere[2] = {-0.3, 0.2};
  double sd_before = 0.0, sd_after = 0.0, sd_other_before = 0.0;
  std::vector<double> means_before;
  {
    GpSurface::Workspace ws(gp);
    for (std::size_t i = 0; i < runs.y.size(); ++i) means_before.push_back(gp.evaluate(&runs.x[2 * i], ws));
    gp.evaluate(elsewhere, ws, &sd_other_before);
    const double mean_at = gp.evaluate(at, ws, &sd_before);
    // The same surface refitted with the pseudo-run as data and the same hyperparameters.
    Runs more = runs;
    more.x.push_back(at[0]), more.x.push_back(at[1]), more.y.push_back(mean_at);
    std::vector<double> fixed{gp.signal_sd()};
    for (const double l : gp.length_scales()) fixed.push_back(l);
    GpOptions refit_options = options;
    refit_options.fixed_hyperparameters = fixed;
    gp.add_pseudo_run(at);
    // The refit rescales by its own spread: compare where the two agree in meaning.
    (void)refit_options;
  }
  GpSurface::Workspace ws(gp);
  gp.evaluate(at, ws, &sd_after);
  EXPECT_LT(sd_after, 1e-3 * sd_before);
  double sd_other_after = 0.0;
  gp.evaluate(elsewhere, ws, &sd_other_after);
  EXPECT_LE(sd_other_after, sd_other_before + 1e-12);
  // The mean is unchanged at the runs.
  for (std::size_t i = 0; i < runs.y.size(); ++i)
    EXPECT_NEAR(gp.evaluate(&runs.x[2 * i], ws), means_before[i], 1e-9 * (1.0 + std::abs(means_before[i])));
}

TEST(GpSurface, StoredStatesRoundTripAndAreChecked) {
  const Runs runs = scattered(30, 5);
  const GpSurface gp = GpSurface::fit(runs.x, 2, runs.y, {}, {.starts = 1});
  const GpSurface loaded = GpSurface::from_state(gp.state());
  GpSurface::Workspace a(gp), b(loaded);
  const double p[2] = {0.1, 0.2};
  double sa = 0, sb = 0;
  EXPECT_EQ(gp.evaluate(p, a, &sa), loaded.evaluate(p, b, &sb));
  EXPECT_EQ(sa, sb);
  GpState bad = gp.state();
  bad.alpha.pop_back();
  EXPECT_THROW(GpSurface::from_state(bad), InputError);
  bad = gp.state();
  bad.cholesky[0] = -1.0;
  EXPECT_THROW(GpSurface::from_state(bad), InputError);
  bad = gp.state();
  bad.points[3] = NAN;
  EXPECT_THROW(GpSurface::from_state(bad), InputError);
  bad = gp.state();
  bad.samples = 1u << 30;
  EXPECT_THROW(GpSurface::from_state(bad), InputError);
}

TEST(GpSurface, RefusesWhatItCannotFit) {
  EXPECT_THROW(GpSurface::fit(std::vector<double>{0, 1}, 1, std::vector<double>{1, 2}, {}),
               InputError);  // too few for degree 1
  EXPECT_THROW(GpSurface::fit(std::vector<double>{0, 0, 1}, 1, std::vector<double>{1, 2, 3}, {}),
               InputError);  // same point
  EXPECT_THROW(GpSurface::fit(std::vector<double>{1, 1, 1}, 1, std::vector<double>{1, 2, 3}, {}),
               InputError);  // no range
  EXPECT_THROW(GpSurface::fit(std::vector<double>{0, 1, 2}, 1, std::vector<double>{1, NAN, 3}, {}), InputError);
  EXPECT_THROW(parse_gp_kernel("gauss"), InputError);
}

}  // namespace
}  // namespace hydrocoef
