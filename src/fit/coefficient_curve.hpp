// Coefficient curves across a disturbance: how the coefficients of a damping
// law change with a disturbance parameter, for example surge damping
// X(u) = a u + b u|u| under a sway current v_c, where a(v_c) and b(v_c) are
// not constant (the ASR-V study found them changing nonlinearly).
//
// Two steps. fit_per_level fits the law (fit_damping_law) separately to the
// runs at each disturbance level; fit_coefficient_curves then turns each
// coefficient's per-level values into a curve of the level: a least-squares
// polynomial, or a monotone piecewise-cubic Hermite interpolant (PCHIP,
// Fritsch-Carlson slopes with MATLAB pchip's end conditions) through them.
//
// Units: the velocity, force and coefficient units are those of
// damping_law.hpp; a level is in the disturbance's SI unit (m/s for a current
// velocity). Curves do not change signs: a coefficient stays in the sign
// convention of the forces it was fitted to. Curves do not extrapolate:
// evaluating outside the fitted levels is an InputError.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "src/fit/damping_law.hpp"

namespace hydrocoef {

/// One disturbance level and the law fitted to the runs at it.
struct LevelFit {
  double level = 0.0;  ///< disturbance value [its SI unit]
  DampingLawFit fit;
};

/// A level fit_per_level left out, and why.
struct SkippedLevel {
  double level = 0.0;  ///< disturbance value [its SI unit]
  std::size_t runs = 0;
  std::string reason;  ///< "1 run; the damping law 'u,u|u|' has 2 terms and needs ..."
};

/// Fits the law separately at each distinct value of `disturbance`; the runs
/// at a level are those whose disturbance equals it exactly (levels are
/// normally set values such as 0.05, not measured ones).
///   spec:        the law's terms, as for fit_damping_law.
///   x:           velocity component of each run [m/s or rad/s].
///   y:           force component of each run [N or N m].
///   disturbance: disturbance value of each run [its SI unit]; same length as x and y.
///   options:     loss, as for fit_damping_law.
/// Returns one LevelFit per distinct level, in increasing order of level.
/// Throws InputError when the lengths differ, there are no runs, a value is
/// not finite (naming the run, 1-based), or (when `skipped` is null) a level
/// has fewer runs than the law has terms or its fit fails, naming the level.
/// With `skipped`, such levels are left out and listed there instead, so that
/// a sweep with a sparse level can still be fitted per level.
std::vector<LevelFit> fit_per_level(const DampingLawSpec& spec, std::span<const double> x, std::span<const double> y,
                                    std::span<const double> disturbance, const LossOptions& options = {},
                                    std::vector<SkippedLevel>* skipped = nullptr);

enum class CurveKind {
  Polynomial,  ///< least-squares polynomial of a chosen degree in the level
  Pchip        ///< monotone piecewise cubic through the per-level values (1-D Fritsch-Carlson, as MATLAB pchip)
};

/// One law coefficient as a function of the disturbance level.
struct CoefficientCurve {
  std::string term;  ///< the coefficient's term as term_name gives it, e.g. "u|u|"
  CurveKind kind = CurveKind::Polynomial;
  int degree = 0;              ///< polynomial degree; 3 for Pchip (cubic pieces)
  std::vector<double> levels;  ///< strictly increasing [disturbance unit]
  std::vector<double> values;  ///< the coefficient fitted at each level [coefficient unit]
  /// Polynomial only: p_0, p_1, ... in ascending powers of the level, value =
  /// sum_j p_j level^j [coefficient unit / disturbance unit^j]. Empty for Pchip.
  std::vector<double> polynomial;
  /// sqrt(mean over levels of (curve(level) - value)^2) [coefficient unit]; 0
  /// for Pchip, which passes through every value.
  double rmse = 0.0;

  /// The coefficient at `level`. Throws InputError naming the level and the
  /// fitted range when level is outside [levels.front(), levels.back()] or NaN.
  double evaluate(double level) const;
  /// d coefficient / d level at `level` [coefficient unit / disturbance unit];
  /// same range rule as evaluate. At an interior PCHIP level it is the
  /// Fritsch-Carlson slope there (the curve is C1).
  double derivative(double level) const;
};

/// One curve per term of the law, in the law's term order.
///   levels: per-level fits of one law (same variable and terms), e.g. from
///           fit_per_level; need not be sorted, but levels must be distinct.
///   kind:   Polynomial (needs at least degree + 1 levels) or Pchip (at least 2).
///   degree: polynomial degree >= 0; ignored for Pchip.
/// Polynomials are fitted by linear least squares (column-scaled QR), so with
/// exactly degree + 1 levels the polynomial interpolates the values.
/// Throws InputError when there are too few levels for the kind and degree, a
/// level repeats, the fits disagree on the law, or a level or coefficient is
/// not finite.
std::vector<CoefficientCurve> fit_coefficient_curves(const std::vector<LevelFit>& levels, CurveKind kind,
                                                     int degree = 2);

}  // namespace hydrocoef
