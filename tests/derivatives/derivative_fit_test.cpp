// Fits of derivative models of several variables (src/derivatives/
// derivative_fit.hpp): a thirteen-term cross-coupled sway model over
// (u, v, r, delta) recovered from exact runs; VIFs, the condition number and
// the covariance checked against computations made here with Eigen; designs
// that cannot tell terms apart warned of (and kept) or refused, naming the
// terms; the weighting rule; and every refusal's message.
#include "src/derivatives/derivative_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "tests/derivatives/synthetic_model.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

const DerivativeWarning* find_warning(const DerivativeFit& fit, const std::string& kind) {
  for (const auto& w : fit.warnings)
    if (w.kind == kind) return &w;
  return nullptr;
}

// The raw design X(i, k) = t_k(run i), built here.
Eigen::MatrixXd raw_design(const std::vector<Term>& terms, const std::vector<DerivativeRun>& runs) {
  Eigen::MatrixXd X(static_cast<Eigen::Index>(runs.size()), static_cast<Eigen::Index>(terms.size()));
  for (std::size_t i = 0; i < runs.size(); ++i)
    for (std::size_t k = 0; k < terms.size(); ++k)
      X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = terms[k].evaluate(runs[i].values);
  return X;
}

std::vector<DerivativeRun> sway_runs(std::size_t n, std::uint64_t seed, double noise, const test::Ranges& ranges) {
  std::mt19937_64 random(seed + 1000);
  return test::make_runs(
      parse_terms(test::kSwayTerms), test::kSwayCoefficients, test::latin_hypercube(ranges, n, seed),
      [&](const std::map<std::string, double>&) { return noise; }, random, false);
}

TEST(DerivativeFit, RecoversACrossCoupledModelFromExactRuns) {
  const auto terms = parse_terms(test::kSwayTerms);
  ASSERT_EQ(terms.size(), 13u);
  const auto runs = sway_runs(80, 11, 0.0, test::sway_ranges());
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  ASSERT_EQ(fit.coefficients.size(), terms.size());
  for (std::size_t k = 0; k < terms.size(); ++k)
    EXPECT_NEAR(fit.coefficients[k], test::kSwayCoefficients[k], 1e-10 * std::abs(test::kSwayCoefficients[k]))
        << terms[k].text();
  EXPECT_EQ(fit.n, 80u);
  EXPECT_FALSE(fit.weighted);
  EXPECT_NEAR(fit.r2, 1.0, 1e-15);
  EXPECT_LT(fit.rmse, 1e-10);
  // Student's t_{0.975, 67} = 1.9960 (any table), with n - m = 80 - 13.
  EXPECT_NEAR(fit.interval_factor, 1.9960, 2e-3);
  const std::map<std::string, double> elsewhere = {{"u", 2.2}, {"v", -0.31}, {"r", 0.17}, {"delta", 0.4}};
  double truth = 0.0;
  for (std::size_t k = 0; k < terms.size(); ++k) truth += test::kSwayCoefficients[k] * terms[k].evaluate(elsewhere);
  EXPECT_NEAR(fit.evaluate(elsewhere), truth, 1e-10 * std::abs(truth));
}

// VIF_k = 1/(1 - R_k^2) from the regression of column k on the others (and
// a constant column when the model has one, R^2 then about the mean).
std::vector<double> direct_vifs(const Eigen::MatrixXd& X, bool has_constant_column) {
  std::vector<double> out;
  for (Eigen::Index k = 0; k < X.cols(); ++k) {
    const bool constant = (X.col(k).array() == X(0, k)).all();
    if (constant) {
      out.push_back(std::nan(""));
      continue;
    }
    Eigen::MatrixXd others(X.rows(), X.cols() - 1);
    for (Eigen::Index j = 0, c = 0; j < X.cols(); ++j)
      if (j != k) others.col(c++) = X.col(j);
    const Eigen::VectorXd beta = others.colPivHouseholderQr().solve(X.col(k));
    const double rss = (X.col(k) - others * beta).squaredNorm();
    const double tss =
        has_constant_column ? (X.col(k).array() - X.col(k).mean()).matrix().squaredNorm() : X.col(k).squaredNorm();
    out.push_back(tss / rss);
  }
  return out;
}

