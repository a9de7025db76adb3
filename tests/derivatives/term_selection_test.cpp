// Term selection by cross-validation (src/derivatives/term_selection.hpp):
// from the thirteen candidate terms of the sway model, runs of a sparse model
// (four of them) with small noise lead backward elimination and the
// one-standard-error rule to exactly the true terms, by leave-one-out and by
// seeded 5-fold cross-validation, weighted or not; the path and its errors
// are reported; the leave-one-out errors are those of fits made without
// each run (and k-fold with one run per fold gives them too); the same seed
// gives the same selection; too few runs are refused.
#include "src/derivatives/term_selection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/derivatives/derivative_fit.hpp"
#include "tests/derivatives/synthetic_model.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

std::set<std::string> texts(const std::vector<Term>& terms) {
  std::set<std::string> out;
  for (const auto& t : terms) out.insert(t.text());
  return out;
}

// Y = -310 v + 95 r - 520 v*|v| + 38 u^2*delta, with noise of 0.5 N (the
// outputs reach about 200 N).
std::vector<DerivativeRun> sparse_runs(std::size_t n, std::uint64_t seed) {
  const auto truth = parse_terms("v, r, v*|v|, u^2*delta");
  std::mt19937_64 random(seed + 17);
  return test::make_runs(
      truth, {-310.0, 95.0, -520.0, 38.0}, test::latin_hypercube(test::sway_ranges(), n, seed),
      [](const std::map<std::string, double>&) { return 0.5; }, random, false);
}

const std::set<std::string> kTrueTerms = {"v", "r", "v*|v|", "u^2*delta"};

void expect_path_is_reported(const TermSelection& selection, std::size_t candidates) {
  ASSERT_EQ(selection.steps.size(), candidates);
  EXPECT_EQ(selection.steps.front().terms.size(), candidates);
  EXPECT_EQ(selection.steps.front().removed, "");
  for (std::size_t k = 1; k < selection.steps.size(); ++k) {
    const auto& step = selection.steps[k];
    EXPECT_EQ(step.terms.size(), candidates - k);
    // The removed term was in the previous set and is not in this one.
    EXPECT_EQ(texts(selection.steps[k - 1].terms).count(step.removed), 1u);
    EXPECT_EQ(texts(step.terms).count(step.removed), 0u);
    EXPECT_GT(step.cv_error, 0.0);
  }
  for (const auto& step : selection.steps) EXPECT_GE(step.cv_error, selection.steps[selection.best_step].cv_error);
  // The one-standard-error rule: the chosen set is within one standard
  // error of the least, and every smaller set on the path is not.
  const auto& best = selection.steps[selection.best_step];
  EXPECT_LE(selection.steps[selection.chosen_step].cv_error, best.cv_error + best.cv_standard_error);
  for (std::size_t k = selection.chosen_step + 1; k < selection.steps.size(); ++k)
    EXPECT_GT(selection.steps[k].cv_error, best.cv_error + best.cv_standard_error);
  EXPECT_GE(selection.chosen_step, selection.best_step);
  EXPECT_EQ(texts(selection.chosen), texts(selection.steps[selection.chosen_step].terms));
}

TEST(TermSelection, LeaveOneOutRecoversTheTrueTermsOfASparseModel) {
  const auto candidates = parse_terms(test::kSwayTerms);
  const auto runs = sparse_runs(80, 5);
  const TermSelection selection = select_terms("Y", candidates, runs);
  EXPECT_EQ(texts(selection.chosen), kTrueTerms);
  expect_path_is_reported(selection, candidates.size());
  EXPECT_EQ(selection.method, "leave-one-out cross-validation, backward elimination, one-standard-error rule");
  // With the true terms, the prediction error is about the noise's variance.
  EXPECT_NEAR(selection.steps[selection.chosen_step].cv_error, 0.25, 0.12);
  // Dropping a true term costs far more than the noise.
  ASSERT_LT(selection.chosen_step + 1, selection.steps.size());
  EXPECT_GT(selection.steps[selection.chosen_step + 1].cv_error, 10.0);
}

TEST(TermSelection, SeededFiveFoldCrossValidationRecoversThemToo) {
  const auto candidates = parse_terms(test::kSwayTerms);
  const auto runs = sparse_runs(80, 12);
  TermSelectionOptions options;
  options.folds = 5;
  options.seed = 42;
  const TermSelection selection = select_terms("Y", candidates, runs, options);
  EXPECT_EQ(texts(selection.chosen), kTrueTerms);
  expect_path_is_reported(selection, candidates.size());
  EXPECT_EQ(selection.method, "5-fold cross-validation (seed 42), backward elimination, one-standard-error rule");
  // Deterministic: the same seed gives the same path, number for number.
  const TermSelection again = select_terms("Y", candidates, runs, options);
  ASSERT_EQ(again.steps.size(), selection.steps.size());
  for (std::size_t k = 0; k < again.steps.size(); ++k) {
    EXPECT_EQ(again.steps[k].removed, selection.steps[k].removed);
    EXPECT_EQ(again.steps[k].cv_error, selection.steps[k].cv_error);
  }
}

