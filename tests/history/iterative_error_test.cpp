// The iterative error of a converged steady run's final iterate
// (src/history/iterative_error): on sequences whose limit is known exactly
// (geometric convergence x_n = x_inf + A lambda^n, with and without a small
// limit cycle), the stated uncertainty covers the true distance to the limit
// and errs on the safe side by no more than the slope's lag says; the rate
// from the series' own changes when no residuals are known; the decay rate
// of a residual history.
#include "src/history/iterative_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace hydrocoef {
namespace {

std::vector<double> geometric(double limit, double amplitude, double rate, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = limit + amplitude * std::pow(rate, static_cast<double>(i));
  return x;
}

TEST(IterativeError, GeometricConvergenceIsCoveredAndNotOverstatedMuch) {
  for (const double rate : {0.8, 0.9, 0.97, 0.99}) {
    for (const std::size_t n : {40u, 150u, 1000u}) {
      if (std::pow(rate, static_cast<double>(n)) < 1e-8) continue;  // converged to round-off: nothing to see
      const auto x = geometric(2.0, -0.3, rate, n);
      const IterativeError e = iterative_error(x, rate);
      const double truth = std::abs(x.back() - 2.0);
      EXPECT_EQ(e.value, x.back());
      EXPECT_TRUE(e.rate_from_residuals);
      EXPECT_DOUBLE_EQ(e.rate, rate);
      // The slope over the tail is the change about tail/2 iterations back.
      const double lag = std::pow(rate, -(static_cast<double>(e.tail) - 1.0) / 2.0);
      EXPECT_GE(e.standard_uncertainty, truth * (1.0 - 1e-9)) << rate << " " << n;
      EXPECT_LE(e.standard_uncertainty, truth * lag * 1.25) << rate << " " << n;
      EXPECT_LT(e.fluctuation, 0.05 * e.extrapolated_error + 1e-15);
    }
  }
}

TEST(IterativeError, TheRateComesFromTheSeriesWhenNoResidualsAreKnown) {
  const auto x = geometric(-1.0, 0.5, 0.95, 300);
  const IterativeError e = iterative_error(x, std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(e.rate_from_residuals);
  EXPECT_NEAR(e.rate, 0.95, 1e-9);
  EXPECT_GE(e.standard_uncertainty, std::abs(x.back() + 1.0));
}

TEST(IterativeError, ALimitCycleIsItsFluctuation) {
  // Converged to 1.0 with a period-4 wiggle of amplitude 1e-3: no trend, the
  // final iterate is off by up to the wiggle.
  std::vector<double> x(400);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 + 1e-3 * std::sin(static_cast<double>(i) * M_PI / 2.0 + 0.3);
  const IterativeError e = iterative_error(x, 0.5);
  EXPECT_NEAR(e.fluctuation, 1e-3 / std::sqrt(2.0), 2e-4);
  EXPECT_GE(e.standard_uncertainty, std::abs(x.back() - 1.0) / 2.0);
  EXPECT_LT(std::abs(e.change_per_iteration), 1e-4);
}

TEST(IterativeError, ACreepThatDoesNotDecayIsAtTheRateCap) {
  // A linear creep: the residuals say nothing decays (rate >= 1): the error
  // is that of the cap, 999 changes per iteration.
  std::vector<double> x(100);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 - 1e-5 * static_cast<double>(i);
  const IterativeError e = iterative_error(x, 1.2);
  EXPECT_EQ(e.rate, kMaxIterationRate);
  EXPECT_NEAR(e.extrapolated_error, 1e-5 * 999.0, 1e-9);
}

TEST(IterativeError, AConstantSeriesHasNoError) {
  const std::vector<double> x(50, 3.25);
  const IterativeError e = iterative_error(x, 0.9);
  EXPECT_EQ(e.value, 3.25);
  EXPECT_EQ(e.standard_uncertainty, 0.0);
  const IterativeError one = iterative_error(std::vector<double>{7.0}, 0.9);
  EXPECT_EQ(one.value, 7.0);
  EXPECT_EQ(one.standard_uncertainty, 0.0);
}

TEST(DecayRate, OfAGeometricSeriesAndWhatItCannotTell) {
  EXPECT_NEAR(decay_rate(geometric(0.0, 1.0, 0.8, 60)), 0.8, 1e-12);
  EXPECT_NEAR(decay_rate(geometric(0.0, 1.0, 1.01, 60)), 1.01, 1e-12);
  EXPECT_TRUE(std::isnan(decay_rate(std::vector<double>(9, 1.0))));                              // too short
  EXPECT_TRUE(std::isnan(decay_rate(std::vector<double>{1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 1, 1})));  // a zero
}

}  // namespace
}  // namespace hydrocoef
