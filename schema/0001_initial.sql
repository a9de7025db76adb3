-- hydrocoef run database, migration 1: bodies, source files, runs, their
-- force components (each with the file it came from), damping-law fits.
-- Units are SI throughout: m, s, rad, N, N m, kg m^-3, m^2 s^-1.

CREATE TABLE body (
  id   INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE CHECK (length(name) > 0)
);

-- One row per imported file. A file is known by the SHA-256 of its bytes:
-- importing the same bytes again is a no-op.
CREATE TABLE source_file (
  id               INTEGER PRIMARY KEY,
  path             TEXT NOT NULL,
  sha256           TEXT NOT NULL UNIQUE CHECK (length(sha256) = 64),
  size_bytes       INTEGER NOT NULL,
  importer         TEXT NOT NULL,
  importer_version TEXT NOT NULL,
  imported_at      TEXT NOT NULL  -- UTC, ISO 8601
);

-- A run is one flow condition of a body: its velocity in body axes and its
-- disturbance parameters. disturbance_key is the canonical text of the
-- disturbances ("name=value;..." sorted), kept for the uniqueness of the key.
CREATE TABLE run (
  id               INTEGER PRIMARY KEY,
  body_id          INTEGER NOT NULL REFERENCES body(id),
  u REAL NOT NULL DEFAULT 0, v REAL NOT NULL DEFAULT 0, w REAL NOT NULL DEFAULT 0,  -- m/s
  p REAL NOT NULL DEFAULT 0, q REAL NOT NULL DEFAULT 0, r REAL NOT NULL DEFAULT 0,  -- rad/s
  disturbance_key  TEXT NOT NULL DEFAULT '',
  density          REAL,  -- kg m^-3, NULL when unknown
  kinematic_viscosity REAL,  -- m^2 s^-1, NULL when unknown
  ref_x REAL NOT NULL DEFAULT 0, ref_y REAL NOT NULL DEFAULT 0, ref_z REAL NOT NULL DEFAULT 0,  -- m, body axes
  UNIQUE (body_id, u, v, w, p, q, r, disturbance_key)
);

CREATE TABLE run_disturbance (
  run_id INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
  name   TEXT NOT NULL,
  value  REAL NOT NULL,  -- SI
  PRIMARY KEY (run_id, name)
) WITHOUT ROWID;

-- One generalized force component of a run, with the file and line it came
-- from. Different files may contribute different components of one run.
CREATE TABLE run_force (
  run_id         INTEGER NOT NULL REFERENCES run(id) ON DELETE CASCADE,
  component      TEXT NOT NULL CHECK (component IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  total          REAL NOT NULL,  -- N or N m
  pressure       REAL,
  viscous        REAL,
  sign_convention TEXT NOT NULL CHECK (sign_convention IN ('on-body', 'opposing')),
  source_id      INTEGER NOT NULL REFERENCES source_file(id),
  source_line    INTEGER,
  PRIMARY KEY (run_id, component)
) WITHOUT ROWID;

CREATE INDEX run_force_source ON run_force(source_id);

-- A damping law fitted to the runs of one body: F_dof = sum_k c_k * term_k(variable).
CREATE TABLE fit (
  id              INTEGER PRIMARY KEY,
  name            TEXT NOT NULL UNIQUE,
  body_id         INTEGER NOT NULL REFERENCES body(id),
  dof             TEXT NOT NULL CHECK (dof IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  variable        TEXT NOT NULL CHECK (variable IN ('u', 'v', 'w', 'p', 'q', 'r')),
  terms           TEXT NOT NULL,  -- as given, e.g. "1,u,u|u|"
  loss            TEXT NOT NULL,  -- "squared", "huber:0.01", ...
  run_filter      TEXT NOT NULL DEFAULT '',  -- the selection the runs came from
  sign_convention TEXT NOT NULL CHECK (sign_convention IN ('on-body', 'opposing')),
  n               INTEGER NOT NULL,
  rmse            REAL NOT NULL,
  r2              REAL NOT NULL,
  created_at      TEXT NOT NULL
);

CREATE TABLE fit_coefficient (
  fit_id    INTEGER NOT NULL REFERENCES fit(id) ON DELETE CASCADE,
  position  INTEGER NOT NULL,
  term      TEXT NOT NULL,
  value     REAL NOT NULL,
  std_error REAL,  -- NULL when it cannot be estimated (n <= number of terms)
  PRIMARY KEY (fit_id, position)
) WITHOUT ROWID;

CREATE TABLE fit_run (
  fit_id INTEGER NOT NULL REFERENCES fit(id) ON DELETE CASCADE,
  run_id INTEGER NOT NULL REFERENCES run(id),
  PRIMARY KEY (fit_id, run_id)
) WITHOUT ROWID;
