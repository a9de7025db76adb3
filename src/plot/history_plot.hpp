// The figure of a run's force history as the database keeps it. A run
// averaged from a force history stores, per component, the window that was
// averaged (its first and last abscissa, the number of samples, how it was
// found), the mean (the run's value), its standard error, the spread and the
// drift across the window, and the run's convergence kind with its reason
// (src/store/database.hpp StoredStatistics), and the history in brief
// (HistoryTrace: each of at most 256 bins' least and largest value, the
// whole record when it is shorter; schema/0016_run_force_trace.sql). The
// figure has one panel per averaged component:
//   - the history over the whole record (its bins' extremes as a band, or
//     the samples as a line), the y range fitted to it from the window's
//     start on (the start-up transient before it may leave the panel); a run
//     stored before traces were kept has none, and the title says so;
//   - a window mean (steady-window, transient-window, given-window): the
//     window shaded, the stored value as a line across it, the band of
//     ± one standard error of the mean, the ± one spread (standard deviation
//     of the samples) lines, and the least-squares trend across the window
//     (the stored value -+ half the drift at its ends);
//   - a converged run (final iterate): the final iterate as a point at its
//     iteration, the band of ± its iterative error, and the line of its
//     change per iteration (the stored drift) leading to it.
// Values as stored (N or N m, the component's sign convention).
#pragma once

#include "src/plot/figure.hpp"
#include "src/store/database.hpp"

namespace hydrocoef::plot {

/// Whether any force component of the run is a mean over a force history
/// (has stored statistics).
bool has_history(const StoredRun& run);

/// The figure above, with the run's trace when it has one
/// (RunDatabase::run_trace). InputError naming the run when no component has
/// statistics (a value from a force table or a surface export).
Figure history_figure(const StoredRun& run, const std::optional<HistoryTrace>& trace = std::nullopt);

}  // namespace hydrocoef::plot