TEST(DerivativeFit, VarianceInflationFactorsMatchDirectRegressions) {
  for (const std::string& list : {std::string(test::kSwayTerms), "1, " + std::string(test::kSwayTerms)}) {
    const auto terms = parse_terms(list);
    std::vector<double> coefficients = test::kSwayCoefficients;
    if (terms.size() > coefficients.size()) coefficients.insert(coefficients.begin(), 12.0);
    std::mt19937_64 random(5);
    const auto runs = test::make_runs(
        terms, coefficients, test::latin_hypercube(test::sway_ranges(), 70, 21),
        [](const std::map<std::string, double>&) { return 1.0; }, random, false);
    const DerivativeFit fit = fit_derivatives("Y", terms, runs);
    const bool has_constant = terms.front().is_constant();
    const std::vector<double> expected = direct_vifs(raw_design(terms, runs), has_constant);
    ASSERT_EQ(fit.vif.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      if (std::isnan(expected[k])) {
        EXPECT_TRUE(std::isnan(fit.vif[k])) << "the constant term has no VIF";
        continue;
      }
      EXPECT_NEAR(fit.vif[k], expected[k], 1e-8 * expected[k]) << list << ": " << terms[k].text();
      EXPECT_GE(fit.vif[k], 1.0);
    }
  }
}

TEST(DerivativeFit, ConditionNumberAndCovarianceMatchEigenDirectly) {
  const auto terms = parse_terms(test::kSwayTerms);
  const auto runs = sway_runs(60, 3, 2.0, test::sway_ranges());
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  const Eigen::MatrixXd X = raw_design(terms, runs);
  const Eigen::MatrixXd unit = X * X.colwise().norm().cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(unit);
  const Eigen::VectorXd s = svd.singularValues();
  EXPECT_NEAR(fit.condition_number, s(0) / s(s.size() - 1), 1e-10 * fit.condition_number);

  // Unweighted: s^2 (X^T X)^-1 with s^2 = SSR / (n - m).
  Eigen::VectorXd y(X.rows());
  for (std::size_t i = 0; i < runs.size(); ++i) y(static_cast<Eigen::Index>(i)) = runs[i].output;
  const Eigen::VectorXd c = X.colPivHouseholderQr().solve(y);
  const double s2 = (X * c - y).squaredNorm() / static_cast<double>(X.rows() - X.cols());
  const Eigen::MatrixXd covariance = s2 * (X.transpose() * X).inverse();
  const std::size_t m = terms.size();
  for (std::size_t i = 0; i < m; ++i) {
    EXPECT_NEAR(fit.coefficients[i], c(static_cast<Eigen::Index>(i)), 1e-9 * std::abs(c(static_cast<Eigen::Index>(i))));
    for (std::size_t j = 0; j < m; ++j) {
      const double expected = covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      const double scale = std::sqrt(covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) *
                                     covariance(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)));
      EXPECT_NEAR(fit.covariance[i * m + j], expected, 1e-6 * scale) << i << "," << j;
    }
    EXPECT_DOUBLE_EQ(fit.std_errors[i], std::sqrt(fit.covariance[i * m + i]));
    EXPECT_DOUBLE_EQ(fit.interval_low[i], fit.coefficients[i] - fit.interval_factor * fit.std_errors[i]);
    EXPECT_DOUBLE_EQ(fit.interval_high[i], fit.coefficients[i] + fit.interval_factor * fit.std_errors[i]);
  }
}

