-- hydrocoef run database, migration 15: the runs of fits and surfaces found
-- by run. The triggers that make fits and surfaces stale when a run's forces
-- change (migrations 3 and 5) look up fit_run and surface_run by run_id for
-- every force row written or deleted; with only the (fit_id, run_id) and
-- (surface_id, run_id) keys each lookup read the whole table, so replacing or
-- deleting N runs that a fit covers cost N times the table (40,000 runs: 145 s
-- holding the write lock).
CREATE INDEX fit_run_by_run ON fit_run(run_id);
CREATE INDEX surface_run_by_run ON surface_run(run_id);
