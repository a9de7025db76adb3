-- hydrocoef run database, migration 9: fits weighted by the runs'
-- uncertainties.
--
-- weighting:    'none' (ordinary least squares), or 'uncertainty' (each
--               run weighted by 1/s^2, s the standard uncertainty of its
--               force component: the standard error of a mean over a force
--               history, with any uncertainty given at import).
-- chi2_reduced: of a weighted fit, sum((r_i/s_i)^2) / (n - k); NULL for an
--               unweighted fit or n <= k.
-- covariance:   the coefficients' covariance as JSON, k x k numbers row by
--               row in the coefficients' units ([unit_i x unit_j]); '' when
--               not recorded (fits made before this version).
-- Fits made before this version were unweighted.

ALTER TABLE fit ADD COLUMN weighting TEXT NOT NULL DEFAULT 'none' CHECK (weighting IN ('none', 'uncertainty'));
ALTER TABLE fit ADD COLUMN chi2_reduced REAL CHECK (chi2_reduced >= 0);
ALTER TABLE fit ADD COLUMN covariance TEXT NOT NULL DEFAULT '';
