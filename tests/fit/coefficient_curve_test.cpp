// Coefficient curves across a disturbance: per-level damping-law fits that
// recover known coefficient functions a(v), b(v); least-squares polynomial
// curves against the exact polynomials and a closed-form regression line;
// PCHIP against hand-computed MATLAB-rule slopes and values, monotonicity
// without overshoot, C1 continuity; and the errors.
#include "src/fit/coefficient_curve.hpp"

#include <gtest/gtest.h>

#include "tests/support/expect_input_error.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/fit/damping_law.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

// Surge damping under a sway current v: X = a(v) u + b(v) u|u| with
// quadratic a and b (coefficients in ascending powers of v).
const std::vector<double> kA = {0.5, 2.0, -30.0};
const std::vector<double> kB = {11.0, 5.0, 200.0};

double polynomial_at(const std::vector<double>& p, double v) { return p[0] + p[1] * v + p[2] * v * v; }

struct Runs {
  std::vector<double> u;
  std::vector<double> X;
  std::vector<double> current;
};

// Runs at 6 current levels x 9 surge speeds, interleaved so that levels are not contiguous.
Runs synthetic_runs() {
  const std::vector<double> levels = {0.1, -0.05, 0.15, 0.0, -0.1, 0.05};
  const std::vector<double> speeds = {-1.2, -0.8, -0.4, -0.1, 0.1, 0.3, 0.6, 1.0, 1.4};
  Runs runs;
  for (double u : speeds)
    for (double v : levels) {
      runs.u.push_back(u);
      runs.current.push_back(v);
      runs.X.push_back(polynomial_at(kA, v) * u + polynomial_at(kB, v) * u * std::abs(u));
    }
  return runs;
}

LevelFit level_fit(double level, std::vector<double> coefficients, const std::string& terms = "u") {
  LevelFit entry;
  entry.level = level;
  entry.fit.spec = parse_damping_terms(terms);
  entry.fit.coefficients = std::move(coefficients);
  return entry;
}

// One-coefficient level fits with the given levels and values.
std::vector<LevelFit> single_coefficient(const std::vector<double>& levels, const std::vector<double>& values) {
  std::vector<LevelFit> fits;
  for (std::size_t i = 0; i < levels.size(); ++i) fits.push_back(level_fit(levels[i], {values[i]}));
  return fits;
}

TEST(FitPerLevel, RecoversTheCoefficientsAtEachLevel) {
  const Runs runs = synthetic_runs();
  const DampingLawSpec spec = parse_damping_terms("u,u|u|");
  const std::vector<LevelFit> fits = fit_per_level(spec, runs.u, runs.X, runs.current);
  ASSERT_EQ(fits.size(), 6u);
  const std::vector<double> sorted = {-0.1, -0.05, 0.0, 0.05, 0.1, 0.15};
  for (std::size_t i = 0; i < fits.size(); ++i) {
    EXPECT_EQ(fits[i].level, sorted[i]);
    EXPECT_EQ(fits[i].fit.n, 9u);
    ASSERT_EQ(fits[i].fit.coefficients.size(), 2u);
    EXPECT_NEAR(fits[i].fit.coefficients[0], polynomial_at(kA, sorted[i]), 1e-10) << "level " << sorted[i];
    EXPECT_NEAR(fits[i].fit.coefficients[1], polynomial_at(kB, sorted[i]), 1e-10) << "level " << sorted[i];
    EXPECT_LT(fits[i].fit.rmse, 1e-10);
  }
}

