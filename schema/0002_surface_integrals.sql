-- hydrocoef run database, migration 2: what is kept of an integrated
-- surface for each run (geometry checks and the integrals that let forces be
-- recomputed for another reference pressure or moment point). Body axes, SI.

CREATE TABLE run_surface (
  run_id            INTEGER PRIMARY KEY REFERENCES run(id) ON DELETE CASCADE,
  source_id         INTEGER NOT NULL REFERENCES source_file(id),
  faces             INTEGER NOT NULL,
  area              REAL NOT NULL,     -- m^2
  signed_volume     REAL NOT NULL,     -- m^3
  closed            INTEGER NOT NULL CHECK (closed IN (0, 1)),
  boundary_edges    INTEGER NOT NULL,
  degenerate_faces  INTEGER NOT NULL,
  normals_flipped   INTEGER NOT NULL CHECK (normals_flipped IN (0, 1)),
  n_dA_x REAL NOT NULL, n_dA_y REAL NOT NULL, n_dA_z REAL NOT NULL,                    -- ∫ n dA, m^2
  x_cross_n_dA_x REAL NOT NULL, x_cross_n_dA_y REAL NOT NULL, x_cross_n_dA_z REAL NOT NULL,  -- ∫ x × n dA, m^3
  reference_pressure REAL NOT NULL,  -- Pa
  pressure_array    TEXT NOT NULL,
  shear_array       TEXT NOT NULL,
  pressure_kind     TEXT NOT NULL CHECK (pressure_kind IN ('static', 'kinematic')),
  shear_convention  TEXT NOT NULL CHECK (shear_convention IN ('on-wall', 'on-fluid')),
  axes              TEXT NOT NULL
);
