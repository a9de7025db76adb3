// A force history reduced to a run (src/history/history_analysis), on
// synthetic histories with a known truth: 200 seeded exponential start-ups
// with AR(1) noise, whose true mean must fall inside mean +- 1.96 SE in 90-98 %
// of the cases and whose standard error must be within 20 % of the exact one;
// a drifting history, a start-up that never ends, a constant, too few
// effective samples and uneven time steps flagged; given windows (T0:T1, last
// N) and their refusals; the components that decide the window; parts.
#include "src/history/history_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "tests/history/synthetic_history.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::ar1_standard_error;
using test::iota_abscissa;
using test::make_series;
using test::SyntheticSeries;

ForceHistory history_of(std::vector<double> fx, std::vector<double> t = {}) {
  ForceHistory h;
  if (t.empty()) t = iota_abscissa(fx.size());
  h.abscissa = HistoryAbscissa::Iteration;
  h.abscissa_values = std::move(t);
  h.values(ForcePart::Total, HistoryComponent::Fx) = std::move(fx);
  return h;
}

const SeriesStatistics& fx_total(const HistoryAnalysis& a) {
  return a.components[static_cast<std::size_t>(HistoryComponent::Fx)].total();
}

// The acceptance test of the issue: exponential start-up + AR(1) noise of
// known autocorrelation, 200 seeded cases with different start-ups and
// correlations.
TEST(HistoryAnalysis, TrueMeanInsideTheStatedIntervalAndErrorWithinTwentyPerCent) {
  const int cases = 200;
  const std::size_t n = 40000;
  int covered = 0;
  int drifting = 0;
  int literal_drift = 0;
  double ratio_sum = 0.0;
  double worst_ratio_error = 0.0;
  double worst_bias = 0.0;
  int needed_cut = 0;
  for (int k = 0; k < cases; ++k) {
    SyntheticSeries spec;
    spec.phi = 0.3 + 0.6 * (k % 20) / 19.0;                                  // tau_int from 1.9 to 19
    spec.sigma = 0.01 * (1 + k % 7);                                         // N
    spec.mean = 0.5 - 0.01 * k;                                              // N
    const double sigma_x = spec.sigma / std::sqrt(1 - spec.phi * spec.phi);  // N
    spec.startup = (k % 2 == 0 ? 1 : -1) * (5 + k % 11) * sigma_x;
    spec.startup_decay = 50.0 + 25.0 * (k % 9);  // samples
    const auto x = make_series(spec, n, 20240 + k);
    const HistoryAnalysis a = analyze_force_history(history_of(x));
    const SeriesStatistics& s = fx_total(a);

    const double truth = ar1_standard_error(spec.phi, spec.sigma, a.sample_count);
    // What the window keeps of the start-up biases the mean by less than its
    // standard error. (MSER stops cutting where what is left of the start-up
    // is about one standard deviation of the noise; the bias that leaves,
    // about sigma_x tau_startup / n, is a fraction of the standard error.
    // Without the cut it would exceed 2 standard errors in most cases.)
    const double decay = std::exp(-1.0 / spec.startup_decay);
    const double kept = spec.startup * std::exp(-double(a.first_sample) / spec.startup_decay) / (1.0 - decay);
    const double bias_in_errors = std::abs(kept) / double(a.sample_count) / truth;
    EXPECT_LT(bias_in_errors, 1.0) << "case " << k << ": window starts at " << a.first_sample;
    worst_bias = std::max(worst_bias, bias_in_errors);
    const double uncut =
        std::abs(spec.startup) / (1.0 - decay) / double(n) / ar1_standard_error(spec.phi, spec.sigma, n);
    if (uncut > 2.0) ++needed_cut;
    EXPECT_GT(a.first_sample, 0u) << "case " << k;
    EXPECT_FALSE(a.flags.no_steady_window) << "case " << k;
    EXPECT_FALSE(a.flags.too_few_effective_samples) << "case " << k;

    if (std::abs(s.mean - spec.mean) <= 1.96 * s.standard_error) ++covered;
    const double ratio = s.standard_error / truth;
    EXPECT_NEAR(ratio, 1.0, 0.2) << "case " << k << " phi " << spec.phi;
    ratio_sum += ratio;
    worst_ratio_error = std::max(worst_ratio_error, std::abs(ratio - 1.0));
    if (a.flags.drifting) ++drifting;
    if (a.components[0].drift_exceeds_standard_error) ++literal_drift;
  }
  const double coverage = double(covered) / cases;
  EXPECT_GE(coverage, 0.90);
  EXPECT_LE(coverage, 0.98);
  EXPECT_NEAR(ratio_sum / cases, 1.0, 0.05);
  EXPECT_GT(needed_cut, cases / 2);  // the start-ups matter: the window had to cut them
  // Stationary after the start-up: the drift test (3 standard errors of the
  // drift) rarely fires; the literal |drift| > SE(mean) fires most of the time.
  EXPECT_LE(drifting, 4);
  EXPECT_GT(literal_drift, cases / 2);
  RecordProperty("coverage", std::to_string(coverage));
  RecordProperty("worst_standard_error_ratio_error", std::to_string(worst_ratio_error));
  RecordProperty("drifting_flags", std::to_string(drifting));
  std::printf(
      "coverage %.3f, mean SE ratio %.4f, worst |ratio - 1| %.3f, worst start-up bias %.2f SE (%d of %d "
      "cases over 2 SE uncut), drifting flags %d, |drift| > SE %d\n",
      coverage, ratio_sum / cases, worst_ratio_error, worst_bias, needed_cut, cases, drifting, literal_drift);
}