TEST(TermSelection, LeaveOneOutErrorsAreThoseOfFitsWithoutEachRun) {
  const auto candidates = parse_terms(test::kSwayTerms);
  const auto runs = sparse_runs(40, 8);
  const TermSelection selection = select_terms("Y", candidates, runs);
  // Step 0 (every candidate) and the chosen step, refitted here run by run.
  for (const std::size_t step : {std::size_t{0}, selection.chosen_step}) {
    const auto& terms = selection.steps[step].terms;
    double sum = 0.0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      std::vector<DerivativeRun> others = runs;
      others.erase(others.begin() + static_cast<std::ptrdiff_t>(i));
      const double e = fit_derivatives("Y", terms, others).evaluate(runs[i].values) - runs[i].output;
      sum += e * e;
    }
    const double expected = sum / static_cast<double>(runs.size());
    EXPECT_NEAR(selection.steps[step].cv_error, expected, 1e-8 * expected) << "step " << step;
  }
  // k-fold with one run per fold is leave-one-out, whatever the shuffle.
  TermSelectionOptions options;
  options.folds = runs.size();
  const TermSelection folds = select_terms("Y", candidates, runs, options);
  EXPECT_NEAR(folds.steps[0].cv_error, selection.steps[0].cv_error, 1e-8 * selection.steps[0].cv_error);
}

TEST(TermSelection, WeightedErrorsAreInUnitsOfTheRunsUncertainties) {
  const auto truth = parse_terms("v, r, v*|v|, u^2*delta");
  std::mt19937_64 random(77);
  // sigma from 0.2 to 2.2 N, each run stating its own.
  const auto runs = test::make_runs(
      truth, {-310.0, 95.0, -520.0, 38.0}, test::latin_hypercube(test::sway_ranges(), 80, 19),
      [](const std::map<std::string, double>& p) { return 0.2 + 4.0 * std::abs(p.at("v")); }, random, true);
  const TermSelection selection = select_terms("Y", parse_terms(test::kSwayTerms), runs);
  EXPECT_TRUE(selection.weighted);
  EXPECT_EQ(texts(selection.chosen), kTrueTerms);
  // Residuals over sigma: about 1 in mean square for the true terms.
  EXPECT_NEAR(selection.steps[selection.chosen_step].cv_error, 1.0, 0.4);
}

TEST(TermSelection, WithoutTheRuleTheLeastErrorSetKeepsTheTrueTerms) {
  const auto candidates = parse_terms(test::kSwayTerms);
  TermSelectionOptions options;
  options.one_standard_error = false;
  const TermSelection selection = select_terms("Y", candidates, sparse_runs(80, 5), options);
  EXPECT_EQ(selection.chosen_step, selection.best_step);
  const auto chosen = texts(selection.chosen);
  for (const auto& t : kTrueTerms) EXPECT_EQ(chosen.count(t), 1u) << t;
}

TEST(TermSelection, RefusesTooFewRunsAndBadFolds) {
  const auto candidates = parse_terms(test::kSwayTerms);
  expect_input_error([&] { select_terms("Y", candidates, sparse_runs(13, 1)); },
                     {"leave-one-out cross-validation of the 13 candidate terms of the law for Y needs at least 14 "
                      "runs, found 13"});
  expect_input_error([&] { select_terms("Y", candidates, sparse_runs(10, 1)); }, {"has 13 terms and 10 runs"});
  TermSelectionOptions options;
  options.folds = 1;
  expect_input_error([&] { select_terms("Y", candidates, sparse_runs(40, 1), options); },
                     {"cross-validation in 1 folds of 40 runs; expected 2 to 40 folds, or 0 for leave-one-out"});
  options.folds = 2;
  expect_input_error([&] { select_terms("Y", candidates, sparse_runs(20, 1), options); },
                     {"2-fold cross-validation of the 13 candidate terms of the law for Y leaves 10 runs to fit"});
  auto runs = sparse_runs(40, 1);
  for (auto& run : runs) run.values["u"] = 2.0;
  expect_input_error([&] { select_terms("Y", candidates, runs); }, {"linearly dependent", "u = 2 at every run"});
}

}  // namespace
}  // namespace hydrocoef
