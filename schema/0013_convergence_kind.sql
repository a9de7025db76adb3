-- hydrocoef run database, migration 13: how each averaged force component was
-- obtained from its history (src/history/history_analysis.hpp).
--
-- convergence: the run's convergence kind, decided from its solver's files:
-- 'converged' (a steady run that met its convergence criteria: the value is
-- the final iterate, standard_error its iterative error, spread the
-- fluctuation about the trend of the last iterations, drift the change per
-- iteration there, window_first = window_last the final iteration, samples 1),
-- 'steady-window' (an iteration record that did not converge, averaged over
-- the component's own statistically steady window), 'transient-window' (the
-- same over physical time), 'given-window' (--window); '' for a component
-- stored before the kind was recorded. convergence_reason: why, in words,
-- with the files and lines of the evidence. Each row's window and flags are
-- its component's own.
ALTER TABLE run_force_statistics ADD COLUMN convergence TEXT NOT NULL DEFAULT ''
  CHECK (convergence IN ('', 'converged', 'steady-window', 'transient-window', 'given-window'));
ALTER TABLE run_force_statistics ADD COLUMN convergence_reason TEXT NOT NULL DEFAULT '';
