// Integrators: RK4's fourth-order convergence measured on problems with exact
// solutions; Dormand–Prince's error control against the exact solution of a
// linear damped oscillator (the error follows the tolerance), exact landing on
// the end time, its evaluation count, and the step-size underflow error.
#include "src/dynamics/integrators.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec1 = Eigen::Matrix<double, 1, 1>;

// x'' + 2 zeta w x' + w^2 x = 0, x(0) = 1, x'(0) = 0 (underdamped).
struct Oscillator {
  double w = 2.0;
  double zeta = 0.1;
  void operator()(double, const Vec2& x, Vec2& dx) const { dx << x[1], -2 * zeta * w * x[1] - w * w * x[0]; }
  Vec2 exact(double t) const {
    const double wd = w * std::sqrt(1 - zeta * zeta);
    const double s = zeta * w;
    const double e = std::exp(-s * t);
    const double x = e * (std::cos(wd * t) + s / wd * std::sin(wd * t));
    const double v = -e * (w * w / wd) * std::sin(wd * t);
    return {x, v};
  }
};

double rk4_error(double h, double t_end) {
  Oscillator f;
  Vec2 x(1.0, 0.0);
  Rk4Workspace<Vec2> w;
  const int n = static_cast<int>(std::lround(t_end / h));
  for (int i = 0; i < n; ++i) rk4_step(f, i * h, h, x, w);
  return (x - f.exact(t_end)).norm();
}

TEST(Rk4, FourthOrderConvergence) {
  const double e1 = rk4_error(0.02, 5.0);
  const double e2 = rk4_error(0.01, 5.0);
  const double e3 = rk4_error(0.005, 5.0);
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.1);
  EXPECT_NEAR(std::log2(e2 / e3), 4.0, 0.1);
}

TEST(Rk4, NonlinearProblemFourthOrder) {
  // x' = -x^2 + sin t has no closed form, so compare with a much finer RK4 run.
  auto f = [](double t, const Vec1& x, Vec1& dx) { dx[0] = -x[0] * x[0] + std::sin(t); };
  auto run = [&](double h) {
    Vec1 x;
    x[0] = 1.0;
    Rk4Workspace<Vec1> w;
    const int n = static_cast<int>(std::lround(4.0 / h));
    for (int i = 0; i < n; ++i) rk4_step(f, i * h, h, x, w);
    return x[0];
  };
  const double reference = run(1e-4);
  const double e1 = std::abs(run(0.04) - reference);
  const double e2 = std::abs(run(0.02) - reference);
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.2);
}

TEST(DormandPrince, ErrorFollowsTheTolerance) {
  Oscillator f;
  double previous_error = 1.0;
  std::size_t previous_steps = 0;
  for (const double tol : {1e-5, 1e-8, 1e-11}) {
    AdaptiveOptions options;
    options.relative_tolerance = tol;
    options.absolute_tolerance = tol;
    DormandPrince45<Vec2> dp(options);
    Vec2 x(1.0, 0.0);
    double t = 0.0;
    dp.advance(f, t, 10.0, x);
    EXPECT_EQ(t, 10.0);
    const double error = (x - f.exact(10.0)).norm();
    // Local error per unit step is held near tol; the global error over 10 s
    // stays within a modest multiple of it.
    EXPECT_LT(error, 50.0 * tol) << tol;
    EXPECT_LT(error, previous_error / 100.0) << tol;
    EXPECT_GT(dp.stats().accepted, previous_steps);
    // FSAL: one evaluation to start, one for the starting-step estimate, six per attempt.
    EXPECT_EQ(dp.stats().evaluations, 2 + 6 * (dp.stats().accepted + dp.stats().rejected));
    previous_error = error;
    previous_steps = dp.stats().accepted;
  }
}

TEST(DormandPrince, PiecewiseAdvanceLandsOnEveryEndTime) {
  Oscillator f;
  AdaptiveOptions options;
  options.relative_tolerance = 1e-10;
  options.absolute_tolerance = 1e-12;
  options.max_step = 0.05;
  DormandPrince45<Vec2> dp(options);
  Vec2 x(1.0, 0.0);
  double t = 0.0;
  for (int k = 1; k <= 30; ++k) {
    dp.advance(f, t, 0.1 * k, x);
    EXPECT_EQ(t, 0.1 * k);
  }
  EXPECT_LT((x - f.exact(3.0)).norm(), 1e-9);
}

TEST(DormandPrince, RejectsStepsWhereTheSolutionChangesScale) {
  // x' = -50 (x - cos t): a fast transient, then a slow one; a large first
  // guess must be cut back.
  auto f = [](double t, const Vec1& x, Vec1& dx) { dx[0] = -50.0 * (x[0] - std::cos(t)); };
  AdaptiveOptions options;
  options.relative_tolerance = 1e-9;
  options.absolute_tolerance = 1e-12;
  DormandPrince45<Vec1> dp(options);
  Vec1 x;
  x[0] = 0.0;
  double t = 0.0;
  dp.advance(f, t, 2.0, x);
  // Exact: x = (2500 cos t + 50 sin t)/2501 - 2500/2501 e^{-50 t}.
  const double exact = (2500.0 * std::cos(2.0) + 50.0 * std::sin(2.0)) / 2501.0 - 2500.0 / 2501.0 * std::exp(-100.0);
  EXPECT_NEAR(x[0], exact, 1e-7);
  EXPECT_GT(dp.stats().rejected, 0u);
}

TEST(DormandPrince, StepUnderflowIsAnInputError) {
  // x' = x^2, x(0) = 1 blows up at t = 1.
  auto f = [](double, const Vec1& x, Vec1& dx) { dx[0] = x[0] * x[0]; };
  DormandPrince45<Vec1> dp;
  Vec1 x;
  x[0] = 1.0;
  double t = 0.0;
  EXPECT_THROW(dp.advance(f, t, 2.0, x), InputError);
  EXPECT_LT(t, 1.0 + 1e-6);  // stopped at the singularity, not past it
}

}  // namespace
}  // namespace hydrocoef