TEST(HistoryAnalysis, ADriftingHistoryIsFlagged) {
  // Settled start-up, then a slow linear drift of 3 % of the mean over the
  // record, buried in noise a sample at a time.
  SyntheticSeries spec{
      .mean = 1.0, .startup = 0.5, .startup_decay = 100.0, .phi = 0.5, .sigma = 0.01, .slope = -1.5e-6};
  const auto x = make_series(spec, 20000, 77);
  const HistoryAnalysis automatic = analyze_force_history(history_of(x));
  EXPECT_TRUE(automatic.flags.drifting || automatic.flags.no_steady_window);
  EXPECT_TRUE(automatic.flags.not_converged());

  HistoryAnalysisOptions last_half;
  last_half.window = HistoryWindow::last_samples(10000);
  const HistoryAnalysis given = analyze_force_history(history_of(x), last_half);
  EXPECT_TRUE(given.flags.drifting);
  EXPECT_FALSE(given.flags.no_steady_window);  // a given window is not judged by MSER
  EXPECT_NEAR(fx_total(given).drift_slope, -1.5e-6, 0.3e-6);
  bool noted = false;
  for (const auto& note : given.notes) noted = noted || note.find("Fx drifts by") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_EQ(flag_names(given.flags), std::vector<std::string>{"drifting"});
}