TEST(CoefficientCurves, QuadraticCurvesRecoverThePolynomials) {
  const Runs runs = synthetic_runs();
  const auto fits = fit_per_level(parse_damping_terms("u,u|u|"), runs.u, runs.X, runs.current);
  const std::vector<CoefficientCurve> curves = fit_coefficient_curves(fits, CurveKind::Polynomial, 2);
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0].term, "u");
  EXPECT_EQ(curves[1].term, "u|u|");
  for (std::size_t j = 0; j < 2; ++j) {
    const std::vector<double>& expected = j == 0 ? kA : kB;
    const CoefficientCurve& curve = curves[j];
    EXPECT_EQ(curve.kind, CurveKind::Polynomial);
    EXPECT_EQ(curve.degree, 2);
    EXPECT_EQ(curve.levels, (std::vector<double>{-0.1, -0.05, 0.0, 0.05, 0.1, 0.15}));
    ASSERT_EQ(curve.polynomial.size(), 3u);
    for (std::size_t p = 0; p < 3; ++p)
      EXPECT_NEAR(curve.polynomial[p], expected[p], 1e-8 * std::abs(expected[p])) << curve.term << " power " << p;
    EXPECT_LT(curve.rmse, 1e-10);
    for (double v : {-0.1, -0.033, 0.0, 0.07, 0.15}) {
      EXPECT_NEAR(curve.evaluate(v), polynomial_at(expected, v), 1e-9) << curve.term << " at " << v;
      EXPECT_NEAR(curve.derivative(v), expected[1] + 2.0 * expected[2] * v, 1e-7) << curve.term << " at " << v;
    }
  }
}

TEST(CoefficientCurves, LinearCurveIsTheLeastSquaresLine) {
  const std::vector<double> levels = {0.0, 0.1, 0.2, 0.4};
  const std::vector<double> values = {1.0, 1.3, 1.1, 2.0};
  const auto curves = fit_coefficient_curves(single_coefficient(levels, values), CurveKind::Polynomial, 1);
  ASSERT_EQ(curves.size(), 1u);
  // Closed-form simple regression.
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    mean_x += levels[i] / 4.0;
    mean_y += values[i] / 4.0;
  }
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    sxy += (levels[i] - mean_x) * (values[i] - mean_y);
    sxx += (levels[i] - mean_x) * (levels[i] - mean_x);
  }
  const double slope = sxy / sxx;
  const double intercept = mean_y - slope * mean_x;
  EXPECT_NEAR(curves[0].polynomial[0], intercept, 1e-12);
  EXPECT_NEAR(curves[0].polynomial[1], slope, 1e-12);
  double ssr = 0.0;
  for (std::size_t i = 0; i < 4; ++i) ssr += std::pow(intercept + slope * levels[i] - values[i], 2);
  EXPECT_NEAR(curves[0].rmse, std::sqrt(ssr / 4.0), 1e-12);
  EXPECT_GT(curves[0].rmse, 0.1);
  EXPECT_TRUE(curves[0].values == values);
}

// Slopes by hand with MATLAB pchip's rules for levels (0, 1, 3), values (0, 2, 3):
// secants 2 and 0.5; interior slope (w1 + w2) / (w1/2 + w2/0.5) with
// w1 = 2*2 + 1 = 5, w2 = 2 + 2*1 = 4: 9 / 10.5 = 6/7; left end
// ((2*1 + 2)*2 - 1*0.5) / 3 = 2.5 (same sign as the secant, kept); right end
// ((2*2 + 1)*0.5 - 2*2) / 3 = -0.5, opposite sign to its secant, so 0.
TEST(PchipCurve, MatchesHandComputedMatlabSlopesAndValues) {
  const auto curves = fit_coefficient_curves(single_coefficient({0.0, 1.0, 3.0}, {0.0, 2.0, 3.0}), CurveKind::Pchip);
  ASSERT_EQ(curves.size(), 1u);
  const CoefficientCurve& curve = curves[0];
  EXPECT_EQ(curve.kind, CurveKind::Pchip);
  EXPECT_EQ(curve.degree, 3);
  EXPECT_TRUE(curve.polynomial.empty());
  EXPECT_EQ(curve.rmse, 0.0);
  EXPECT_NEAR(curve.derivative(0.0), 2.5, 1e-14);
  EXPECT_NEAR(curve.derivative(1.0), 6.0 / 7.0, 1e-14);
  EXPECT_NEAR(curve.derivative(3.0), 0.0, 1e-14);
  // Hermite cubics at the interval midpoints: 0.5 + 0.125*2.5 - 0.125*(6/7) ... = 33.75/28; and 19/7.
  EXPECT_NEAR(curve.evaluate(0.5), 33.75 / 28.0, 1e-14);
  EXPECT_NEAR(curve.evaluate(2.0), 19.0 / 7.0, 1e-14);
  EXPECT_EQ(curve.evaluate(0.0), 0.0);
  EXPECT_EQ(curve.evaluate(1.0), 2.0);
  EXPECT_EQ(curve.evaluate(3.0), 3.0);
}

