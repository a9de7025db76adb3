// Which terms a derivative model needs, chosen by how well the model predicts
// runs it was not fitted to: backward elimination from a candidate list,
// scored by cross-validation, and the one-standard-error rule.
//
// Each step removes the term whose removal leaves the smallest
// cross-validated error, down to one term. The chosen set is the smallest set
// on that path whose error is within one standard error of the path's
// minimum (the one-standard-error rule: Breiman, Friedman, Olshen & Stone,
// Classification and Regression Trees, 1984, ch. 3; Hastie, Tibshirani
// & Friedman, The Elements of Statistical Learning, 2nd ed., 2009, sec.
// 7.10): a term stays only when the runs show that it predicts better.
//
// Cross-validation: leave-one-out by default, from the one fit of each set
// (the prediction error of run i left out is e_i / (1 - h_ii), h the hat
// matrix), or k-fold with folds drawn by a seeded shuffle (std::mt19937_64,
// whose output the C++ standard fixes, with a Fisher-Yates shuffle written
// here), so that a selection is the same on every machine.
//
// Units: errors are mean squared prediction errors in the output's unit
// squared (N^2, (N m)^2), or, in a weighted fit, of the residuals over each
// run's uncertainty (dimensionless). Signs are the runs' own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "src/derivatives/design_matrix.hpp"
#include "src/derivatives/terms.hpp"

namespace hydrocoef {

struct TermSelectionOptions {
  /// 0: leave-one-out; k >= 2: k-fold (at most the number of runs).
  std::size_t folds = 0;
  std::uint64_t seed = 1;  ///< the k-fold shuffle's seed
  /// Choose by the one-standard-error rule; false: the set of least error.
  bool one_standard_error = true;
  /// Weight by 1/sigma^2 when every run states an uncertainty (as the fit).
  bool use_uncertainties = true;
};

/// One set on the elimination path.
struct SelectionStep {
  std::vector<Term> terms;  ///< the set, in the candidates' order
  std::string removed;      ///< the term removed to reach it; "" for the full candidate set
  /// Cross-validated mean squared prediction error; +inf when the set
  /// cannot predict a left-out run (a fold's runs cannot fit it, or a run's
  /// leverage is 1).
  double cv_error = 0.0;
  double cv_standard_error = 0.0;  ///< the standard error of cv_error
};

struct TermSelection {
  std::vector<SelectionStep> steps;         ///< the full set first, then one term fewer per step
  std::size_t best_step = 0;                ///< the step of least cv_error
  std::size_t chosen_step = 0;              ///< the step the rule chose
  std::vector<Term> chosen;                 ///< steps[chosen_step].terms
  bool weighted = false;                    ///< errors are in units of the runs' uncertainties
  std::string method;                       ///< e.g. "leave-one-out, one-standard-error rule"
  std::vector<DerivativeWarning> warnings;  ///< as the fit's design gives them ("unweighted")
};

/// Chooses terms of `output` among `candidates` over the runs.
/// Throws InputError as fit_derivatives does for the full candidate set
/// (fewer runs than candidates, missing names, values not finite, terms
/// linearly dependent over the runs), and when the runs are too few to
/// cross-validate it (leave-one-out needs one run more than candidates;
/// k-fold needs every training part to have as many runs as candidates),
/// or folds is 1 or more than the runs.
TermSelection select_terms(std::string_view output, const std::vector<Term>& candidates,
                           const std::vector<DerivativeRun>& runs, const TermSelectionOptions& options = {});

}  // namespace hydrocoef