TEST(DerivativeFit, WarnsOfTermsANarrowDriftRangeCannotTellApart) {
  // Drift from 0.08 to 0.10 m/s only: over so short a range v^3 is nearly a
  // straight line in v, and with a constant term the two cannot be told apart.
  const auto terms = parse_terms("1, v, v^3, r");
  const std::vector<double> truth = {3.0, -300.0, -400.0, 90.0};
  const auto runs =
      test::exact_runs(terms, truth, test::latin_hypercube({{"v", {0.08, 0.10}}, {"r", {-0.3, 0.3}}}, 40, 8));
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  const DerivativeWarning* warning = find_warning(fit, "collinear-terms");
  ASSERT_NE(warning, nullptr);
  EXPECT_NE(warning->message.find("v (VIF"), std::string::npos) << warning->message;
  EXPECT_NE(warning->message.find("v^3 (VIF"), std::string::npos) << warning->message;
  EXPECT_NE(warning->message.find("with v^3"), std::string::npos) << warning->message;
  EXPECT_EQ(warning->message.find("r (VIF"), std::string::npos) << warning->message;
  EXPECT_NE(warning->message.find("above 10"), std::string::npos);
  EXPECT_NE(warning->message.find("Montgomery, Peck & Vining"), std::string::npos);
  EXPECT_GT(fit.vif[1], 100.0);
  EXPECT_GT(fit.vif[2], 100.0);
  EXPECT_LT(fit.vif[3], 1.5);
  // Kept: the coefficients are still those of the runs.
  for (std::size_t k = 0; k < truth.size(); ++k) EXPECT_NEAR(fit.coefficients[k], truth[k], 1e-7 * std::abs(truth[k]));
}

TEST(DerivativeFit, WarnsOfAnIllConditionedDesignNamingTheTerms) {
  // Every run at u = 2 m/s to within 1e-7: u*v is 2 v to seven digits.
  const auto terms = parse_terms("v, u*v, r");
  const std::vector<double> truth = {-300.0, -45.0, 90.0};
  const auto runs = test::exact_runs(
      terms, truth,
      test::latin_hypercube({{"u", {2.0 - 1e-7, 2.0 + 1e-7}}, {"v", {-0.5, 0.5}}, {"r", {-0.3, 0.3}}}, 30, 4));
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  EXPECT_GT(fit.condition_number, 1e6);
  const DerivativeWarning* warning = find_warning(fit, "ill-conditioned");
  ASSERT_NE(warning, nullptr);
  EXPECT_NE(warning->message.find("a combination of v and u*v,"), std::string::npos) << warning->message;
  EXPECT_NE(warning->message.find("above 1e+06"), std::string::npos) << warning->message;
  ASSERT_NE(find_warning(fit, "collinear-terms"), nullptr);
  for (double c : fit.coefficients) EXPECT_TRUE(std::isfinite(c));
  EXPECT_NEAR(fit.coefficients[2], truth[2], 1e-6 * std::abs(truth[2]));
}

TEST(DerivativeFit, ANarrowSymmetricDriftRangeIsNotIllConditionedOnceColumnsAreScaled) {
  // v and v^3 over -0.02..0.02 m/s: tiny values, but the unit-norm columns
  // correlate as over any symmetric range (about 0.92): no warning.
  const auto terms = parse_terms("v, v^3, r");
  const std::vector<double> truth = {-300.0, -400.0, 90.0};
  const auto runs =
      test::exact_runs(terms, truth, test::latin_hypercube({{"v", {-0.02, 0.02}}, {"r", {-0.3, 0.3}}}, 40, 9));
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  EXPECT_TRUE(fit.warnings.empty());
  EXPECT_LT(fit.condition_number, 20.0);
  EXPECT_LT(fit.vif[0], 10.0);
  for (std::size_t k = 0; k < truth.size(); ++k) EXPECT_NEAR(fit.coefficients[k], truth[k], 1e-10 * std::abs(truth[k]));
}