TEST(PchipCurve, MonotoneValuesGiveAMonotoneCurveThroughThem) {
  // A step that an ordinary cubic spline would overshoot, with uneven spacing.
  const std::vector<double> levels = {-0.2, -0.1, 0.0, 0.02, 0.1, 0.3};
  for (double direction : {1.0, -1.0}) {
    std::vector<double> values = {0.0, 0.1, 0.2, 3.0, 3.1, 3.2};
    for (double& v : values) v *= direction;
    const auto curves = fit_coefficient_curves(single_coefficient(levels, values), CurveKind::Pchip);
    const CoefficientCurve& curve = curves[0];
    for (std::size_t k = 0; k < levels.size(); ++k) EXPECT_EQ(curve.evaluate(levels[k]), values[k]) << k;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
      const double low = std::min(values[k], values[k + 1]);
      const double high = std::max(values[k], values[k + 1]);
      double previous = curve.evaluate(levels[k]);
      for (int s = 1; s <= 200; ++s) {
        const double level = levels[k] + (levels[k + 1] - levels[k]) * s / 200.0;
        const double value = curve.evaluate(std::min(level, levels[k + 1]));
        EXPECT_GE(direction * (value - previous), -1e-15) << "interval " << k << " step " << s;
        EXPECT_GE(value, low - 1e-15);
        EXPECT_LE(value, high + 1e-15);
        EXPECT_GE(direction * curve.derivative(std::min(level, levels[k + 1])), -1e-12);
        previous = value;
      }
    }
  }
}

TEST(PchipCurve, FlatAtExtremaLinearDataAndC1) {
  // A local maximum keeps its value: the slope there is 0 and the curve stays below it.
  const auto peak = fit_coefficient_curves(single_coefficient({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0}), CurveKind::Pchip)[0];
  EXPECT_EQ(peak.derivative(1.0), 0.0);
  for (int s = 0; s <= 100; ++s) EXPECT_LE(peak.evaluate(0.02 * s), 1.0);

  // Linear data stays linear; two levels interpolate linearly.
  const auto line =
      fit_coefficient_curves(single_coefficient({0.0, 0.1, 0.35, 0.4}, {1.0, 1.2, 1.7, 1.8}), CurveKind::Pchip)[0];
  for (double v : {0.0, 0.05, 0.2, 0.37, 0.4}) {
    EXPECT_NEAR(line.evaluate(v), 1.0 + 2.0 * v, 1e-14);
    EXPECT_NEAR(line.derivative(v), 2.0, 1e-12);
  }
  const auto two = fit_coefficient_curves(single_coefficient({1.0, 3.0}, {5.0, 4.0}), CurveKind::Pchip)[0];
  EXPECT_NEAR(two.evaluate(2.5), 4.25, 1e-14);
  EXPECT_NEAR(two.derivative(1.7), -0.5, 1e-14);

  // C1: derivative equals central differences, and is continuous across a knot.
  const auto curve = fit_coefficient_curves(single_coefficient({0.0, 0.1, 0.25, 0.3, 0.5}, {2.0, 2.5, 2.6, 3.5, 3.6}),
                                            CurveKind::Pchip)[0];
  for (double v : {0.03, 0.12, 0.26, 0.41}) {
    const double h = 1e-6;
    EXPECT_NEAR(curve.derivative(v), (curve.evaluate(v + h) - curve.evaluate(v - h)) / (2.0 * h), 1e-6) << v;
  }
  // The second derivative is ~1e3 here, so 2e-12 apart the slopes differ by ~2e-9; a jump would be O(1).
  EXPECT_NEAR(curve.derivative(0.25 - 1e-12), curve.derivative(0.25 + 1e-12), 1e-7);
}

