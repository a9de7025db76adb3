// The value of a steady run that met its solver's convergence criteria, and
// the iterative error left in it.
//
// A steady solver (simpleFoam, a CFX steady run) stops when its residuals
// fall below the case's criteria; the integrated forces are then still
// creeping towards the value of the fully converged solution. The stored
// value is the final iterate, and its uncertainty the iterative error that
// remains: for a fixed-point iteration converging geometrically at a rate
// lambda per iteration, the error of iterate n is the sum of the changes to
// come,
//     x_inf - x_n = delta_n (lambda + lambda^2 + ...) = delta_n lambda / (1 - lambda),
// with delta_n the change per iteration at the end (Ferziger & Peric,
// "Computational Methods for Fluid Dynamics", 3rd ed., Springer 2002,
// section 5.7, where the rate is the iteration matrix's largest eigenvalue).
// The rate is the one the solver's residuals show over the record's tail (the
// slowest of the controlled fields: src/history/convergence_evidence.hpp);
// without residuals, the component's own changes, where they decay. It is
// capped at kMaxIterationRate: a rate that close to 1 states an iterative
// error of up to 1000 changes per iteration, which says "not converged".
//
// delta_n is the least-squares slope over the last samples (a twentieth of
// the record, 5 to 20 samples): for a geometric tail that is the change a few
// iterations back, larger than the last by lambda^(-tail/2), so the estimate
// errs on the safe side (by 10 % at lambda = 0.99, 36 % at 0.97 over 20
// samples). The fluctuation is the root-mean-square scatter of those samples
// about that line (a run converging with a small limit cycle). The standard
// uncertainty is the two in quadrature.
#pragma once

#include <cstddef>
#include <span>

namespace hydrocoef {

inline constexpr double kMaxIterationRate = 0.999;

struct IterativeError {
  double value = 0.0;                 ///< the final iterate
  double change_per_iteration = 0.0;  ///< delta_n: slope over the tail, per sample
  double rate = 0.0;                  ///< lambda used, in [0, kMaxIterationRate]
  bool rate_from_residuals = false;   ///< else from the series' own changes
  double extrapolated_error = 0.0;    ///< |delta_n| lambda / (1 - lambda), >= 0
  double fluctuation = 0.0;           ///< RMS scatter about the tail's line, >= 0
  double standard_uncertainty = 0.0;  ///< hypot(extrapolated_error, fluctuation)
  std::size_t tail = 0;               ///< samples in the tail
};

/// The final iterate of `values` (one per iteration, at least one, finite)
/// with its iterative error. `residual_rate`: the residuals' rate per
/// iteration over the tail (> 0), or NaN when the solver's residuals are not
/// known.
IterativeError iterative_error(std::span<const double> values, double residual_rate);

/// The slowest geometric decay rate per sample of a positive series over its
/// last quarter (at least 10 samples): exp of the least-squares slope of
/// log(series). NaN when fewer than 10 positive finite values are there.
double decay_rate(std::span<const double> series);

}  // namespace hydrocoef
