#include "src/derivatives/term_selection.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A left-out run whose leverage is within this of 1 cannot be predicted by
// the others (the set fits it exactly whatever its output).
constexpr double kMinLeaveOutWeight = 1e-12;

struct CvScore {
  double error = kInfinity;
  double standard_error = kInfinity;
};

// Mean and standard error of the mean of `values`.
CvScore mean_and_error(const std::vector<double>& values) {
  const double count = static_cast<double>(values.size());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / count;
  const double squares = std::accumulate(values.begin(), values.end(), 0.0,
                                         [mean](double sum, double v) { return sum + (v - mean) * (v - mean); });
  return {mean, values.size() > 1 ? std::sqrt(squares / (count - 1.0) / count) : kInfinity};
}

Eigen::MatrixXd columns_of(const Eigen::MatrixXd& design, const std::vector<std::size_t>& which) {
  Eigen::MatrixXd out(design.rows(), static_cast<Eigen::Index>(which.size()));
  for (std::size_t k = 0; k < which.size(); ++k)
    out.col(static_cast<Eigen::Index>(k)) = design.col(static_cast<Eigen::Index>(which[k]));
  return out;
}

// The least-squares solution of A x = b, or nothing when A's columns are
// dependent (by the fit's rank rule, on A with its columns scaled to unit norm).
std::optional<Eigen::VectorXd> solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::VectorXd norms = A.colwise().norm().transpose();
  if ((norms.array() == 0.0).any() || A.rows() < A.cols()) return std::nullopt;
  const Eigen::MatrixXd unit = A * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd = jacobi_svd(unit, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  if (!(s(s.size() - 1) > kRankTolerance * s(0))) return std::nullopt;
  const Eigen::VectorXd x = svd.matrixV() * (svd.matrixU().transpose() * b).cwiseQuotient(s);
  return Eigen::VectorXd(x.cwiseQuotient(norms));
}

// Leave-one-out from one fit: the prediction error of run i left out is
// e_i / (1 - h_ii), h_ii = ||U_i||^2 with U the thin left singular vectors.
CvScore leave_one_out(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd = jacobi_svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  if (!(s(s.size() - 1) > kRankTolerance * s(0))) return {};
  const Eigen::VectorXd x = svd.matrixV() * (svd.matrixU().transpose() * b).cwiseQuotient(s);
  const Eigen::VectorXd residuals = A * x - b;
  std::vector<double> squared(static_cast<std::size_t>(A.rows()));
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    const double left_out_weight = 1.0 - svd.matrixU().row(i).squaredNorm();
    if (!(left_out_weight > kMinLeaveOutWeight)) return {};
    const double e = residuals(i) / left_out_weight;
    squared[static_cast<std::size_t>(i)] = e * e;
  }
  return mean_and_error(squared);
}

// k-fold: the pooled mean squared error of the left-out runs; its standard
// error from the spread of the folds' mean squared errors.
CvScore k_fold(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::vector<std::size_t>& fold_of,
               std::size_t folds) {
  double total = 0.0;
  std::vector<double> fold_errors;
  for (std::size_t f = 0; f < folds; ++f) {
    std::vector<Eigen::Index> train, test;
    for (std::size_t i = 0; i < fold_of.size(); ++i) {
      if (fold_of[i] == f) {
        test.push_back(static_cast<Eigen::Index>(i));
      } else {
        train.push_back(static_cast<Eigen::Index>(i));
      }
    }
    Eigen::MatrixXd A_train(static_cast<Eigen::Index>(train.size()), A.cols());
    Eigen::VectorXd b_train(static_cast<Eigen::Index>(train.size()));
    Eigen::Index row = 0;
    for (const Eigen::Index i : train) {
      A_train.row(row) = A.row(i);
      b_train(row++) = b(i);
    }
    const auto x = solve(A_train, b_train);
    if (!x) return {};
    double sum = 0.0;
    for (const Eigen::Index i : test) {
      const double e = A.row(i).dot(*x) - b(i);
      sum += e * e;
    }
    total += sum;
    fold_errors.push_back(sum / static_cast<double>(test.size()));
  }
  CvScore score = mean_and_error(fold_errors);
  score.error = total / static_cast<double>(fold_of.size());
  return score;
}

// Fold f holds the runs at places f, f + k, f + 2k, ... of a seeded
// Fisher-Yates shuffle (std::mt19937_64's sequence is fixed by the standard;
// the shuffle is written here because std::shuffle's is not).
std::vector<std::size_t> assign_folds(std::size_t n, std::size_t folds, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::mt19937_64 random(seed);
  for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[static_cast<std::size_t>(random() % i)]);
  std::vector<std::size_t> fold_of(n);
  for (std::size_t place = 0; place < n; ++place) fold_of[order[place]] = place % folds;
  return fold_of;
}

}  // namespace

