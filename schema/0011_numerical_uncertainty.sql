-- hydrocoef run database, migration 11: numerical uncertainty from a mesh
-- study (hydrocoef gci; src/pipeline/grid_convergence_runs.hpp).
--
-- One row per body, physical key and force component: the grid-convergence
-- index of Celik et al. (ASME J. Fluids Eng. 130, 2008, 078001) from the
-- runs of that key at the three finest mesh levels. The physical key is the
-- run key without its mesh parameters: the velocity u..r and the canonical
-- text of the other disturbances (disturbance_key, as in table run). The
-- mesh parameter (mesh_parameter, e.g. 'mesh') marks a run's mesh level;
-- fine_level is its value on the finest mesh, whose runs of the key the
-- result applies to: numerical_uncertainty = gci_fine * |phi1| / 2, in N or
-- N m (NULL when the procedure gave no GCI), combined in quadrature with a
-- run's other uncertainties. h1..h3 are the representative cell sizes (m,
-- or relative to the domain when no volume was given), phi1..phi3 the
-- component's values, fine to coarse. gci runs again replace the rows of a key.
CREATE TABLE numerical_uncertainty (
  body_id          INTEGER NOT NULL REFERENCES body(id),
  u REAL NOT NULL, v REAL NOT NULL, w REAL NOT NULL,
  p REAL NOT NULL, q REAL NOT NULL, r REAL NOT NULL,
  disturbance_key  TEXT NOT NULL,
  component        TEXT NOT NULL CHECK (component IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  mesh_parameter   TEXT NOT NULL,
  fine_level       REAL NOT NULL,
  levels           INTEGER NOT NULL CHECK (levels >= 3),
  h1 REAL NOT NULL, h2 REAL NOT NULL, h3 REAL NOT NULL,
  phi1 REAL NOT NULL, phi2 REAL NOT NULL, phi3 REAL NOT NULL,
  convergence      TEXT NOT NULL CHECK (convergence IN ('monotonic', 'oscillatory', 'converged', 'not found')),
  apparent_order   REAL,
  extrapolated     REAL,
  relative_error   REAL,
  extrapolated_relative_error REAL,
  gci_fine         REAL CHECK (gci_fine >= 0),
  numerical_uncertainty REAL CHECK (numerical_uncertainty >= 0),
  note             TEXT NOT NULL DEFAULT '',
  created_at       TEXT NOT NULL,
  PRIMARY KEY (body_id, u, v, w, p, q, r, disturbance_key, component)
) WITHOUT ROWID;
