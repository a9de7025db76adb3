// The least-squares fit of a derivative model of several variables to all
// the selected runs at once: output = sum_k c_k t_k(x) with terms t_k
// (src/derivatives/terms.hpp) such as v, u*v, v*|v|, v^2*r, u^2*delta, and
// the statistics that say how far the runs determine each coefficient.
//
// The model is linear in its coefficients, so the fit is one linear least-
// squares problem, solved through the singular value decomposition of the
// design with unit-norm columns (Eigen's JacobiSVD, accurate to the relative
// precision of each column however the terms differ in size); the same
// decomposition gives the covariance, the condition number and the rank.
//
// Units: a coefficient's unit is the output's unit over its term's unit (for
// Y and u*v: N s^2 m^-2); Term::powers() gives the term's unit. Body axes x
// forward, y starboard, z down (SNAME); the fit changes no sign: the
// coefficients are in the convention of the runs' outputs.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "src/derivatives/design_matrix.hpp"
#include "src/derivatives/terms.hpp"

namespace hydrocoef {

struct DerivativeFitOptions {
  /// Weight by 1/sigma^2 when every run states an uncertainty (runs that
  /// state none leave the fit unweighted, with a warning).
  bool use_uncertainties = true;
  /// Variance inflation factors above this are warned of. 10 is the usual
  /// rule of thumb: Montgomery, Peck & Vining, Introduction to Linear
  /// Regression Analysis (Wiley), ch. 9 "Multicollinearity": "VIFs that
  /// exceed 5 or 10 indicate that the associated regression coefficients are
  /// poorly estimated because of multicollinearity".
  double vif_threshold = 10.0;
  /// Condition numbers (of the design with unit-norm columns) above this are
  /// warned of: the coefficients' relative accuracy is about the condition
  /// number times the data's, so beyond 1e6 six digits of the runs' forces
  /// are lost to the dependence between terms (Belsley, Kuh & Welsch,
  /// Regression Diagnostics, 1980, call condition indexes of 30 to 100
  /// "moderate to strong"; 1e6 warns only of severe cases).
  double condition_threshold = 1e6;
};

/// A fitted model and how well the runs determine it.
struct DerivativeFit {
  std::string output;                ///< the output's name, e.g. "Y"
  std::vector<Term> terms;           ///< as given, in the order of the coefficients
  std::vector<double> coefficients;  ///< [output unit / term unit]
  /// The coefficients' covariance, m x m row by row [unit_i x unit_j].
  /// Unweighted: s^2 (A^T A)^-1 with s^2 = SSR / (n - m) (NaN when n = m).
  /// Weighted (every run's sigma_i given, rows divided by sigma_i):
  /// S^2 (A^T A)^-1, S^2 = max(1, chi^2 / (n - m)): when the runs scatter
  /// more than their uncertainties say, it is scaled by the Birge ratio
  /// squared (R. T. Birge, Phys. Rev. 40 (1932) 207; the Particle Data
  /// Group's scale factor), never scaled down; the project's rule for
  /// weighted fits (src/fit/damping_law.hpp).
  std::vector<double> covariance;
  std::vector<double> std_errors;  ///< square roots of the covariance's diagonal
  /// 95 % intervals c_k -/+ interval_factor * std_errors[k].
  std::vector<double> interval_low, interval_high;
  /// The 95 % quantile the intervals use: Student's t_{0.975, n-m} when the
  /// variance comes from the residuals (unweighted fits, and weighted fits
  /// scaled by the Birge ratio); the normal 1.96 when the stated
  /// uncertainties are used as they are. NaN when n = m and unweighted.
  double interval_factor = std::numeric_limits<double>::quiet_NaN();
  /// Variance inflation factors, one per term: VIF_k = 1 / (1 - R_k^2), R_k^2
  /// of the (weighted) regression of term k's column on the other terms',
  /// measured about the mean when the model has a constant term and about
  /// zero otherwise; equivalently Var(c_k) over what it would be if term k
  /// were orthogonal to the others. NaN for the constant term.
  std::vector<double> vif;
  /// sigma_max / sigma_min of the weighted design with unit-norm columns.
  double condition_number = 0.0;
  double rmse = 0.0;  ///< sqrt(SSR / n) of the unweighted residuals [output unit]
  double r2 = 0.0;    ///< 1 - SSR / SST, SST about the mean output; NaN when every output is equal
  std::size_t n = 0;  ///< runs fitted
  bool weighted = false;
  /// Weighted fits: chi^2 / (n - m) with chi^2 = sum (r_i / sigma_i)^2; NaN
  /// when unweighted or n = m.
  double chi2_reduced = std::numeric_limits<double>::quiet_NaN();
  double covariance_scale = 1.0;  ///< S^2 above for weighted fits, 1 otherwise
  /// "collinear-terms", "ill-conditioned", "unweighted",
  /// "scatter-exceeds-uncertainty", "scatter-below-uncertainty".
  std::vector<DerivativeWarning> warnings;

  /// The model's value at `point` (name -> value) [output unit].
  double evaluate(const std::map<std::string, double>& point) const;
};

/// Fits `output` = sum_k c_k terms[k] to the runs.
/// Throws InputError (one line, nothing else happens) for what make_design
/// refuses (no terms, fewer runs than terms, a name a run lacks, a value
/// that is not finite, a term zero at every run) and for terms that are
/// linearly dependent over the runs, naming them. An ill-conditioned but
/// solvable fit is returned with its warnings.
DerivativeFit fit_derivatives(std::string_view output, const std::vector<Term>& terms,
                              const std::vector<DerivativeRun>& runs, const DerivativeFitOptions& options = {});

}  // namespace hydrocoef
