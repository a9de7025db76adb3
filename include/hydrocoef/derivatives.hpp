// Derivative models of several variables, as `hydrocoef derivatives fit |
// list | show | delete | evaluate` makes and reads them: a force or moment
// of a body written as sum_k c_k t_k(x) over all its selected runs at once,
// each term t_k a product of the runs' velocity components, rates and
// disturbances ("v, r, v*|v|, u*v, v^2*r, u^2*delta"), fitted by one linear
// least-squares problem (weighted by 1/sigma^2 when every run states an
// uncertainty), with the coefficients' covariance, 95 % intervals, variance
// inflation factors, the design's condition number and warnings naming the
// terms the runs cannot tell apart; stored with the runs it was made from.
//
// Units and frames: SI; body axes x forward, y starboard, z down (SNAME);
// the variables are the runs' keys u, v, w [m/s], p, q, r [rad/s] and their
// disturbances by name (SI: angles in rad); the output is a force X, Y, Z [N]
// or moment K, M, N [N m] on the body, in the runs' own sign convention. A
// coefficient's unit is the output's over its term's: Y_v|v| in N/(m/s)^2.
// `show` restates the coefficients in the prime (SNAME 1950), bis (Norrbin
// 1971) or MMG (Yasukawa and Yoshimura 2015) system, naming the
// normalisation of each.
//
// Errors: bad input (an option, a term the parser does not know, fewer runs
// than terms, terms the runs cannot tell apart, a reference value a form
// needs and lacks) is an InputError with the message the command-line tool
// prints, and nothing is stored; a read-only Database refuses writes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/export.hpp"