TEST(CoefficientCurves, PchipThroughPerLevelFits) {
  const Runs runs = synthetic_runs();
  const auto fits = fit_per_level(parse_damping_terms("u,u|u|"), runs.u, runs.X, runs.current);
  const auto curves = fit_coefficient_curves(fits, CurveKind::Pchip);
  ASSERT_EQ(curves.size(), 2u);
  for (std::size_t i = 0; i < fits.size(); ++i) {
    EXPECT_EQ(curves[0].evaluate(fits[i].level), fits[i].fit.coefficients[0]);
    EXPECT_EQ(curves[1].evaluate(fits[i].level), fits[i].fit.coefficients[1]);
  }
  // Between levels, close to the smooth truth (levels 0.05 apart).
  EXPECT_NEAR(curves[1].evaluate(0.075), polynomial_at(kB, 0.075), 0.05);
}

TEST(CoefficientCurveErrors, TooFewLevels) {
  const auto two = single_coefficient({0.0, 0.1}, {1.0, 2.0});
  expect_input_error([&] { (void)fit_coefficient_curves(two, CurveKind::Polynomial, 2); },
                     {"degree-2 polynomial", "at least 3 disturbance levels", "found 2"});
  expect_input_error([&] { (void)fit_coefficient_curves(single_coefficient({0.0}, {1.0}), CurveKind::Pchip); },
                     {"PCHIP", "at least 2", "found 1"});
  expect_input_error([&] { (void)fit_coefficient_curves({}, CurveKind::Pchip); }, {"found 0"});
  expect_input_error([&] { (void)fit_coefficient_curves(two, CurveKind::Polynomial, -1); }, {"degree -1"});
  EXPECT_NO_THROW((void)fit_coefficient_curves(two, CurveKind::Polynomial, 1));
}

TEST(CoefficientCurveErrors, BadLevelFits) {
  expect_input_error(
      [&] {
        (void)fit_coefficient_curves(single_coefficient({0.0, 0.1, 0.1}, {1.0, 2.0, 3.0}), CurveKind::Pchip);
      },
      {"level 0.1", "appears twice"});
  expect_input_error(
      [&] {
        (void)fit_coefficient_curves(single_coefficient({0.0, std::nan(""), 0.2}, {1.0, 2.0, 3.0}), CurveKind::Pchip);
      },
      {"level nan", "finite"});
  expect_input_error(
      [&] {
        (void)fit_coefficient_curves(
            single_coefficient({0.0, 0.1, 0.2}, {1.0, std::numeric_limits<double>::infinity(), 3.0}), CurveKind::Pchip);
      },
      {"'u'", "level 0.1", "inf", "finite"});
  std::vector<LevelFit> mixed = single_coefficient({0.0, 0.1}, {1.0, 2.0});
  mixed.push_back(level_fit(0.2, {1.0, 2.0}, "u,u|u|"));
  expect_input_error([&] { (void)fit_coefficient_curves(mixed, CurveKind::Pchip); },
                     {"level 0.2", "'u,u|u|'", "'u'", "one law"});
}

TEST(CoefficientCurveErrors, EvaluationOutsideTheLevelsDoesNotExtrapolate) {
  const Runs runs = synthetic_runs();
  const auto fits = fit_per_level(parse_damping_terms("u,u|u|"), runs.u, runs.X, runs.current);
  for (CurveKind kind : {CurveKind::Polynomial, CurveKind::Pchip}) {
    const auto curves = fit_coefficient_curves(fits, kind, 2);
    expect_input_error([&] { (void)curves[1].evaluate(0.2); }, {"'u|u|'", "level 0.2", "[-0.1, 0.15]", "extrapolate"});
    expect_input_error([&] { (void)curves[0].derivative(-0.11); }, {"'u'", "level -0.11", "[-0.1, 0.15]"});
    expect_input_error([&] { (void)curves[0].evaluate(std::nan("")); }, {"level nan"});
  }
}

