#include "src/derivatives/design_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

// A right singular vector's component beyond this names its term as part of
// a dependence (the components of terms outside it are rounding, ~1e-15).
constexpr double kNullVectorComponent = 1e-3;
// How many runs a message lists before "and N more".
constexpr std::size_t kListedRuns = 5;

std::string listed_runs(const std::vector<DerivativeRun>& runs, const std::vector<std::size_t>& which) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < which.size() && k < kListedRuns; ++k) names.push_back(run_label(runs, which[k]));
  if (which.size() > kListedRuns) names.push_back(std::to_string(which.size() - kListedRuns) + " more");
  return and_list(names);
}

}  // namespace

std::string and_list(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (k > 0) out += k + 1 == items.size() ? " and " : ", ";
    out += items[k];
  }
  return out;
}

std::string run_label(const std::vector<DerivativeRun>& runs, std::size_t i) {
  if (i < runs.size() && !runs[i].label.empty()) return printable_text(runs[i].label, 80);
  return "run " + std::to_string(i + 1);
}

std::string constant_names_note(const std::vector<std::string>& names, const std::vector<DerivativeRun>& runs) {
  std::string out;
  for (const auto& name : names) {
    bool constant = !runs.empty();
    double first = 0.0;
    for (std::size_t i = 0; i < runs.size() && constant; ++i) {
      const auto it = runs[i].values.find(name);
      if (it == runs[i].values.end()) {
        constant = false;
      } else if (i == 0) {
        first = it->second;
      } else if (it->second != first) {
        constant = false;
      }
    }
    if (constant) out += (out.empty() ? "" : "; ") + name + " = " + shortest_number(first) + " at every run";
  }
  return out;
}

DesignMatrix make_design(std::string_view output, const std::vector<Term>& terms,
                         const std::vector<DerivativeRun>& runs, bool use_uncertainties) {
  const std::string law = "the law for " + printable_text(output, 40);
  if (terms.empty()) throw InputError(law + " has no terms; expected at least one");
  const std::size_t n = runs.size(), m = terms.size();
  if (n < m)
    throw InputError(law + " has " + std::to_string(m) + " terms and " + std::to_string(n) +
                     " runs; expected at least " + std::to_string(m) + " runs (" + std::to_string(m + 1) +
                     " for an uncertainty)");

  const std::vector<std::string> names = term_variables(terms);
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& name : names) {
      const auto it = runs[i].values.find(name);
      if (it == runs[i].values.end()) {
        const auto term = std::find_if(terms.begin(), terms.end(), [&](const Term& t) {
          const auto v = t.variables();
          return std::find(v.begin(), v.end(), name) != v.end();
        });
        throw InputError(run_label(runs, i) + " has no value of " + name + ", which the term " + term->text() + " of " +
                         law + " needs; expected every run to give " + and_list(names));
      }
      if (!std::isfinite(it->second))
        throw InputError(run_label(runs, i) + " has " + name + " = " + shortest_number(it->second) +
                         "; expected finite values of " + and_list(names));
    }
    if (!std::isfinite(runs[i].output))
      throw InputError(run_label(runs, i) + " has " + printable_text(output, 40) + " = " +
                       shortest_number(runs[i].output) + "; expected a finite value");
    const double sigma = runs[i].sigma;
    if (!std::isnan(sigma) && !(std::isfinite(sigma) && sigma > 0.0))
      throw InputError(run_label(runs, i) + " states the uncertainty " + shortest_number(sigma) + " of " +
                       printable_text(output, 40) + "; expected a finite uncertainty > 0, or none");
  }

  DesignMatrix design;
  std::vector<std::size_t> without;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isnan(runs[i].sigma)) without.push_back(i);
  design.weighted = use_uncertainties && without.empty();
  if (use_uncertainties && !without.empty() && without.size() < n)
    design.warnings.push_back({"unweighted", std::to_string(without.size()) + " of the " + std::to_string(n) +
                                                 " runs state no uncertainty of " + printable_text(output, 40) + " (" +
                                                 listed_runs(runs, without) + "): fitted unweighted"});

  const auto rows = static_cast<Eigen::Index>(n), cols = static_cast<Eigen::Index>(m);
  design.row_weight.resize(rows);
  design.rhs.resize(rows);
  Eigen::MatrixXd values(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const DerivativeRun& run = runs[static_cast<std::size_t>(i)];
    design.row_weight(i) = design.weighted ? 1.0 / run.sigma : 1.0;
    design.rhs(i) = run.output * design.row_weight(i);
    for (Eigen::Index k = 0; k < cols; ++k) {
      const Term& term = terms[static_cast<std::size_t>(k)];
      values(i, k) = term.evaluate(run.values) * design.row_weight(i);
      if (!std::isfinite(values(i, k)) || !std::isfinite(design.rhs(i)))
        throw InputError("the term " + term.text() + " of " + law + " is " + shortest_number(values(i, k)) + " at " +
                         run_label(runs, static_cast<std::size_t>(i)) +
                         (design.weighted ? " (divided by its uncertainty)" : "") +
                         "; expected values whose powers stay within double precision");
    }
  }
  design.column_scale.resize(cols);
  for (Eigen::Index k = 0; k < cols; ++k) {
    const Term& term = terms[static_cast<std::size_t>(k)];
    const double norm = values.col(k).stableNorm();
    if (norm == 0.0) {
      const std::string note = constant_names_note(term.variables(), runs);
      throw InputError("the term " + term.text() + " of " + law + " is zero at every one of the " + std::to_string(n) +
                       " runs" + (note.empty() ? "" : " (" + note + ")") +
                       ", so its coefficient cannot be fitted; expected runs where it is not zero");
    }
    if (!std::isfinite(norm))
      throw InputError("the values of the term " + term.text() + " of " + law +
                       " overflow when squared and summed; expected values whose powers stay within double precision");
    design.column_scale(k) = norm;
  }
  design.scaled = values * design.column_scale.cwiseInverse().asDiagonal();
  return design;
}

void refuse_dependent_terms(std::string_view output, const std::vector<Term>& terms,
                            const std::vector<DerivativeRun>& runs, const Eigen::JacobiSVD<Eigen::MatrixXd>& svd) {
  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::Index m = svd.matrixV().rows();
  if (s.size() == 0 || m == 0) return;
  std::vector<Term> involved;
  for (Eigen::Index j = 0; j < m; ++j) {
    bool in_null_space = false;
    for (Eigen::Index k = 0; k < s.size(); ++k)
      if (!(s(k) > kRankTolerance * s(0)) && std::abs(svd.matrixV()(j, k)) > kNullVectorComponent) in_null_space = true;
    if (in_null_space) involved.push_back(terms[static_cast<std::size_t>(j)]);
  }
  if (involved.empty()) return;
  std::vector<std::string> texts;
  std::transform(involved.begin(), involved.end(), std::back_inserter(texts), [](const Term& t) { return t.text(); });
  const std::string note = constant_names_note(term_variables(involved), runs);
  throw InputError("the terms " + and_list(texts) + " of the law for " + printable_text(output, 40) +
                   " are linearly dependent over these " + std::to_string(runs.size()) + " runs" +
                   (note.empty() ? "" : " (" + note + ")") +
                   ", so their coefficients cannot be told apart; expected runs that vary their names independently, "
                   "or fewer terms");
}

}  // namespace hydrocoef
