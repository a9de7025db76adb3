-- hydrocoef run database, migration 17: each body's reference data, for the
-- non-dimensional coefficients of its runs (`hydrocoef body set`, `runs
-- --coefficients`): C_F = F / (1/2 rho U^2 A), C_M = M / (1/2 rho U^2 A L),
-- Re = U L / nu, Fn = U / sqrt(g L). NULL: not given.
--
-- reference_length L [m]; draft [m]; displaced_volume [m^3]; the moment
-- reference point (moment_x, moment_y, moment_z) [m], body axes, all three or
-- none (none: moments about each run's own reference point); default_area:
-- the name of one of the body's areas (body_reference_area), the one used
-- when no other is asked for.
CREATE TABLE body_reference (
  body_id          INTEGER PRIMARY KEY REFERENCES body(id) ON DELETE CASCADE,
  reference_length REAL CHECK (reference_length > 0),
  draft            REAL CHECK (draft > 0),
  displaced_volume REAL CHECK (displaced_volume > 0),
  moment_x REAL, moment_y REAL, moment_z REAL,
  default_area     TEXT,
  updated_at       TEXT NOT NULL,  -- UTC, ISO 8601
  CHECK ((moment_x IS NULL) = (moment_y IS NULL) AND (moment_y IS NULL) = (moment_z IS NULL))
);

-- The named reference areas of a body [m^2] (frontal, wetted, planform,
-- "L*d", "L^2": any name, several per body).
CREATE TABLE body_reference_area (
  body_id INTEGER NOT NULL REFERENCES body(id) ON DELETE CASCADE,
  name    TEXT NOT NULL CHECK (length(name) > 0),
  area    REAL NOT NULL CHECK (area > 0),
  PRIMARY KEY (body_id, name)
) WITHOUT ROWID;