TEST(DerivativeFit, RefusesTermsTheRunsMakeLinearlyDependent) {
  const auto runs_at = [](double u, std::pair<double, double> v_range) {
    auto points = test::latin_hypercube({{"v", v_range}, {"r", {-0.3, 0.3}}}, 30, 6);
    for (auto& p : points) p["u"] = u;
    return test::exact_runs(parse_terms("v, r"), {-300.0, 90.0}, points);
  };
  expect_input_error(
      [&] {
        fit_derivatives("Y", parse_terms("v, r, u*v"), runs_at(2.0, {-0.5, 0.5}));
      },
      {"the terms v and u*v of the law for Y are linearly dependent over these 30 runs", "(u = 2 at every run)",
       "cannot be told apart"});
  expect_input_error(
      [&] {
        fit_derivatives("Y", parse_terms("u*v, r, v"), runs_at(1.3, {-0.5, 0.5}));
      },
      {"the terms u*v and v", "u = 1.3 at every run"});
  // Drift to one side only: v*|v| is v^2 at every run.
  expect_input_error(
      [&] {
        fit_derivatives("Y", parse_terms("v*|v|, r, v^2"), runs_at(2.0, {0.1, 0.5}));
      },
      {"the terms v*|v| and v^2 of the law for Y are linearly dependent"});
  expect_input_error(
      [&] {
        fit_derivatives("N", parse_terms("v, u*v, r"), runs_at(0.0, {-0.5, 0.5}));
      },
      {"the term u*v of the law for N is zero at every one of the 30 runs (u = 0 at every run)", "cannot be fitted"});
}

TEST(DerivativeFit, RefusesFewerRunsThanTerms) {
  const auto terms = parse_terms("v, r, delta, v^3, v^2*r, v*r^2, r^3, u*v, u*r, u^2*delta, v*|v|, r*|r|");
  ASSERT_EQ(terms.size(), 12u);
  const auto runs = sway_runs(9, 2, 0.0, test::sway_ranges());
  expect_input_error([&] { fit_derivatives("Y", terms, runs); },
                     {"the law for Y has 12 terms and 9 runs; expected at least 12 runs (13 for an uncertainty)"});
  expect_input_error([&] { fit_derivatives("Y", {}, runs); }, {"the law for Y has no terms"});
}

TEST(DerivativeFit, RefusesRunsWithoutANameOrWithValuesThatAreNotFinite) {
  const auto terms = parse_terms(test::kSwayTerms);
  auto runs = sway_runs(30, 2, 0.0, test::sway_ranges());
  auto missing = runs;
  missing[3].values.erase("delta");
  expect_input_error([&] { fit_derivatives("Y", terms, missing); },
                     {"run 4 has no value of delta, which the term delta of the law for Y needs",
                      "expected every run to give u, v, r and delta"});
  missing[3].label = "run 17 (tank)";
  expect_input_error([&] { fit_derivatives("Y", terms, missing); }, {"run 17 (tank) has no value of delta"});
  auto bad_value = runs;
  bad_value[6].values["v"] = std::nan("");
  expect_input_error([&] { fit_derivatives("Y", terms, bad_value); }, {"run 7 has v = nan", "expected finite values"});
  auto bad_output = runs;
  bad_output[2].output = std::numeric_limits<double>::infinity();
  expect_input_error([&] { fit_derivatives("Y", terms, bad_output); }, {"run 3 has Y = inf"});
  auto bad_sigma = runs;
  bad_sigma[4].sigma = -1.0;
  expect_input_error([&] { fit_derivatives("Y", terms, bad_sigma); },
                     {"run 5 states the uncertainty -1 of Y", "expected a finite uncertainty > 0, or none"});
  auto huge = runs;
  huge[8].values["v"] = 1e200;
  expect_input_error([&] { fit_derivatives("Y", terms, huge); }, {"the term v^3 of the law for Y is inf at run 9"});
}

TEST(DerivativeFit, WeightedAndUnweightedFitsAgreeWhenEveryRunStatesOneUncertainty) {
  const auto terms = parse_terms(test::kSwayTerms);
  const auto noisy = [](bool state) {
    std::mt19937_64 random(99);
    return test::make_runs(
        parse_terms(test::kSwayTerms), test::kSwayCoefficients, test::latin_hypercube(test::sway_ranges(), 50, 17),
        [](const std::map<std::string, double>&) { return 0.5; }, random, state);
  };
  const DerivativeFit plain = fit_derivatives("Y", terms, noisy(false));
  const DerivativeFit weighted = fit_derivatives("Y", terms, noisy(true));
  EXPECT_FALSE(plain.weighted);
  EXPECT_TRUE(weighted.weighted);
  ASSERT_TRUE(std::isfinite(weighted.chi2_reduced));
  EXPECT_TRUE(std::isnan(plain.chi2_reduced));
  const std::size_t m = terms.size();
  // Both minimize the same sum; the covariances differ by S^2 / s^2 =
  // max(1, chi2) / chi2, s^2 = chi2 sigma^2 being the residual variance.
  const double ratio = std::max(1.0, weighted.chi2_reduced) / weighted.chi2_reduced;
  for (std::size_t k = 0; k < m; ++k) {
    EXPECT_NEAR(weighted.coefficients[k], plain.coefficients[k], 1e-9 * std::abs(plain.coefficients[k]));
    EXPECT_NEAR(weighted.covariance[k * m + k], plain.covariance[k * m + k] * ratio,
                1e-9 * weighted.covariance[k * m + k]);
  }
  EXPECT_DOUBLE_EQ(weighted.covariance_scale, std::max(1.0, weighted.chi2_reduced));
  EXPECT_EQ(weighted.interval_factor == plain.interval_factor, weighted.chi2_reduced > 1.0);
}

