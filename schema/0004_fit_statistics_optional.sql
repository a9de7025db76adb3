-- hydrocoef run database, migration 4: a fit's RMSE and R^2 may be absent.
-- R^2 is undefined when the fitted force does not vary (a symmetric body's
-- side force is exactly constant) and the RMSE carries no information when
-- there are no more runs than terms; both are then stored as NULL and shown
-- as n/a, instead of failing the fit. The table is rebuilt (SQLite cannot
-- drop a NOT NULL constraint); hydrocoef runs this with foreign keys off and
-- checks them before committing.

CREATE TABLE fit_new (
  id              INTEGER PRIMARY KEY,
  name            TEXT NOT NULL UNIQUE,
  body_id         INTEGER NOT NULL REFERENCES body(id),
  dof             TEXT NOT NULL CHECK (dof IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  variable        TEXT NOT NULL CHECK (variable IN ('u', 'v', 'w', 'p', 'q', 'r')),
  terms           TEXT NOT NULL,  -- as given, e.g. "1,u,u|u|"
  loss            TEXT NOT NULL,  -- "squared", "huber:0.01", ...
  run_filter      TEXT NOT NULL DEFAULT '',  -- the selection the runs came from
  sign_convention TEXT NOT NULL CHECK (sign_convention IN ('on-body', 'opposing')),
  n               INTEGER NOT NULL CHECK (n >= 0),
  rmse            REAL CHECK (rmse >= 0),  -- N or N m; NULL when undefined
  r2              REAL,                    -- NULL when undefined (constant data)
  created_at      TEXT NOT NULL
);

INSERT INTO fit_new (id, name, body_id, dof, variable, terms, loss, run_filter, sign_convention, n, rmse, r2,
                     created_at)
  SELECT id, name, body_id, dof, variable, terms, loss, run_filter, sign_convention, n, rmse, r2, created_at FROM fit;

DROP TABLE fit;
ALTER TABLE fit_new RENAME TO fit;
