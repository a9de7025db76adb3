-- hydrocoef run database, migration 12: forced-oscillation analyses (a
-- virtual planar motion mechanism; hydrocoef pmm, src/pipeline/pmm_runs.hpp).
--
-- One pmm_run row per analysed run: the body, the mean body velocity of the
-- run (a forward speed under a yaw oscillation; zeros for still water), the
-- imposed motion of one degree of freedom x_dof(t) = amplitude sin(omega t +
-- phase) (dof 0..5 = surge, sway, heave, roll, pitch, yaw; amplitude in m or
-- rad, omega in rad/s, phase in rad), where that motion was read
-- (motion_source: 'constant/dynamicMeshDict:21', '--motion'), whether the
-- body moved in still water or stood in an oscillating stream (then the
-- Froude-Krylov force rho V a was removed with displaced_volume), the window
-- of whole periods the fit used, the number of fitted harmonics, the
-- Keulegan-Carpenter and Stokes numbers of the given body size, the source
-- file by path and SHA-256, and the kept window of the history for plots:
-- `history` is float64 samples, 7 per row (t [s], X Y Z [N], K M N [N m]),
-- at most 4096 rows (every k-th row of a longer window).
--
-- One pmm_coefficient row per force component of a run: its mean, the
-- added-mass entry M_A[component][dof] and the linear damping
-- D[component][dof] (Fossen's signs: F = -M_A x'' - D x'), their standard
-- errors from the period-to-period spread, the fraction of the variance the
-- fit explains, and the harmonics as a JSON list s1, c1, s2, c2, ... (the
-- coefficients of sin k(omega t + phase) and cos k(omega t + phase)).
-- The same file analysed with the same motion again replaces its rows.
CREATE TABLE pmm_run (
  id                 INTEGER PRIMARY KEY,
  body_id            INTEGER NOT NULL REFERENCES body(id),
  u REAL NOT NULL, v REAL NOT NULL, w REAL NOT NULL,
  p REAL NOT NULL, q REAL NOT NULL, r REAL NOT NULL,
  dof                INTEGER NOT NULL CHECK (dof BETWEEN 0 AND 5),
  amplitude          REAL NOT NULL CHECK (amplitude > 0),
  omega              REAL NOT NULL CHECK (omega > 0),
  phase              REAL NOT NULL,
  medium             TEXT NOT NULL CHECK (medium IN ('still water', 'oscillating stream')),
  motion_source      TEXT NOT NULL,
  window_start       REAL NOT NULL,
  window_end         REAL NOT NULL,
  periods            INTEGER NOT NULL CHECK (periods >= 3),
  transient_periods  INTEGER NOT NULL CHECK (transient_periods >= 0),
  samples            INTEGER NOT NULL CHECK (samples > 0),
  harmonics          INTEGER NOT NULL CHECK (harmonics BETWEEN 1 AND 10),
  size               REAL CHECK (size > 0),
  keulegan_carpenter REAL,
  kinematic_viscosity REAL CHECK (kinematic_viscosity > 0),
  stokes_number      REAL,
  rho                REAL CHECK (rho > 0),
  displaced_volume   REAL CHECK (displaced_volume > 0),
  source_path        TEXT NOT NULL,
  source_sha256      TEXT NOT NULL,
  importer           TEXT NOT NULL,
  history            BLOB NOT NULL,
  created_at         TEXT NOT NULL,
  UNIQUE (body_id, source_sha256, dof, amplitude, omega, phase, medium)
);

CREATE TABLE pmm_coefficient (
  pmm_run_id    INTEGER NOT NULL REFERENCES pmm_run(id) ON DELETE CASCADE,
  component     TEXT NOT NULL CHECK (component IN ('X', 'Y', 'Z', 'K', 'M', 'N')),
  mean          REAL NOT NULL,
  added_mass    REAL NOT NULL,
  added_mass_se REAL NOT NULL CHECK (added_mass_se >= 0),
  damping       REAL NOT NULL,
  damping_se    REAL NOT NULL CHECK (damping_se >= 0),
  explained     REAL NOT NULL,
  harmonics     TEXT NOT NULL,
  PRIMARY KEY (pmm_run_id, component)
) WITHOUT ROWID;
