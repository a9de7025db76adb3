// Statistics of one window of a correlated series (src/history/statistics):
// the standard error of the mean against the exact one of AR(1) noise, with
// and without coarse graining; the floor at tau = 1 for periodic and
// anti-correlated data; exact means of constant series far from zero; the
// drift of a known line and the standard error of the drift; unresolved
// autocorrelation; refusals of bad input.
#include "src/history/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "tests/history/synthetic_history.hpp"

namespace hydrocoef {
namespace {

using test::ar1_standard_error;
using test::iota_abscissa;
using test::make_series;
using test::SyntheticSeries;

TEST(SeriesStatistics, WhiteNoiseHasTauNearOneAndTheTextbookError) {
  const std::size_t n = 20000;
  const auto x = make_series({.mean = 3.0, .phi = 0.0, .sigma = 2.0}, n, 11);
  const SeriesStatistics s = series_statistics(x, iota_abscissa(n));
  EXPECT_EQ(s.count, n);
  EXPECT_NEAR(s.mean, 3.0, 4.0 * 2.0 / std::sqrt(double(n)));
  EXPECT_NEAR(s.std_dev, 2.0, 0.05);
  EXPECT_NEAR(s.autocorrelation_time, 1.0, 0.15);
  EXPECT_NEAR(s.standard_error / (2.0 / std::sqrt(double(n))), 1.0, 0.1);
  EXPECT_NEAR(s.effective_samples, double(n) / s.autocorrelation_time, 1e-9);
  EXPECT_TRUE(s.autocorrelation_resolved);
  EXPECT_EQ(s.block_size, 1u);
  EXPECT_FALSE(s.constant);
}

// 100 stationary AR(1) series over a range of correlation: each standard
// error within 20 % of the exact one, and no bias beyond 5 % on average.
TEST(SeriesStatistics, Ar1StandardErrorIsWithinTwentyPerCentOfTheExactOne) {
  const std::size_t n = 30000;
  double ratio_sum = 0.0;
  double worst = 0.0;
  const int cases = 100;
  for (int k = 0; k < cases; ++k) {
    const double phi = 0.2 + 0.7 * k / (cases - 1.0);  // tau from 1.5 to 19
    const double sigma = 0.5 + 0.01 * k;
    const auto x = make_series({.mean = -1.5, .phi = phi, .sigma = sigma}, n, 1000 + k);
    const SeriesStatistics s = series_statistics(x, iota_abscissa(n));
    const double truth = ar1_standard_error(phi, sigma, n);
    const double ratio = s.standard_error / truth;
    ratio_sum += ratio;
    worst = std::max(worst, std::abs(ratio - 1.0));
    EXPECT_NEAR(ratio, 1.0, 0.2) << "phi " << phi;
    EXPECT_NEAR(s.autocorrelation_time / ((1 + phi) / (1 - phi)), 1.0, 0.4) << "phi " << phi;
    EXPECT_TRUE(s.autocorrelation_resolved);
  }
  EXPECT_NEAR(ratio_sum / cases, 1.0, 0.05);
  RecordProperty("worst_relative_error", std::to_string(worst));
}

// A long, strongly correlated series (tau = 199) cannot be windowed within
// 200 lags: it is coarse-grained, and the error is still right. The same
// series analysed without coarse graining agrees.
TEST(SeriesStatistics, CoarseGrainingKeepsTheErrorOfALongCorrelatedSeries) {
  const std::size_t n = 300000;
  const double phi = 0.99;
  const auto x = make_series({.mean = 10.0, .phi = phi, .sigma = 0.1}, n, 7);
  const auto t = iota_abscissa(n, 0.0, 1e-3);
  const SeriesStatistics coarse = series_statistics(x, t);
  EXPECT_GT(coarse.block_size, 1u);
  EXPECT_TRUE(coarse.autocorrelation_resolved);
  EXPECT_LE(coarse.autocorrelation_window, 200u);
  const double truth = ar1_standard_error(phi, 0.1, n);
  EXPECT_NEAR(coarse.standard_error / truth, 1.0, 0.2);
  EXPECT_NEAR(coarse.autocorrelation_time / ((1 + phi) / (1 - phi)), 1.0, 0.4);

  StatisticsOptions fine;
  fine.max_blocks = n;
  fine.max_lag = 2000;
  const SeriesStatistics direct = series_statistics(x, t, fine);
  EXPECT_EQ(direct.block_size, 1u);
  EXPECT_GT(direct.autocorrelation_window, 500u);
  EXPECT_NEAR(coarse.standard_error / direct.standard_error, 1.0, 0.15);
  EXPECT_DOUBLE_EQ(coarse.mean, direct.mean);
}

// Each block averages many samples of weakly correlated noise: blocking a
// million samples into 65536 blocks leaves the error right.
TEST(SeriesStatistics, BlockingWeaklyCorrelatedNoiseLeavesTheErrorRight) {
  const std::size_t n = 1000000;
  const auto x = make_series({.mean = 0.0, .phi = 0.5, .sigma = 1.0}, n, 99);
  const SeriesStatistics s = series_statistics(x, iota_abscissa(n));
  EXPECT_EQ(s.block_size, 16u);  // ceil(10^6 / 65536)
  EXPECT_NEAR(s.standard_error / ar1_standard_error(0.5, 1.0, n), 1.0, 0.1);
}

TEST(SeriesStatistics, ConstantSeriesHasNoErrorAndAnExactMean) {
  for (const double value : {0.0, 0.1, -7.25e-3, 123456.789}) {
    const std::vector<double> x(1001, value);
    const SeriesStatistics s = series_statistics(x, iota_abscissa(x.size()));
    EXPECT_TRUE(s.constant);
    EXPECT_EQ(s.mean, value);
    EXPECT_EQ(s.std_dev, 0.0);
    EXPECT_EQ(s.standard_error, 0.0);
    EXPECT_EQ(s.drift, 0.0);
    EXPECT_EQ(s.drift_standard_error, 0.0);
    EXPECT_EQ(s.autocorrelation_time, 1.0);
    EXPECT_EQ(s.effective_samples, 1001.0);
  }
}

TEST(SeriesStatistics, LargeOffsetDoesNotSpoilTheSpread) {
  const std::size_t n = 5000;
  auto x = make_series({.mean = 0.0, .phi = 0.0, .sigma = 1e-6}, n, 5);
  for (double& v : x) v += 1e6;
  const SeriesStatistics s = series_statistics(x, iota_abscissa(n));
  EXPECT_NEAR(s.std_dev / 1e-6, 1.0, 0.05);
  EXPECT_NEAR(s.mean, 1e6, 1e-7);
}

TEST(SeriesStatistics, DriftOfALineIsItsSlopeTimesTheSpan) {
  const std::size_t n = 101;
  std::vector<double> t(n), x(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 2.0 + 0.5 * double(i);  // unevenly started, 0.5 s steps
    x[i] = 4.0 - 0.25 * t[i];
  }
  const SeriesStatistics s = series_statistics(x, t);
  EXPECT_NEAR(s.drift_slope, -0.25, 1e-12);
  EXPECT_NEAR(s.drift, -0.25 * 50.0, 1e-10);
  EXPECT_NEAR(s.mean, 4.0 - 0.25 * 27.0, 1e-12);
  // Nothing but the line: the residuals about it, and so the drift's
  // standard error, vanish (up to rounding).
  EXPECT_LT(s.drift_standard_error, 1e-9 * std::abs(s.drift));
}

// A trend buried in noise must not widen its own error bar: the drift's
// standard error comes from the noise about the line. (tau about the mean is
// inflated by the trend; the standard error of the mean keeps that.)
TEST(SeriesStatistics, DriftErrorComesFromTheNoiseAboutTheLine) {
  const std::size_t n = 10000;
  const auto x = make_series({.mean = 1.0, .phi = 0.5, .sigma = 0.01, .slope = -1.5e-6}, n, 77);
  const SeriesStatistics s = series_statistics(x, iota_abscissa(n));
  const double noise_only = std::sqrt(12.0) * ar1_standard_error(0.5, 0.01, n);
  EXPECT_NEAR(s.drift_standard_error / noise_only, 1.0, 0.2);
  EXPECT_NEAR(s.drift, -1.5e-6 * (n - 1), 4.0 * noise_only);
  EXPECT_GT(s.autocorrelation_time, 20.0);  // the trend looks like slow fluctuation about the mean
}

// For noise, the drift's standard error is about sqrt(12) times the mean's,
// and the drift itself scatters by that much.
TEST(SeriesStatistics, DriftStandardErrorIsAboutRootTwelveTimesTheMeans) {
  const std::size_t n = 20000;
  double sum_z2 = 0.0;
  const int cases = 60;
  for (int k = 0; k < cases; ++k) {
    const auto x = make_series({.mean = 1.0, .phi = 0.6, .sigma = 1.0}, n, 300 + k);
    const SeriesStatistics s = series_statistics(x, iota_abscissa(n));
    EXPECT_NEAR(s.drift_standard_error / s.standard_error, std::sqrt(12.0), 0.05);
    const double z = s.drift / s.drift_standard_error;
    sum_z2 += z * z;
  }
  // The drift in units of its standard error has unit variance (within the
  // scatter of a 60-sample variance estimate).
  EXPECT_NEAR(sum_z2 / cases, 1.0, 0.45);
}

// A sine over whole periods has an exact mean; the estimate stays
// conservative (at least the white-noise value), resolved within one period.
// Anti-correlated noise is floored at tau = 1.
TEST(SeriesStatistics, PeriodicAndAntiCorrelatedSeriesStayConservative) {
  const std::size_t n = 10000;
  std::vector<double> sine(n);
  for (std::size_t i = 0; i < n; ++i) sine[i] = 2.0 + std::sin(2.0 * std::numbers::pi * double(i) / 100.0);
  const SeriesStatistics s = series_statistics(sine, iota_abscissa(n));
  EXPECT_NEAR(s.mean, 2.0, 1e-12);
  EXPECT_TRUE(s.autocorrelation_resolved);
  EXPECT_LE(s.autocorrelation_window, 100u);
  EXPECT_GE(s.standard_error, s.std_dev / std::sqrt(double(n)));
  EXPECT_LT(s.standard_error, 0.1 * s.std_dev);

  const auto alternating = make_series({.mean = 0.0, .phi = -0.8, .sigma = 1.0}, n, 3);
  const SeriesStatistics a = series_statistics(alternating, iota_abscissa(n));
  EXPECT_DOUBLE_EQ(a.autocorrelation_time, 1.0);
  EXPECT_GT(a.standard_error, ar1_standard_error(-0.8, 1.0, n));  // conservative
}

TEST(SeriesStatistics, ShortAndTinySeries) {
  const std::vector<double> one{4.5};
  const SeriesStatistics s1 = series_statistics(one, std::vector<double>{0.0});
  EXPECT_TRUE(s1.constant);
  EXPECT_EQ(s1.mean, 4.5);

  const std::vector<double> two{1.0, 3.0};
  const SeriesStatistics s2 = series_statistics(two, std::vector<double>{0.0, 1.0});
  EXPECT_EQ(s2.mean, 2.0);
  EXPECT_EQ(s2.std_dev, 1.0);
  EXPECT_EQ(s2.drift, 2.0);
  EXPECT_GE(s2.standard_error, 1.0 / std::sqrt(2.0));
}

TEST(SeriesStatistics, RefusesBadInput) {
  const std::vector<double> empty;
  EXPECT_THROW(series_statistics(empty, empty), std::invalid_argument);
  EXPECT_THROW(series_statistics(std::vector<double>{1, 2}, std::vector<double>{0}), std::invalid_argument);
  EXPECT_THROW(series_statistics(std::vector<double>{1, 2}, std::vector<double>{1, 1}), std::invalid_argument);
  EXPECT_THROW(series_statistics(std::vector<double>{1, NAN}, std::vector<double>{0, 1}), std::invalid_argument);
  EXPECT_THROW(series_statistics(std::vector<double>{1, 2}, std::vector<double>{0, INFINITY}), std::invalid_argument);
}

TEST(SeriesStatistics, MethodTextNamesTheSettings) {
  StatisticsOptions options;
  options.window_factor = 6;
  options.max_lag = 50;
  const std::string text = standard_error_method(options);
  EXPECT_NE(text.find("Sokal"), std::string::npos);
  EXPECT_NE(text.find("M >= 6 tau"), std::string::npos);
  EXPECT_NE(text.find("50 lags"), std::string::npos);
}

}  // namespace
}  // namespace hydrocoef
