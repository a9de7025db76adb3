// The value of a steady run that met its solver's convergence criteria, and
// the iterative error left in it.
//
// A steady solver (simpleFoam, a CFX steady run) stops when its residuals
// fall below the case's criteria; the integrated forces are then still
// creeping towards the value of the fully converged solution, and not at the
// rate the residuals fall: on the repository's own runs stopped at
// residualControl 1e-4 (data/openfoam-sphere/converged, each continued to
// full convergence) the lateral force of a quarter sphere was still 1.6-2.6 %
// from its converged value while the residuals decayed by 3-5 % per
// iteration, and the change per iteration times lambda / (1 - lambda) with the
// residuals' rate (Ferziger & Peric, "Computational Methods for Fluid
// Dynamics", section 5.7) fell short of the distance by up to 5 times. So the
// error is taken from what the force record itself shows, as the larger of
//   - the change over the last quarter of the record, |x_n - x_(n - n/4)|: how
//     far the value still moved lately;
//   - the distance to the limit of an exponential approach fitted to the last
//     half of the record, x_i = x_inf + A exp(-i / tau), least squares
//     for tau on a log-spaced grid from 2 iterations to half the record
//     (longer time constants are a drift the record cannot extrapolate),
//     refined by a golden-section search: |x_n - x_inf|.
// On those twelve runs (36 components) this covered every converged value
// within one such error, at 1-6 % of the force: the honest size of the
// iterative error at that criterion. It errs on the safe side where a force
// creeps almost linearly (the drag there, by up to 9 times).
//
// Cost: O(n) per tau tried on the last half of the record (about 100).
#pragma once

#include <cstddef>
#include <span>

namespace hydrocoef {

struct IterativeError {
  double value = 0.0;                 ///< the final iterate
  double recent_change = 0.0;         ///< |x_n - x_(n - n/4)|
  double extrapolated = 0.0;          ///< x_inf of the exponential fit (the final iterate when too short)
  double time_constant = 0.0;         ///< tau of that fit, in iterations (0 when none)
  double change_per_iteration = 0.0;  ///< least-squares slope over the last 5 to 20 samples
  double fluctuation = 0.0;           ///< RMS scatter of the last half about the fit
  double standard_uncertainty = 0.0;  ///< max(recent_change, |x_n - x_inf|)
};

/// The final iterate of `values` (one per iteration, at least one, finite)
/// with its iterative error.
IterativeError iterative_error(std::span<const double> values);

/// The slowest geometric decay rate per sample of a positive series over its
/// last quarter (at least 10 samples): exp of the least-squares slope of
/// log(series). NaN when fewer than 10 positive finite values are there.
/// (The residuals' rate, reported with a converged run.)
double decay_rate(std::span<const double> series);

}  // namespace hydrocoef
