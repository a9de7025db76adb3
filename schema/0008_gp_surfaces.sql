-- hydrocoef run database, migration 8: Gaussian-process surfaces.
--
-- A surface may be of kind 'gp' (src/surface/stored_gp_surface.hpp: the
-- solved state of one Gaussian process per output, so that loading needs no
-- new factorisation). SQLite cannot change a CHECK constraint in place, so
-- the table is rebuilt with the same columns and rows. The triggers that mark
-- surfaces stale name the table in their bodies: they are dropped first and
-- made again as migration 3 made them, so that renaming the new table finds
-- no trigger naming a missing one. Migrations run with foreign keys off
-- (surface_run's rows keep their surface ids; they are checked before the
-- commit).

DROP TRIGGER run_force_insert_stales_surfaces;
DROP TRIGGER run_force_update_stales_surfaces;
DROP TRIGGER run_force_delete_stales_surfaces;

CREATE TABLE surface_new (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL UNIQUE CHECK (length(name) > 0),
  body_id       INTEGER NOT NULL REFERENCES body(id),
  kind          TEXT NOT NULL CHECK (kind IN ('grid', 'rbf', 'gp')),
  method        TEXT NOT NULL,   -- linear, pchip, ..., the RBF kernel or the GP kernel
  definition    TEXT NOT NULL,   -- JSON: axes (names, breakpoints, extrapolation), outputs, units, options
  data          BLOB NOT NULL,   -- float64 little-endian values in the layout the definition states
  quality       TEXT NOT NULL,   -- JSON: leave-one-out max and RMS per output, in the output's units
  created_at    TEXT NOT NULL,
  stale         INTEGER NOT NULL DEFAULT 0 CHECK (stale IN (0, 1))
);
INSERT INTO surface_new (id, name, body_id, kind, method, definition, data, quality, created_at, stale)
  SELECT id, name, body_id, kind, method, definition, data, quality, created_at, stale FROM surface;
DROP TABLE surface;
ALTER TABLE surface_new RENAME TO surface;

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
