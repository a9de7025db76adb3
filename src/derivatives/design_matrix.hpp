// The runs a derivative model is fitted to, and the design matrix built from
// them: one row per run, one column per term (src/derivatives/terms.hpp).
// Shared by the fit (derivative_fit) and the term selection
// (term_selection), so that both check the runs by one rule and see the same
// numbers.
//
// Units: a run's values are the body's velocities relative to the water, its
// rates and angles (SI, body axes x forward, y starboard, z down; or the same
// made non-dimensional), its output a force [N] or moment [N m] on the body
// (or its coefficient), sigma in the output's unit. Nothing here changes a
// sign: the fit is in the runs' own convention.
//
// Weighting follows the project's rule for weighted fits (src/pipeline/
// fit_runs.cpp, fit_weights): the fit is weighted by 1/sigma^2 when asked and
// every run states an uncertainty; when only some do, it is fitted unweighted
// and a warning says how many runs state none.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "src/derivatives/terms.hpp"

namespace hydrocoef {

/// One run: where it was (name -> value) and what was measured there.
struct DerivativeRun {
  std::string label;                     ///< how messages name it, e.g. "run 12"; empty: "run N" (1-based place)
  std::map<std::string, double> values;  ///< u, v, r, delta, ...: SI (m/s, rad/s, rad) or non-dimensional
  double output = 0.0;                   ///< the force or moment [N or N m] (or its coefficient)
  /// One-sigma standard uncertainty of output, in its unit; NaN when the run states none.
  double sigma = std::numeric_limits<double>::quiet_NaN();
};

/// A warning about a fit: a short kind ("collinear-terms", "ill-conditioned",
/// "unweighted", "scatter-exceeds-uncertainty") and one line for people.
struct DerivativeWarning {
  std::string kind;
  std::string message;
};

/// The weighted design with unit-norm columns: scaled(i, k) = t_k(x_i) w_i /
/// column_scale(k), w_i = 1/sigma_i for a weighted fit and 1 otherwise.
struct DesignMatrix {
  Eigen::MatrixXd scaled;        ///< n x m, each column of norm 1
  Eigen::VectorXd column_scale;  ///< m: the norm of each weighted column [term unit / weight unit]
  Eigen::VectorXd rhs;           ///< n: y_i w_i
  Eigen::VectorXd row_weight;    ///< n: w_i [1 / output unit], or 1
  bool weighted = false;
  std::vector<DerivativeWarning> warnings;  ///< "unweighted" when only some runs state an uncertainty
};

/// How messages name run i (0-based): its label, or "run i+1".
std::string run_label(const std::vector<DerivativeRun>& runs, std::size_t i);

/// Checks the runs against the terms and builds the design.
///   output: the output's name for messages ("Y", "N", ...).
///   use_uncertainties: weight by 1/sigma^2 when every run states sigma.
/// Throws InputError (one line) for: no terms; fewer runs than terms (saying
/// how many are needed, and one more for an uncertainty); a run without a
/// value of a name the terms need; a value, output or stated uncertainty
/// that is not finite (or an uncertainty <= 0), naming the run; a term whose
/// value overflows; a term that is zero at every run, naming the names that
/// are constant over the runs.
DesignMatrix make_design(std::string_view output, const std::vector<Term>& terms,
                         const std::vector<DerivativeRun>& runs, bool use_uncertainties);

/// Singular values below this fraction of the largest one (of the design
/// with unit-norm columns) mean the columns are linearly dependent: agreeing
/// to twelve digits is what rounding leaves of an exact dependence (a
/// product with a name that is the same in every run), and no run's data can
/// tell such columns apart.
inline constexpr double kRankTolerance = 1e-12;

/// Throws InputError naming the terms that take part in the (numerical) null
/// space of `design` (singular values below kRankTolerance times the
/// largest), and the names that are constant over the runs among theirs.
/// Does nothing when the columns are independent. `svd` is design.scaled's
/// singular value decomposition with V computed.
void refuse_dependent_terms(std::string_view output, const std::vector<Term>& terms,
                            const std::vector<DerivativeRun>& runs, const Eigen::JacobiSVD<Eigen::MatrixXd>& svd);

/// "u = 2 at every run" for each name of `names` that has one value over
/// all runs, joined by "; " (empty when none has).
std::string constant_names_note(const std::vector<std::string>& names, const std::vector<DerivativeRun>& runs);

/// "a", "a and b", "a, b and c".
std::string and_list(const std::vector<std::string>& items);

}  // namespace hydrocoef
