#include "src/derivatives/derivative_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "src/core/dense_decompositions.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/surface/gp_surface.hpp"

namespace hydrocoef {
namespace {

constexpr double kNormal975 = 1.959963984540054;
// Terms whose component in the weakest right singular vector exceeds this
// share of its largest component are named as the barely determined combination.
constexpr double kWeakDirectionShare = 0.2;

// Term k's VIF: Var(c_k) over its value were term k orthogonal to the rest,
// [(A^T A)^-1]_kk * ||a_k - mean part||^2 with A the weighted design; the
// mean part is a_k's projection on the constant column when there is one.
std::vector<double> variance_inflation(const DesignMatrix& design, const std::vector<Term>& terms,
                                       const Eigen::MatrixXd& unit_inverse) {
  const Eigen::Index m = design.scaled.cols();
  Eigen::Index constant = -1;
  for (Eigen::Index k = 0; k < m; ++k)
    if (terms[static_cast<std::size_t>(k)].is_constant()) constant = k;
  std::vector<double> vif(static_cast<std::size_t>(m), std::numeric_limits<double>::quiet_NaN());
  for (Eigen::Index k = 0; k < m; ++k) {
    if (k == constant) continue;
    // Columns have unit norm: ||a_k||^2 = 1, and its part along the unit
    // constant column c is (a_k . c) c.
    double spread = 1.0;
    if (constant >= 0) {
      const double along = design.scaled.col(k).dot(design.scaled.col(constant));
      spread = 1.0 - along * along;
    }
    vif[static_cast<std::size_t>(k)] = unit_inverse(k, k) * spread;
  }
  return vif;
}

// The "collinear-terms" warning: the terms above the threshold, and the
// term each is most correlated with (centred when the model has a constant).
void warn_of_inflation(DerivativeFit& fit, const DesignMatrix& design, double threshold) {
  std::vector<std::string> flagged;
  const Eigen::Index m = design.scaled.cols();
  const bool has_constant =
      std::any_of(fit.terms.begin(), fit.terms.end(), [](const Term& t) { return t.is_constant(); });
  Eigen::MatrixXd columns = design.scaled;
  if (has_constant) {
    const Eigen::VectorXd unit = design.row_weight / design.row_weight.norm();  // the constant's weighted column
    for (Eigen::Index k = 0; k < m; ++k) columns.col(k) -= unit * unit.dot(columns.col(k));
  }
  for (Eigen::Index k = 0; k < m; ++k) {
    const double vif = fit.vif[static_cast<std::size_t>(k)];
    if (!(vif > threshold)) continue;
    Eigen::Index partner = -1;
    double best = 0.0;
    for (Eigen::Index j = 0; j < m; ++j) {
      if (j == k || fit.terms[static_cast<std::size_t>(j)].is_constant()) continue;
      const double norms = columns.col(k).norm() * columns.col(j).norm();
      const double r = norms > 0.0 ? columns.col(k).dot(columns.col(j)) / norms : 0.0;
      if (partner < 0 || std::abs(r) > std::abs(best)) {
        best = r;
        partner = j;
      }
    }
    std::string item = fit.terms[static_cast<std::size_t>(k)].text() + " (VIF " + significant(vif, 3);
    if (partner >= 0)
      item += ", correlation " + significant(best, 4) + " with " + fit.terms[static_cast<std::size_t>(partner)].text();
    flagged.push_back(item + ")");
  }
  if (flagged.empty()) return;
  fit.warnings.push_back(
      {"collinear-terms", "variance inflation factors above " + significant(threshold, 3) +
                              " (the rule of thumb of Montgomery, Peck & Vining, Introduction to Linear Regression "
                              "Analysis, ch. 9): " +
                              and_list(flagged) +
                              "; these terms cannot be told apart well over the runs' range: their coefficients' "
                              "standard errors are inflated by sqrt(VIF); runs over a wider or less correlated range "
                              "of their names separate them"});
}

// The "ill-conditioned" warning: the terms with large components in the
// right singular vector of the smallest singular value.
void warn_of_conditioning(DerivativeFit& fit, const Eigen::JacobiSVD<Eigen::MatrixXd>& svd, double threshold) {
  if (!(fit.condition_number > threshold)) return;
  const Eigen::Index last = svd.singularValues().size() - 1;
  const Eigen::VectorXd weakest = svd.matrixV().col(last);
  const double largest = weakest.cwiseAbs().maxCoeff();
  std::vector<std::string> named;
  for (Eigen::Index k = 0; k < weakest.size(); ++k)
    if (std::abs(weakest(k)) >= kWeakDirectionShare * largest)
      named.push_back(fit.terms[static_cast<std::size_t>(k)].text());
  fit.warnings.push_back(
      {"ill-conditioned", "the condition number of the design (columns scaled to unit norm) is " +
                              significant(fit.condition_number, 3) + ", above " + significant(threshold, 3) +
                              ": the runs barely determine a combination of " + and_list(named) +
                              ", whose coefficients lose about log10 of it in digits; expected runs that vary these "
                              "terms' names over a range that separates them, or fewer terms"});
}

// The weighted fit's scatter against its stated uncertainties, as the
// damping-law fit reports it (src/pipeline/fit_stored_runs.cpp): chi^2/(n-m)
// has a standard deviation of about sqrt(2/(n-m)); beyond three of them the
// disagreement is worth a warning.
void warn_of_scatter(DerivativeFit& fit, std::size_t dof) {
  if (!fit.weighted || !std::isfinite(fit.chi2_reduced)) return;
  const double spread = 3.0 * std::sqrt(2.0 / static_cast<double>(dof));
  if (fit.chi2_reduced > 1.0 + spread)
    fit.warnings.push_back({"scatter-exceeds-uncertainty",
                            "reduced chi^2 = " + significant(fit.chi2_reduced, 4) +
                                ": the runs scatter about the model more than their uncertainties say (the model "
                                "misses something, or the uncertainties are understated); the covariance is scaled by "
                                "it (Birge ratio " +
                                significant(std::sqrt(fit.chi2_reduced), 4) + ")"});
  else if (fit.chi2_reduced < 1.0 - spread)
    fit.warnings.push_back(
        {"scatter-below-uncertainty", "reduced chi^2 = " + significant(fit.chi2_reduced, 4) +
                                          ": the runs scatter about the model less than their uncertainties say (the "
                                          "uncertainties are overstated)"});
}

}  // namespace

double DerivativeFit::evaluate(const std::map<std::string, double>& point) const {
  double value = 0.0;
  for (std::size_t k = 0; k < terms.size() && k < coefficients.size(); ++k)
    value += coefficients[k] * terms[k].evaluate(point);
  return value;
}

DerivativeFit fit_derivatives(std::string_view output, const std::vector<Term>& terms,
                              const std::vector<DerivativeRun>& runs, const DerivativeFitOptions& options) {
  DesignMatrix design = make_design(output, terms, runs, options.use_uncertainties);
  const std::size_t n = runs.size(), m = terms.size();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd = jacobi_svd(design.scaled, Eigen::ComputeThinU | Eigen::ComputeThinV);
  refuse_dependent_terms(output, terms, runs, svd);

  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  const Eigen::VectorXd scaled_solution = V * (svd.matrixU().transpose() * design.rhs).cwiseQuotient(s);
  // (A^T A)^-1 of the unit-norm design: V diag(1/s^2) V^T.
  const Eigen::MatrixXd unit_inverse = V * s.cwiseAbs2().cwiseInverse().asDiagonal() * V.transpose();
  const Eigen::VectorXd weighted_residuals = design.scaled * scaled_solution - design.rhs;
  const Eigen::VectorXd residuals = weighted_residuals.cwiseQuotient(design.row_weight);
  Eigen::VectorXd outputs(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) outputs(static_cast<Eigen::Index>(i)) = runs[i].output;

  DerivativeFit fit;
  fit.output = std::string(output);
  fit.terms = terms;
  fit.n = n;
  fit.weighted = design.weighted;
  fit.warnings = std::move(design.warnings);
  fit.condition_number = s(0) / s(s.size() - 1);
  const double ssr = residuals.squaredNorm();
  const double sst = (outputs.array() - outputs.mean()).matrix().squaredNorm();
  fit.rmse = std::sqrt(ssr / static_cast<double>(n));
  fit.r2 = sst > 0.0 ? 1.0 - ssr / sst : std::numeric_limits<double>::quiet_NaN();

  const std::size_t dof = n - m;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double reduced = dof > 0 ? weighted_residuals.squaredNorm() / static_cast<double>(dof) : nan;
  double variance_factor = reduced;  // unweighted: s^2
  if (design.weighted) {
    fit.chi2_reduced = reduced;
    fit.covariance_scale = std::isfinite(reduced) ? std::max(1.0, reduced) : 1.0;
    variance_factor = fit.covariance_scale;
  }
  const bool from_residuals = !design.weighted || fit.covariance_scale > 1.0;
  fit.interval_factor = from_residuals ? (dof > 0 ? student_t_factor(dof) * kNormal975 : nan) : kNormal975;

  fit.coefficients.resize(m);
  fit.covariance.resize(m * m);
  for (std::size_t i = 0; i < m; ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    fit.coefficients[i] = scaled_solution(ii) / design.column_scale(ii);
    if (!std::isfinite(fit.coefficients[i]))
      throw InputError("the coefficient of " + terms[i].text() + " in the law for " + printable_text(output, 40) +
                       " overflows; expected outputs and term values within double precision");
    for (std::size_t j = 0; j < m; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      fit.covariance[i * m + j] =
          variance_factor * unit_inverse(ii, jj) / (design.column_scale(ii) * design.column_scale(jj));
    }
  }
  for (std::size_t k = 0; k < m; ++k) {
    const double se = std::sqrt(fit.covariance[k * m + k]);
    fit.std_errors.push_back(se);
    fit.interval_low.push_back(fit.coefficients[k] - fit.interval_factor * se);
    fit.interval_high.push_back(fit.coefficients[k] + fit.interval_factor * se);
  }

  fit.vif = variance_inflation(design, terms, unit_inverse);
  warn_of_inflation(fit, design, options.vif_threshold);
  warn_of_conditioning(fit, svd, options.condition_threshold);
  if (dof > 0) warn_of_scatter(fit, dof);
  return fit;
}

}  // namespace hydrocoef
