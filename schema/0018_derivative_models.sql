-- hydrocoef run database, migration 18: derivative models of several
-- variables (hydrocoef derivatives fit; src/derivatives/, src/store/
-- derivative_store.hpp), fitted to all the selected runs of a body at once.
--
-- derivative_model: one fitted model. output X..N (a force [N] or moment
-- [N m] on the body, body axes x forward, y starboard, z down); terms: the
-- canonical term list ("v, r, v*|v|, u*v"; src/derivatives/terms.hpp);
-- model_template: '' or the template the terms came from ('abkowitz', 'auv',
-- 'mmg', 'mmg-beta'); selection: '' or how the terms were chosen from the
-- candidates by cross-validation ('loo', 'kfold:K'), candidates: the list
-- chosen from ('' without selection); run_filter: the selection's canonical
-- text ('' all runs); weighting: 'uncertainty' (each run weighted by 1/s^2 of
-- its standard uncertainty) or 'none'; the statistics of the fit (rmse in the
-- output's unit; r2, chi2_reduced and interval_factor NULL when undefined);
-- covariance: the coefficients' covariance, m x m row by row, as a JSON list
-- of numbers (null where undefined); warnings: a JSON list of
-- {"kind", "message"}. A model becomes stale when a force of a run it was
-- fitted to changes or is deleted; its run ids are kept.
--
-- derivative_coefficient: one per term, in the order of terms: the
-- coefficient [output unit / term unit, SI], its standard error, its 95 %
-- interval and its variance inflation factor (NULL when undefined).
CREATE TABLE derivative_model (
  id               INTEGER PRIMARY KEY,
  name             TEXT NOT NULL UNIQUE,
  body_id          INTEGER NOT NULL REFERENCES body(id),
  output           TEXT NOT NULL CHECK (output IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  terms            TEXT NOT NULL,
  model_template   TEXT NOT NULL,
  selection        TEXT NOT NULL,
  candidates       TEXT NOT NULL,
  run_filter       TEXT NOT NULL,
  weighting        TEXT NOT NULL CHECK (weighting IN ('none', 'uncertainty')),
  n                INTEGER NOT NULL CHECK (n >= 1),
  rmse             REAL NOT NULL CHECK (rmse >= 0),
  r2               REAL,
  condition_number REAL NOT NULL CHECK (condition_number >= 1),
  chi2_reduced     REAL CHECK (chi2_reduced >= 0),
  covariance_scale REAL NOT NULL CHECK (covariance_scale > 0),
  interval_factor  REAL CHECK (interval_factor > 0),
  covariance       TEXT NOT NULL,
  warnings         TEXT NOT NULL,
  created_at       TEXT NOT NULL,
  stale            INTEGER NOT NULL DEFAULT 0 CHECK (stale IN (0, 1))
);

CREATE TABLE derivative_coefficient (
  model_id      INTEGER NOT NULL REFERENCES derivative_model(id) ON DELETE CASCADE,
  position      INTEGER NOT NULL CHECK (position >= 0),
  term          TEXT NOT NULL,
  value         REAL NOT NULL,
  std_error     REAL CHECK (std_error >= 0),
  interval_low  REAL,
  interval_high REAL,
  vif           REAL,
  PRIMARY KEY (model_id, position)
) WITHOUT ROWID;

CREATE TABLE derivative_model_run (
  model_id INTEGER NOT NULL REFERENCES derivative_model(id) ON DELETE CASCADE,
  run_id   INTEGER NOT NULL,
  PRIMARY KEY (model_id, run_id)
) WITHOUT ROWID;
CREATE INDEX derivative_model_run_by_run ON derivative_model_run(run_id);

-- Any change to a force of a run a model used makes the model stale.
CREATE TRIGGER run_force_insert_stales_derivative_models AFTER INSERT ON run_force
BEGIN
  UPDATE derivative_model SET stale = 1 WHERE id IN (SELECT model_id FROM derivative_model_run WHERE run_id = NEW.run_id);
END;
CREATE TRIGGER run_force_update_stales_derivative_models AFTER UPDATE ON run_force
BEGIN
  UPDATE derivative_model SET stale = 1 WHERE id IN (SELECT model_id FROM derivative_model_run WHERE run_id = NEW.run_id);
END;
CREATE TRIGGER run_force_delete_stales_derivative_models AFTER DELETE ON run_force
BEGIN
  UPDATE derivative_model SET stale = 1 WHERE id IN (SELECT model_id FROM derivative_model_run WHERE run_id = OLD.run_id);
END;
