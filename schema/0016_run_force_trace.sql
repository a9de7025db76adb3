-- hydrocoef run database, migration 16: each averaged run's force history in
-- brief (src/history/history_trace.hpp), so that the report and `plot
-- history` draw it from the database alone, long after the CFD files are gone.
--
-- abscissa: 'time' [s] or 'iteration'; samples: in the whole record;
-- components: the force components present, in the data's order ("X,Y,Z,K,M,N"
-- or a part of it); data: float64, the bins' last abscissas (bins values, bins
-- = min(samples, 256)), then per component its bins' least values and their
-- largest values (2 x bins each). Body axes, forces on the body, as the run's.
-- A run's trace is that of its latest history import; a component written
-- without a history takes it away.
CREATE TABLE run_force_trace (
  run_id     INTEGER PRIMARY KEY REFERENCES run(id) ON DELETE CASCADE,
  abscissa   TEXT NOT NULL CHECK (abscissa IN ('time', 'iteration')),
  samples    INTEGER NOT NULL CHECK (samples >= 1),
  components TEXT NOT NULL,
  data       BLOB NOT NULL
);