TermSelection select_terms(std::string_view output, const std::vector<Term>& candidates,
                           const std::vector<DerivativeRun>& runs, const TermSelectionOptions& options) {
  const DesignMatrix design = make_design(output, candidates, runs, options.use_uncertainties);
  refuse_dependent_terms(output, candidates, runs,
                         jacobi_svd(design.scaled, Eigen::ComputeThinU | Eigen::ComputeThinV));
  const std::size_t n = runs.size(), m = candidates.size();
  const std::string law = "the law for " + printable_text(output, 40);
  if (options.folds == 0 && n < m + 1)
    throw InputError("leave-one-out cross-validation of the " + std::to_string(m) + " candidate terms of " + law +
                     " needs at least " + std::to_string(m + 1) + " runs, found " + std::to_string(n));
  if (options.folds == 1 || options.folds > n)
    throw InputError("cross-validation in " + std::to_string(options.folds) + " folds of " + std::to_string(n) +
                     " runs; expected 2 to " + std::to_string(n) + " folds, or 0 for leave-one-out");
  if (options.folds >= 2) {
    const std::size_t largest_fold = (n + options.folds - 1) / options.folds;
    if (n - largest_fold < m)
      throw InputError(std::to_string(options.folds) + "-fold cross-validation of the " + std::to_string(m) +
                       " candidate terms of " + law + " leaves " + std::to_string(n - largest_fold) +
                       " runs to fit some folds; expected at least " + std::to_string(m) +
                       " (more runs or more folds)");
  }
  const std::vector<std::size_t> fold_of =
      options.folds >= 2 ? assign_folds(n, options.folds, options.seed) : std::vector<std::size_t>();
  const auto score = [&](const std::vector<std::size_t>& which) {
    const Eigen::MatrixXd A = columns_of(design.scaled, which);
    return options.folds >= 2 ? k_fold(A, design.rhs, fold_of, options.folds) : leave_one_out(A, design.rhs);
  };
  const auto terms_of = [&](const std::vector<std::size_t>& which) {
    std::vector<Term> out;
    std::transform(which.begin(), which.end(), std::back_inserter(out), [&](std::size_t k) { return candidates[k]; });
    return out;
  };

  TermSelection selection;
  selection.weighted = design.weighted;
  selection.warnings = design.warnings;
  selection.method = (options.folds >= 2 ? std::to_string(options.folds) + "-fold cross-validation (seed " +
                                               std::to_string(options.seed) + ")"
                                         : std::string("leave-one-out cross-validation")) +
                     ", backward elimination, " +
                     (options.one_standard_error ? "one-standard-error rule" : "least cross-validated error");
  std::vector<std::size_t> current(m);
  for (std::size_t k = 0; k < m; ++k) current[k] = k;
  CvScore full = score(current);
  selection.steps.push_back({terms_of(current), "", full.error, full.standard_error});
  while (current.size() > 1) {
    std::size_t best_place = 0;
    CvScore best;
    for (std::size_t place = 0; place < current.size(); ++place) {
      std::vector<std::size_t> fewer = current;
      fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(place));
      const CvScore s = score(fewer);
      if (s.error < best.error) {
        best = s;
        best_place = place;
      }
    }
    const std::string removed = candidates[current[best_place]].text();
    current.erase(current.begin() + static_cast<std::ptrdiff_t>(best_place));
    selection.steps.push_back({terms_of(current), removed, best.error, best.standard_error});
  }

  for (std::size_t k = 1; k < selection.steps.size(); ++k)
    if (selection.steps[k].cv_error < selection.steps[selection.best_step].cv_error) selection.best_step = k;
  const SelectionStep& best = selection.steps[selection.best_step];
  if (!std::isfinite(best.cv_error))
    throw InputError("cross-validation of " + law + " over " + std::to_string(n) +
                     " runs could not predict a left-out run with any set of the candidate terms; expected more "
                     "runs, spread over the range of the terms' names");
  selection.chosen_step = selection.best_step;
  if (options.one_standard_error) {
    const double limit = best.cv_error + (std::isfinite(best.cv_standard_error) ? best.cv_standard_error : 0.0);
    for (std::size_t k = selection.best_step; k < selection.steps.size(); ++k)
      if (selection.steps[k].cv_error <= limit) selection.chosen_step = k;
  }
  selection.chosen = selection.steps[selection.chosen_step].terms;
  return selection;
}

}  // namespace hydrocoef
