-- hydrocoef run database, migration 10: an uncertainty given at import.
--
-- uncertainty: the standard uncertainty of a force component's value that
-- the user stated when importing it (hydrocoef import --uncertainty X=0.01,
-- or X=2% of the value), in N or N m; NULL when none was stated. It is
-- combined with the standard error of a mean over a force history
-- (run_force_statistics) in quadrature, sqrt(se^2 + u^2), wherever a run's
-- uncertainty is used (weighted fits, GP surfaces).

ALTER TABLE run_force ADD COLUMN uncertainty REAL CHECK (uncertainty >= 0);
