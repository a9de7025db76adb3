-- hydrocoef run database, migration 6: the statistics of force components
-- that are means over a force history (an OpenFOAM force file, a CFX
-- monitor, a CSV of time and forces).
--
-- One row per averaged force component: the window of the history that was
-- averaged (abscissa "time" [s] or "iteration"), how it was found, the number
-- of samples, the standard error of the mean corrected for autocorrelation,
-- the spread (standard deviation) and the drift across the window (N or N m,
-- body axes, signed as the component), the effective sample size, and the
-- convergence flags of the history (comma-separated, '' when converged).
-- A component without a row is a value with no statistics (a surface export,
-- a force table). The row goes with its force component: it is written and
-- deleted with it.

CREATE TABLE run_force_statistics (
  run_id            INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
  component         TEXT NOT NULL CHECK (component IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  abscissa          TEXT NOT NULL CHECK (abscissa IN ('time', 'iteration')),
  window_method     TEXT NOT NULL,
  window_first      REAL NOT NULL,
  window_last       REAL NOT NULL,
  samples           INTEGER NOT NULL CHECK (samples >= 0),
  flags             TEXT NOT NULL DEFAULT '',
  standard_error    REAL NOT NULL CHECK (standard_error >= 0),
  spread            REAL NOT NULL CHECK (spread >= 0),
  drift             REAL NOT NULL,
  effective_samples REAL NOT NULL CHECK (effective_samples >= 0),
  PRIMARY KEY (run_id, component)
) WITHOUT ROWID;

-- The planes of symmetry a fit let each run stand for its mirror image in
-- ("v", "v,w", "v/current_v" with the disturbances that change sign; '' for
-- none), so that the fit can be made again as it was.
ALTER TABLE fit ADD COLUMN mirror TEXT NOT NULL DEFAULT '';