TEST(FitPerLevelErrors, LevelsWithTooFewOrUnsuitableRuns) {
  const DampingLawSpec spec = parse_damping_terms("1,u,u|u|");
  // Level 0.05 has only two runs for three terms.
  const std::vector<double> u = {0.1, 0.2, 0.3, 0.4, 0.1, 0.2};
  const std::vector<double> X = {1.0, 2.0, 3.5, 5.0, 1.0, 2.0};
  const std::vector<double> current = {0.0, 0.0, 0.0, 0.0, 0.05, 0.05};
  expect_input_error([&] { (void)fit_per_level(spec, u, X, current); },
                     {"disturbance level 0.05", "2 runs", "'1,u,u|u|'", "at least 3"});

  // Level 0.1 has enough runs, but all at one speed: the fitter's error, naming the level.
  const std::vector<double> u2 = {0.1, 0.2, 0.3, 0.5, 0.5, 0.5};
  const std::vector<double> current2 = {0.0, 0.0, 0.0, 0.1, 0.1, 0.1};
  expect_input_error([&] { (void)fit_per_level(spec, u2, X, current2); },
                     {"at disturbance level 0.1 (3 runs)", "linearly dependent"});
}

// With a list for skipped levels, a sparse or unsuitable level is left out
// and named there, and the other levels are fitted as they would be alone.
TEST(FitPerLevelErrors, SparseLevelsAreSkippedWhenAskedAndNamed) {
  const DampingLawSpec spec = parse_damping_terms("1,u,u|u|");
  const std::vector<double> u = {0.1, 0.2, 0.3, 0.4, 0.1, 0.2, 0.5, 0.5, 0.5};
  const std::vector<double> X = {1.0, 2.0, 3.5, 5.0, 1.0, 2.0, 1.0, 2.0, 3.0};
  const std::vector<double> current = {0.0, 0.0, 0.0, 0.0, 0.05, 0.05, 0.1, 0.1, 0.1};
  std::vector<SkippedLevel> skipped;
  const auto fits = fit_per_level(spec, u, X, current, {}, &skipped);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].level, 0.0);
  const auto alone = fit_damping_law(spec, std::vector<double>(u.begin(), u.begin() + 4),
                                     std::vector<double>(X.begin(), X.begin() + 4));
  for (std::size_t k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(fits[0].fit.coefficients[k], alone.coefficients[k]);
  ASSERT_EQ(skipped.size(), 2u);
  EXPECT_EQ(skipped[0].level, 0.05);
  EXPECT_EQ(skipped[0].runs, 2u);
  EXPECT_NE(skipped[0].reason.find("at least 3"), std::string::npos) << skipped[0].reason;
  EXPECT_EQ(skipped[1].level, 0.1);
  EXPECT_NE(skipped[1].reason.find("linearly dependent"), std::string::npos) << skipped[1].reason;
}

TEST(FitPerLevelErrors, NonFiniteAndMismatchedInput) {
  const DampingLawSpec spec = parse_damping_terms("u,u|u|");
  std::vector<double> u = {0.1, 0.2, 0.3, 0.1, 0.2, 0.3};
  std::vector<double> X = {1.0, 2.0, 3.0, 1.0, 2.0, 3.0};
  std::vector<double> current = {0.0, 0.0, 0.0, 0.1, 0.1, 0.1};
  current[3] = std::nan("");
  expect_input_error([&] { (void)fit_per_level(spec, u, X, current); }, {"run 4 of 6", "disturbance = nan", "finite"});
  current[3] = 0.1;
  X[5] = std::numeric_limits<double>::infinity();
  expect_input_error([&] { (void)fit_per_level(spec, u, X, current); }, {"run 6 of 6", "force = inf"});
  X[5] = 3.0;
  expect_input_error([&] { (void)fit_per_level(spec, u, X, std::vector<double>(5, 0.0)); },
                     {"6 velocity values", "6 force values", "5 disturbance values"});
  expect_input_error([&] { (void)fit_per_level(spec, {}, {}, {}); }, {"no runs"});
  // -0 and 0 are one level, reported as 0.
  current = {0.0, -0.0, 0.0, 0.1, 0.1, 0.1};
  const auto fits = fit_per_level(spec, u, X, current);
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_FALSE(std::signbit(fits[0].level));
  EXPECT_EQ(fits[0].fit.n, 3u);
}

}  // namespace
}  // namespace hydrocoef