namespace hydrocoef {
inline namespace api {

/// What `hydrocoef derivatives fit` fits.
struct HYDROCOEF_EXPORT DerivativeModelOptions {
  std::string body;    ///< the body whose runs are fitted (--body)
  std::string output;  ///< X Y Z K M N (--output)
  /// The terms, comma-separated (--terms "v, r, v*|v|, u*v"); or empty with a template.
  std::string terms;
  /// A named term list for the output (--template abkowitz|auv|mmg|mmg-beta); "" none.
  std::string model_template;
  /// "" fit the terms as given; "loo" or "kfold:K" (--select): choose among
  /// them by cross-validation (backward elimination, one-standard-error rule).
  std::string select;
  std::uint64_t seed = 1;                  ///< the k-fold shuffle's seed (--seed)
  std::vector<std::string> where;          ///< selection clauses (--where), combined with AND
  std::vector<std::int64_t> exclude_runs;  ///< run ids left out (--exclude-run)
  /// The name to store it under (--name); default BODY:OUTPUT(TERMS), then @SELECTION.
  std::string name;
  bool replace = false;         ///< replace a stored model of the same name (--replace)
  bool store = true;            ///< false: --no-store
  bool weighted = true;         ///< false: --unweighted
  double vif_threshold = 10.0;  ///< VIFs above it are warned of (--vif-threshold)
  /// The nominal speed U0 [m/s] of terms in du = u - U0 (--u0; the
  /// Abkowitz template's surge variable): each run's du is its u less U0.
  /// NaN: not given (a term in du is then refused). Not stored with the
  /// model: `evaluate` takes du itself (--at du=...).
  double u0 = std::numeric_limits<double>::quiet_NaN();

  /// InputError for a missing body or output, an output not X..N, both or
  /// neither of terms and template, a --select other than loo or kfold:K
  /// (K >= 2), a selection clause that does not parse, a bad name, a VIF
  /// threshold not above 1, or a --u0 that is not finite.
  void validate() const;
};

/// One coefficient: the derivative of the output by its term.
struct DerivativeCoefficient {
  std::string term;  ///< canonical, e.g. "v*|v|"
  std::string unit;  ///< e.g. "N/(m/s)^2"; "1" in a non-dimensional form
  double value = 0.0;
  double std_error = std::numeric_limits<double>::quiet_NaN();      ///< one sigma; NaN when undefined
  double interval_low = std::numeric_limits<double>::quiet_NaN();   ///< 95 %
  double interval_high = std::numeric_limits<double>::quiet_NaN();  ///< 95 %
  double vif = std::numeric_limits<double>::quiet_NaN();            ///< variance inflation factor; NaN for the constant
  /// show --form prime|bis|mmg: the normalisation, e.g. "prime (SNAME 1950):
  /// Y_v' = Y_v / (1/2 rho U L^2), L = 3 m, U = 1.5 m/s, rho = 1025 kg/m^3";
  /// "" when dimensional.
  std::string normalisation;
};

/// A fitted (or stored) derivative model.
struct HYDROCOEF_EXPORT DerivativeModel {
  std::string database;
  std::string name;
  std::string body;
  std::string output;          ///< X..N
  std::string terms;           ///< canonical list, "v, r, v*|v|"
  std::string model_template;  ///< "" or the template the terms came from
  std::string selection;       ///< "" or "loo", "kfold:K"
  std::string candidates;      ///< the list a selection chose from ("" without one)
  std::string where;           ///< the run selection, canonical ("" all runs)
  std::string unit;            ///< of the output: "N" or "N m" (rmse's)
  /// "dimensional" (SI), or "prime", "bis", "mmg" (show --form): the
  /// coefficients, standard errors, intervals and covariance are in this form.
  std::string form = "dimensional";
  std::vector<DerivativeCoefficient> coefficients;
  std::vector<double> covariance;  ///< m x m row by row; empty when undefined (as many runs as terms)
  double condition_number = 0.0;   ///< of the (weighted) design with unit-norm columns
  double rmse = 0.0;               ///< [output unit, SI]
  double r2 = std::numeric_limits<double>::quiet_NaN();
  std::size_t n = 0;               ///< runs fitted
  std::string weighting = "none";  ///< "uncertainty" or "none"
  double chi2_reduced = std::numeric_limits<double>::quiet_NaN();
  double covariance_scale = 1.0;
  double interval_factor = std::numeric_limits<double>::quiet_NaN();  ///< t or 1.96 of the intervals
  std::vector<std::int64_t> runs;                                     ///< the runs it was fitted to
  std::vector<std::string> warnings;                                  ///< "kind: message"
  std::int64_t id = 0;                                                ///< 0 when not stored
  bool stale = false;                                                 ///< a force of its runs changed since
  std::string created_at;                                             ///< UTC ISO 8601 (stored models)

  std::string text() const;
  std::string json() const;
};

/// Fits the model to the body's selected runs and stores it (unless
/// options.store is false). InputError, nothing stored, for what validate()
/// refuses, an unknown body, no runs, a term the parser does not know, a
/// template without the output, fewer runs than terms, a run without a
/// name a term needs, terms the runs cannot tell apart, or a taken name.
HYDROCOEF_EXPORT DerivativeModel fit_derivative_model(Database& database, const DerivativeModelOptions& options);

/// The stored models (of one body when body is not ""), by name.
struct HYDROCOEF_EXPORT DerivativeModelList {
  std::string database;
  std::vector<DerivativeModel> models;

  std::string text() const;
  std::string json() const;
};
HYDROCOEF_EXPORT DerivativeModelList list_derivative_models(const Database& database, const std::string& body = "");

/// `hydrocoef derivatives show NAME [--form ...]`.
struct HYDROCOEF_EXPORT DerivativeShowOptions {
  std::string name;
  std::string form = "dimensional";  ///< dimensional, prime, bis or mmg (--form)
  /// Reference values (NaN: not given): --length L [m], --speed U [m/s],
  /// --density RHO [kg/m^3], --draft D [m] (mmg), --mass M [kg] (bis; else
  /// rho times --volume [m^3]), --gravity [m/s^2] (bis; standard gravity).
  double length = std::numeric_limits<double>::quiet_NaN();
  double speed = std::numeric_limits<double>::quiet_NaN();
  double density = std::numeric_limits<double>::quiet_NaN();
  double draft = std::numeric_limits<double>::quiet_NaN();
  double mass = std::numeric_limits<double>::quiet_NaN();
  double volume = std::numeric_limits<double>::quiet_NaN();
  double gravity = 9.80665;

  /// InputError for an empty name, an unknown form, or a given reference
  /// value that is not finite and positive. (A form's missing reference
  /// values are refused by show_derivative_model, naming them.)
  void validate() const;
};

/// A stored model, its coefficients in the form asked for. InputError
/// listing the stored names when there is none of that name; naming the
/// reference value to give when the form needs one; naming the variable
/// when a term's variable has no known normalisation (velocities u, v, w,
/// du; rates p, q, r; angles alpha, beta, delta, delta_*).
HYDROCOEF_EXPORT DerivativeModel show_derivative_model(const Database& database, const DerivativeShowOptions& options);

/// What `hydrocoef derivatives delete NAME` did.
struct HYDROCOEF_EXPORT DerivativeDeletion {
  std::string database;
  std::string name;
  std::int64_t id = 0;

  std::string text() const;
  std::string json() const;
};
/// Deletes a stored model in one transaction. InputError listing the stored
/// names when there is none of that name (nothing deleted).
HYDROCOEF_EXPORT DerivativeDeletion delete_derivative_model(Database& database, const std::string& name);

/// `hydrocoef derivatives evaluate NAME --at v=0.1 --at r=0.02`.
struct HYDROCOEF_EXPORT DerivativeEvaluationOptions {
  std::string name;
  std::map<std::string, double> at;  ///< variable -> value (SI), every variable of the model's terms

  /// InputError for an empty name, no value, or a value that is not finite.
  void validate() const;
};

/// A stored model at one point, with the standard error of its value from
/// the coefficients' covariance C: sqrt(b^T C b), b the terms at the point.
struct HYDROCOEF_EXPORT DerivativeEvaluation {
  std::string name;
  std::string output;  ///< X..N
  std::string unit;    ///< "N" or "N m"
  std::map<std::string, double> at;
  double value = 0.0;
  double std_error = std::numeric_limits<double>::quiet_NaN();  ///< NaN when the covariance is undefined
  std::vector<double> basis;  ///< each term's value at the point, in the order of the terms
  bool stale = false;

  std::string text() const;
  std::string json() const;
};
/// InputError listing the stored names when there is none of that name, and
/// naming the variable when `at` lacks one a term needs.
HYDROCOEF_EXPORT DerivativeEvaluation evaluate_derivative_model(const Database& database,
                                                                const DerivativeEvaluationOptions& options);

}  // namespace api
}  // namespace hydrocoef