TEST(HistoryAnalysis, AStartUpWithNoSteadyPartIsFlagged) {
  SyntheticSeries spec{.mean = 0.2, .startup = 1.0, .startup_decay = 6000.0, .phi = 0.5, .sigma = 1e-3};
  const auto x = make_series(spec, 8000, 78);
  const HistoryAnalysis a = analyze_force_history(history_of(x));
  EXPECT_TRUE(a.flags.no_steady_window);
  EXPECT_TRUE(a.flags.not_converged());
  bool noted = false;
  for (const auto& note : a.notes) noted = noted || note.find("Fx: no steady window") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(HistoryAnalysis, ConstantHistoryHasNoErrorAndNoFlags) {
  const HistoryAnalysis a = analyze_force_history(history_of(std::vector<double>(500, 0.27)));
  const SeriesStatistics& s = fx_total(a);
  EXPECT_EQ(s.mean, 0.27);
  EXPECT_EQ(s.standard_error, 0.0);
  EXPECT_EQ(s.std_dev, 0.0);
  EXPECT_TRUE(s.constant);
  EXPECT_FALSE(a.flags.any());
  EXPECT_EQ(a.first_sample, 0u);
  EXPECT_EQ(a.sample_count, 500u);
}

TEST(HistoryAnalysis, ShortRecordsAreTooShortToFindAWindow) {
  const auto x = make_series({.mean = 1.0, .phi = 0.0, .sigma = 0.1}, 60, 1);
  const HistoryAnalysis a = analyze_force_history(history_of(x));
  EXPECT_TRUE(a.flags.no_steady_window);
  EXPECT_EQ(a.sample_count, 60u);
  bool noted = false;
  for (const auto& note : a.notes) noted = noted || note.find("too short") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(HistoryAnalysis, StronglyCorrelatedShortWindowHasTooFewEffectiveSamples) {
  // tau ~ 199 on 2000 samples: about 10 independent samples.
  const auto x = make_series({.mean = 1.0, .phi = 0.99, .sigma = 0.01}, 2000, 2);
  HistoryAnalysisOptions options;
  options.window = HistoryWindow::last_samples(2000);
  const HistoryAnalysis a = analyze_force_history(history_of(x), options);
  EXPECT_TRUE(a.flags.too_few_effective_samples);
}

TEST(HistoryAnalysis, GivenRangeIsInclusiveAndInAbscissaUnits) {
  std::vector<double> x(1000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = double(i + 1);  // value = iteration
  HistoryAnalysisOptions options;
  options.window = HistoryWindow::range(601, 1000);
  const HistoryAnalysis a = analyze_force_history(history_of(x), options);
  EXPECT_EQ(a.first_sample, 600u);
  EXPECT_EQ(a.sample_count, 400u);
  EXPECT_EQ(a.first_abscissa, 601.0);
  EXPECT_EQ(a.last_abscissa, 1000.0);
  EXPECT_DOUBLE_EQ(fx_total(a).mean, 800.5);
  EXPECT_EQ(a.window_method, "range 601:1000");
  EXPECT_EQ(a.window_kind, HistoryWindow::Kind::Range);

  options.window = HistoryWindow::range(990.5, INFINITY);
  const HistoryAnalysis open = analyze_force_history(history_of(x), options);
  EXPECT_EQ(open.sample_count, 10u);
  EXPECT_EQ(open.window_method, "range 990.5:");
}

TEST(HistoryAnalysis, GivenWindowsThatDoNotFitAreRefused) {
  const auto h = history_of(std::vector<double>(100, 1.0));
  HistoryAnalysisOptions options;
  options.window = HistoryWindow::range(200, 300);
  test::expect_input_error(
      [&] { analyze_force_history(h, options); },
      {"range 200:300", "holds 0 samples", "100 samples from iteration 1 to iteration 100", "expected at least 2"});
  options.window = HistoryWindow::range(50, 50);
  test::expect_input_error([&] { analyze_force_history(h, options); }, {"holds 1 sample "});
  options.window = HistoryWindow::last_samples(101);
  test::expect_input_error([&] { analyze_force_history(h, options); },
                           {"last 101 samples does not fit", "expected 2 to 100"});
  options.window = HistoryWindow::last_samples(1);
  EXPECT_THROW(analyze_force_history(h, options), InputError);

  ForceHistory empty;
  empty.abscissa_values = {1, 2, 3};
  test::expect_input_error([&] { analyze_force_history(empty); }, {"no total force or moment"});
}

TEST(HistoryAnalysis, AGivenWindowBeforeTheStartUpEndsIsNoted) {
  const auto x =
      make_series({.mean = 0.0, .startup = 50.0, .startup_decay = 200.0, .phi = 0.0, .sigma = 1.0}, 10000, 9);
  HistoryAnalysisOptions options;
  options.window = HistoryWindow::last_samples(9990);
  const HistoryAnalysis a = analyze_force_history(history_of(x), options);
  bool noted = false;
  for (const auto& note : a.notes)
    noted = noted || note.find("starts before MSER-5 ends the start-up of Fx") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(HistoryAnalysis, UnevenTimeStepsAreFlagged) {
  const std::size_t n = 2000;
  std::vector<double> t(n);
  double time = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = time;
    time += i < n / 2 ? 1e-3 : 2e-3;  // the time step doubles half way
  }
  auto h = history_of(make_series({.mean = 1.0, .phi = 0.0, .sigma = 0.1}, n, 4), t);
  h.abscissa = HistoryAbscissa::Time;
  const HistoryAnalysis a = analyze_force_history(h);
  EXPECT_TRUE(a.flags.uneven_sampling);
  EXPECT_FALSE(a.flags.not_converged());

  auto even = history_of(make_series({.mean = 1.0, .phi = 0.0, .sigma = 0.1}, n, 4), iota_abscissa(n, 0.0, 0.1));
  EXPECT_FALSE(analyze_force_history(even).flags.uneven_sampling);  // 0.1 steps with rounding are even
}

TEST(HistoryAnalysis, DecidingComponentsSetTheWindowAndTheRunFlags) {
  const std::size_t n = 5000;
  ForceHistory h =
      history_of(make_series({.mean = 1.0, .startup = 0.1, .startup_decay = 100.0, .phi = 0.0, .sigma = 0.01}, n, 1));
  // Mz never settles (a trend); Fx settles early.
  h.values(ForcePart::Total, HistoryComponent::Mz) =
      make_series({.mean = 0.0, .phi = 0.0, .sigma = 1e-4, .slope = 1e-5}, n, 2);
  const HistoryAnalysis all = analyze_force_history(h);
  EXPECT_TRUE(all.flags.no_steady_window);
  EXPECT_TRUE(all.components[5].flags.no_steady_window);

  HistoryAnalysisOptions forces_only;
  forces_only.deciding_components = {true, true, true, false, false, false};
  const HistoryAnalysis a = analyze_force_history(h, forces_only);
  EXPECT_FALSE(a.flags.not_converged());
  EXPECT_EQ(a.window_set_by, HistoryComponent::Fx);
  EXPECT_TRUE(a.components[5].flags.no_steady_window);  // still on the component itself
  EXPECT_TRUE(a.components[5].present);
  EXPECT_FALSE(a.components[1].present);
  EXPECT_LT(a.first_sample, n / 4);
}

TEST(HistoryAnalysis, PartsGetTheirOwnStatisticsOverTheSameWindow) {
  const std::size_t n = 3000;
  auto pressure = make_series({.mean = 0.8, .phi = 0.7, .sigma = 0.01}, n, 10);
  auto viscous = make_series({.mean = 0.1, .phi = 0.2, .sigma = 0.001}, n, 11);
  std::vector<double> total(n);
  for (std::size_t i = 0; i < n; ++i) total[i] = pressure[i] + viscous[i];
  ForceHistory h = history_of(total);
  h.values(ForcePart::Pressure, HistoryComponent::Fx) = pressure;
  h.values(ForcePart::Viscous, HistoryComponent::Fx) = viscous;
  HistoryAnalysisOptions options;
  options.window = HistoryWindow::range(1001, 3000);
  const HistoryAnalysis a = analyze_force_history(h, options);
  const ComponentAnalysis& fx = a.components[0];
  ASSERT_TRUE(fx.parts[1] && fx.parts[2]);
  EXPECT_FALSE(fx.parts[3]);
  EXPECT_EQ(fx.parts[1]->count, 2000u);
  EXPECT_NEAR(fx.total().mean, fx.parts[1]->mean + fx.parts[2]->mean, 1e-14);
  EXPECT_GT(fx.parts[1]->standard_error, fx.parts[2]->standard_error);
}

TEST(HistoryAnalysis, RefusesAHistoryThatBreaksItsInvariants) {
  ForceHistory h = history_of({1.0, 2.0, 3.0}, {0.0, 2.0, 1.0});
  EXPECT_THROW(analyze_force_history(h), std::invalid_argument);
  ForceHistory short_series = history_of({1.0, 2.0, 3.0});
  short_series.values(ForcePart::Total, HistoryComponent::Fy) = {1.0};
  EXPECT_THROW(analyze_force_history(short_series), std::invalid_argument);
}

// --- the run's convergence kind and a window per component ------------------

ConvergenceEvidence met_at(double iteration, double rate) {
  ConvergenceEvidence e;
  e.solver = SolverKind::Steady;
  e.solver_source = "system/fvSchemes:20: ddtSchemes default steadyState";
  e.criteria_stated = true;
  e.criteria_source = "system/fvSolution:40: SIMPLE residualControl p 0.0001";
  e.criteria_met_at = iteration;
  e.residuals_source = "postProcessing/solverInfo/0/solverInfo.dat:147";
  e.residual_rate = rate;
  return e;
}

TEST(HistoryAnalysis, AConvergedSteadyRunStoresItsFinalIterateWithItsIterativeError) {
  // Geometric convergence to 0.5 at rate 0.97 per iteration, stopped at 300.
  const std::size_t n = 300;
  std::vector<double> fx(n);
  for (std::size_t i = 0; i < n; ++i) fx[i] = 0.5 + 0.2 * std::pow(0.97, static_cast<double>(i));
  ForceHistory h = history_of(fx, iota_abscissa(n, 1.0));
  h.values(ForcePart::Total, HistoryComponent::Mz) = std::vector<double>(n, 1e-9);  // zero by symmetry
  HistoryAnalysisOptions options;
  options.evidence = met_at(static_cast<double>(n), 0.97);
  const HistoryAnalysis a = analyze_force_history(h, options);
  EXPECT_EQ(a.convergence, RunConvergence::Converged);
  EXPECT_EQ(convergence_name(a.convergence), "converged");
  EXPECT_NE(a.convergence_reason.find("solverInfo.dat:147"), std::string::npos) << a.convergence_reason;
  EXPECT_NE(a.convergence_reason.find("fvSolution:40"), std::string::npos) << a.convergence_reason;
  const ComponentAnalysis& x = a.components[0];
  EXPECT_EQ(x.total().mean, fx.back());
  EXPECT_EQ(x.sample_count, 1u);
  EXPECT_EQ(x.last_abscissa, static_cast<double>(n));
  const double truth = fx.back() - 0.5;
  EXPECT_GE(x.total().standard_error, truth);
  // At most the change over the last quarter (75 iterations: 0.97^-75 - 1 = 8.8 times the error).
  EXPECT_LE(x.total().standard_error, 9.0 * truth);
  EXPECT_FALSE(a.flags.any());
  EXPECT_TRUE(a.components[5].negligible);
  EXPECT_FALSE(a.components[5].flags.any());

  // The same record without the solver's word is a steady window: its mean
  // is not the final iterate.
  const HistoryAnalysis plain = analyze_force_history(h);
  EXPECT_EQ(plain.convergence, RunConvergence::SteadyWindow);
  EXPECT_NE(plain.components[0].total().mean, fx.back());
  // Criteria met at another iteration than the record's last: not converged.
  options.evidence = met_at(static_cast<double>(n - 10), 0.97);
  EXPECT_EQ(analyze_force_history(h, options).convergence, RunConvergence::SteadyWindow);
  // A given window overrides the evidence.
  options.evidence = met_at(static_cast<double>(n), 0.97);
  options.window = HistoryWindow::last_samples(50);
  const HistoryAnalysis given = analyze_force_history(h, options);
  EXPECT_EQ(given.convergence, RunConvergence::GivenWindow);
  EXPECT_EQ(given.components[0].sample_count, 50u);
}

TEST(HistoryAnalysis, EachComponentHasItsOwnWindow) {
  // Fx settles at once; Fy has a long start-up. Fy's window must not cut
  // Fx's, and a negligible Mz (round-off noise) sets nothing and is not
  // flagged.
  const std::size_t n = 4000;
  ForceHistory h = history_of(make_series({.mean = 1.0, .phi = 0.0, .sigma = 0.01}, n, 21));
  h.values(ForcePart::Total, HistoryComponent::Fy) =
      make_series({.mean = 0.3, .startup = 0.5, .startup_decay = 150.0, .phi = 0.0, .sigma = 0.01}, n, 22);
  std::vector<double> mz = make_series({.mean = 0.0, .phi = 0.0, .sigma = 1e-7, .slope = 1e-10}, n, 23);
  h.values(ForcePart::Total, HistoryComponent::Mz) = mz;
  const HistoryAnalysis a = analyze_force_history(h);
  const ComponentAnalysis& fx = a.components[0];
  const ComponentAnalysis& fy = a.components[1];
  EXPECT_LT(fx.first_sample, 200u);
  EXPECT_GT(fy.first_sample, 300u);
  EXPECT_EQ(fx.sample_count, n - fx.first_sample);
  EXPECT_EQ(fx.total().count, fx.sample_count);
  EXPECT_EQ(a.window_set_by, HistoryComponent::Fy);
  EXPECT_EQ(a.first_sample, fy.first_sample);
  EXPECT_TRUE(a.components[5].negligible);
  EXPECT_FALSE(a.components[5].flags.any());
  EXPECT_FALSE(a.flags.not_converged());
  // Fx's mean is over its own window: the mean of those samples.
  double sum = 0.0;
  const auto& x = h.values(ForcePart::Total, HistoryComponent::Fx);
  for (std::size_t i = fx.first_sample; i < n; ++i) sum += x[i];
  EXPECT_NEAR(fx.total().mean, sum / static_cast<double>(n - fx.first_sample), 1e-13);
}

TEST(HistoryAnalysis, ARecordOverTimeIsATransientWindow) {
  const std::size_t n = 2000;
  ForceHistory h =
      history_of(make_series({.mean = 1.0, .phi = 0.5, .sigma = 0.01}, n, 31), iota_abscissa(n, 0.0, 0.01));
  h.abscissa = HistoryAbscissa::Time;
  const HistoryAnalysis a = analyze_force_history(h);
  EXPECT_EQ(a.convergence, RunConvergence::TransientWindow);
  // Criteria "met" on a record over time are not a converged steady run.
  HistoryAnalysisOptions options;
  options.evidence = met_at(h.abscissa_values.back(), 0.9);
  EXPECT_EQ(analyze_force_history(h, options).convergence, RunConvergence::TransientWindow);
}

TEST(HistoryAnalysis, MissedCriteriaAreSaidWithTheirEvidence) {
  const std::size_t n = 1000;
  ForceHistory h = history_of(make_series({.mean = 1.0, .phi = 0.5, .sigma = 0.01}, n, 41), iota_abscissa(n, 1.0));
  HistoryAnalysisOptions options;
  ConvergenceEvidence e = met_at(1000.0, 0.99);
  e.criteria_met_at.reset();
  e.criteria_missed = "initial residuals at 1000: p 0.003 (tolerance 0.0001)";
  options.evidence = e;
  const HistoryAnalysis a = analyze_force_history(h, options);
  EXPECT_EQ(a.convergence, RunConvergence::SteadyWindow);
  EXPECT_NE(a.convergence_reason.find("p 0.003 (tolerance 0.0001)"), std::string::npos) << a.convergence_reason;
}

}  // namespace
}  // namespace hydrocoef