TEST(DerivativeFit, RunsThatStateNoUncertaintyLeaveTheFitUnweightedWithAWarning) {
  const auto terms = parse_terms(test::kSwayTerms);
  auto runs = sway_runs(40, 23, 0.0, test::sway_ranges());
  for (auto& run : runs) run.sigma = 0.5;
  runs[2].sigma = std::nan("");
  runs[8].sigma = std::nan("");
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  EXPECT_FALSE(fit.weighted);
  const DerivativeWarning* warning = find_warning(fit, "unweighted");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->message, "2 of the 40 runs state no uncertainty of Y (run 3 and run 9): fitted unweighted");
  DerivativeFitOptions options;
  options.use_uncertainties = false;
  for (auto& run : runs) run.sigma = 0.5;
  const DerivativeFit asked_plain = fit_derivatives("Y", terms, runs, options);
  EXPECT_FALSE(asked_plain.weighted);
  EXPECT_EQ(find_warning(asked_plain, "unweighted"), nullptr);
}

TEST(DerivativeFit, UnderstatedUncertaintiesScaleTheCovarianceByTheBirgeRatio) {
  const auto terms = parse_terms(test::kSwayTerms);
  std::mt19937_64 random(7);
  auto runs = test::make_runs(
      terms, test::kSwayCoefficients, test::latin_hypercube(test::sway_ranges(), 60, 31),
      [](const std::map<std::string, double>&) { return 1.0; }, random, true);
  for (auto& run : runs) run.sigma = 0.1;  // ten times too small
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  EXPECT_TRUE(fit.weighted);
  EXPECT_NEAR(fit.chi2_reduced, 100.0, 40.0);
  EXPECT_DOUBLE_EQ(fit.covariance_scale, fit.chi2_reduced);
  EXPECT_NE(find_warning(fit, "scatter-exceeds-uncertainty"), nullptr);
  EXPECT_NEAR(fit.interval_factor, 2.0117, 2e-3);  // t_{0.975, 47}
  for (auto& run : runs) run.sigma = 10.0;         // ten times too large: not scaled down
  const DerivativeFit loose = fit_derivatives("Y", terms, runs);
  EXPECT_DOUBLE_EQ(loose.covariance_scale, 1.0);
  EXPECT_NE(find_warning(loose, "scatter-below-uncertainty"), nullptr);
  EXPECT_DOUBLE_EQ(loose.interval_factor, 1.959963984540054);
}

TEST(DerivativeFit, AsManyRunsAsTermsFitExactlyWithoutAnUncertainty) {
  const auto terms = parse_terms(test::kSwayTerms);
  const auto runs = sway_runs(13, 41, 0.0, test::sway_ranges());
  const DerivativeFit fit = fit_derivatives("Y", terms, runs);
  for (std::size_t k = 0; k < terms.size(); ++k) {
    EXPECT_NEAR(fit.coefficients[k], test::kSwayCoefficients[k], 1e-8 * std::abs(test::kSwayCoefficients[k]));
    EXPECT_TRUE(std::isnan(fit.std_errors[k]));
  }
  EXPECT_TRUE(std::isnan(fit.interval_factor));
}

}  // namespace
}  // namespace hydrocoef
