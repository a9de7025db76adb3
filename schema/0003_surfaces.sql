-- hydrocoef run database, migration 3: coefficient surfaces built from runs.
-- A surface is stored as the table it evaluates (gridded) or as its samples
-- and build options (scattered), with its quality figures and the runs it
-- came from. It is marked stale as soon as a force component of its body
-- changes, so a user knows to rebuild it.

CREATE TABLE surface (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL UNIQUE CHECK (length(name) > 0),
  body_id       INTEGER NOT NULL REFERENCES body(id),
  kind          TEXT NOT NULL CHECK (kind IN ('grid', 'rbf')),
  method        TEXT NOT NULL,   -- linear, pchip, ... or the RBF kernel
  definition    TEXT NOT NULL,   -- JSON: axes (names, breakpoints, extrapolation), outputs, units, options
  data          BLOB NOT NULL,   -- float64 little-endian values in the layout the definition states
  quality       TEXT NOT NULL,   -- JSON: leave-one-out max and RMS per output, in the output's units
  created_at    TEXT NOT NULL,
  stale         INTEGER NOT NULL DEFAULT 0 CHECK (stale IN (0, 1))
);

CREATE TABLE surface_run (
  surface_id INTEGER NOT NULL REFERENCES surface(id) ON DELETE CASCADE,
  run_id     INTEGER NOT NULL REFERENCES run(id),
  PRIMARY KEY (surface_id, run_id)
) WITHOUT ROWID;

-- Any change to a body's forces makes its surfaces stale.
CREATE TRIGGER run_force_insert_stales_surfaces AFTER INSERT ON run_force
BEGIN
  UPDATE surface SET stale = 1 WHERE body_id = (SELECT body_id FROM run WHERE id = NEW.run_id);
END;
CREATE TRIGGER run_force_update_stales_surfaces AFTER UPDATE ON run_force
BEGIN
  UPDATE surface SET stale = 1 WHERE body_id = (SELECT body_id FROM run WHERE id = NEW.run_id);
END;
CREATE TRIGGER run_force_delete_stales_surfaces AFTER DELETE ON run_force
BEGIN
  UPDATE surface SET stale = 1 WHERE body_id = (SELECT body_id FROM run WHERE id = OLD.run_id);
END;
