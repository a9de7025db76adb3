// The least-squares fit of damping laws to CFD runs. A law (its terms and
// their evaluation: src/core/damping_terms.hpp) is one generalized-force
// component written as a linear combination of basis terms of one velocity
// component, for example the surge law X(u) = c0 + c1 u + c2 u|u|.
//
// A law is linear in its coefficients, so the fit is an ordinary (or, with a
// robust loss, iteratively reweighted) linear least-squares problem. It is
// solved with Ceres so that robust losses and the covariance of the
// coefficients come from one well-tested place.
//
// Units: x is in the velocity component's SI unit (m/s for u, v, w; rad/s for
// p, q, r) and the force in N (X, Y, Z) or N m (K, M, N). A coefficient's unit
// is the force's unit divided by its basis term's unit (for u|u|: N s^2 m^-2).
// Fitting does not change signs: the law is in whatever sign convention the
// force values were given in.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/damping_terms.hpp"

namespace hydrocoef {

/// How residuals are penalized. Robust losses grow slower than r^2 beyond
/// loss_scale, so a few bad runs cannot drag the law away from the rest.
enum class LossKind {
  Squared,  ///< ordinary least squares
  Huber,    ///< r^2 within loss_scale, linear beyond
  Cauchy,   ///< logarithmic beyond loss_scale: strongest outlier rejection
  SoftLOne  ///< smooth blend of r^2 and |r|
};

struct LossOptions {
  LossKind loss = LossKind::Squared;
  /// Residual size [force's unit: N or N m] beyond which a robust loss starts
  /// discounting a run. Must be finite and > 0 for robust losses; ignored for Squared.
  double loss_scale = 0.0;
};

/// Parses "squared", "huber:SCALE", "cauchy:SCALE" or "soft-l1:SCALE", SCALE
/// being a positive number in the force's unit (e.g. "huber:0.01"). Throws
/// InputError naming the text otherwise.
LossOptions parse_loss(std::string_view text);

/// The canonical text of a loss, "squared" or "huber:0.01" (shortest
/// round-trip form of the scale); parse_loss reads it back.
std::string format_loss(const LossOptions& options);

/// A fitted law and how well it fits.
struct DampingLawFit {
  DampingLawSpec spec;
  std::vector<double> coefficients;  ///< same order as spec.terms; [force unit / term unit]
  /// One-sigma standard errors, same order and units as coefficients:
  /// sqrt(diag(s^2 (J^T W J)^-1)) with J the design matrix, W the robust
  /// loss's weights at the solution (all 1 for Squared) and
  /// s^2 = sum(w_i r_i^2)/(n-k). NaN when n <= k, where s^2 is undefined.
  ///
  /// Weighted fits (each run's standard uncertainty sigma_i given): the
  /// residuals are r_i / sigma_i, the covariance is S^2 (J^T W J)^-1 with
  /// S^2 = max(1, chi^2 / (n - k)): when the runs scatter more than their
  /// uncertainties say (the law misses something, or the uncertainties are
  /// understated), the covariance is scaled by the Birge ratio squared, as
  /// the Particle Data Group scales an average's error by S (R. T. Birge,
  /// Phys. Rev. 40 (1932) 207; PDG, Review of Particle Physics,
  /// "Introduction: averaging"); it is never scaled down. The standard
  /// errors are the square roots of its diagonal.
  std::vector<double> std_errors;
  /// The coefficients' covariance, k x k row by row [unit_i x unit_j], as the
  /// standard errors above (their squares on the diagonal).
  std::vector<double> covariance;
  bool weighted = false;  ///< fitted with the runs' uncertainties
  /// Weighted fits: chi^2 / (n - k), chi^2 = sum (r_i / sigma_i)^2. About 1
  /// when the runs scatter about the law as their uncertainties say; well
  /// above 1: the law misses something or the uncertainties are understated;
  /// well below: overstated. NaN for unweighted fits or n <= k.
  double chi2_reduced = std::numeric_limits<double>::quiet_NaN();
  /// What the covariance of a weighted fit was scaled by: S^2 above (1 when
  /// the scatter does not exceed the stated uncertainties, and for
  /// unweighted fits, whose covariance is scaled by s^2 instead).
  double covariance_scale = 1.0;
  double rmse = 0.0;  ///< sqrt(SSR/n) of the unweighted residuals [force unit]
  double r2 = 0.0;    ///< 1 - SSR/SST, SST about the mean of y; NaN when all y are equal
  std::size_t n = 0;  ///< number of observations fitted
  std::string loss;   ///< format_loss of the options used, e.g. "squared" or "huber:0.01"

  /// The law's value at x [force unit]; x in m/s or rad/s.
  double evaluate(double x) const;
};

/// Fits y ~ sum_k c_k basis_k(x) over the observations (x[i], y[i]).
///   spec:    the law's terms; validated as parse_damping_terms would.
///   x:       velocity component of each run [m/s or rad/s].
///   y:       force component of each run [N or N m], same length as x.
///   options: loss; robust losses start from the least-squares solution.
///   sigma:   each run's standard uncertainty [N or N m], all finite and > 0
///            (a weighted fit), or empty (an unweighted one).
/// Throws InputError when x and y differ in length, there are fewer runs than
/// terms, a value is not finite, the spec is invalid, or the terms are
/// linearly dependent on this data (e.g. all x equal with terms 1,u; or
/// u,|u| with no negative u), naming the terms concerned.
DampingLawFit fit_damping_law(const DampingLawSpec& spec, std::span<const double> x, std::span<const double> y,
                              const LossOptions& options = {}, std::span<const double> sigma = {});

}  // namespace hydrocoef
