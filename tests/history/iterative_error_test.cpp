// The iterative error of a converged steady run's final iterate
// (src/history/iterative_error): on sequences whose limit is known exactly
// (geometric convergence, a linear creep, a limit cycle) the stated
// uncertainty covers the true distance to the limit; the decay rate of a
// residual history. The real runs' check (every converged value covered) is
// tests/cli/cli_converged_study_test.cpp.
#include "src/history/iterative_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace hydrocoef {
namespace {

std::vector<double> geometric(double limit, double amplitude, double rate, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = limit + amplitude * std::pow(rate, static_cast<double>(i));
  return x;
}

TEST(IterativeError, GeometricConvergenceIsCovered) {
  // x_i = 2 - 0.3 lambda^i: the error of the last iterate is known exactly.
  // It is covered, and overstated by no more than the change over the last
  // quarter says (for fast convergence that change is the larger).
  for (const auto& [rate, n] :
       {std::pair{0.9, 100}, std::pair{0.95, 200}, std::pair{0.97, 300}, std::pair{0.99, 1000}}) {
    SCOPED_TRACE(rate);
    const auto x = geometric(2.0, -0.3, rate, static_cast<std::size_t>(n));
    const IterativeError e = iterative_error(x);
    const double truth = std::abs(x.back() - 2.0);
    EXPECT_EQ(e.value, x.back());
    EXPECT_GE(e.standard_uncertainty, truth * (1.0 - 1e-9));
    const double recent = truth * (std::pow(rate, -static_cast<double>(n / 4)) - 1.0);
    EXPECT_NEAR(e.recent_change, recent, 1e-9 * recent);
    EXPECT_LE(e.standard_uncertainty, std::max(recent, 2.0 * truth) * 1.0001);
    // The exponential fit finds the limit (its time constant is on a grid).
    EXPECT_NEAR(e.extrapolated, 2.0, 0.5 * truth);
  }
}

TEST(IterativeError, ACreepThatHasNotSettledIsItsRecentChange) {
  // A force still falling linearly at the end (the lateral force of the
  // residualControl runs): at least the change over the last quarter.
  std::vector<double> x(200);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 - 1e-4 * static_cast<double>(i);
  const IterativeError e = iterative_error(x);
  EXPECT_NEAR(e.recent_change, 50 * 1e-4, 1e-12);
  EXPECT_GE(e.standard_uncertainty, e.recent_change);
  EXPECT_NEAR(e.change_per_iteration, -1e-4, 1e-12);
}

TEST(IterativeError, ALimitCycleIsCoveredByItsSwing) {
  // Converged to 1.0 with a period-4 wiggle of amplitude 1e-3.
  std::vector<double> x(400);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.0 + 1e-3 * std::sin(static_cast<double>(i) * M_PI / 2.0 + 0.3);
  const IterativeError e = iterative_error(x);
  EXPECT_GE(e.standard_uncertainty, std::abs(x.back() - 1.0) / 2.0);
  EXPECT_LE(e.standard_uncertainty, 4e-3);
  EXPECT_LT(std::abs(e.change_per_iteration), 1e-4);
}

TEST(IterativeError, AConstantSeriesHasNoError) {
  const std::vector<double> x(50, 3.25);
  const IterativeError e = iterative_error(x);
  EXPECT_EQ(e.value, 3.25);
  EXPECT_EQ(e.standard_uncertainty, 0.0);
  const IterativeError one = iterative_error(std::vector<double>{7.0});
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
