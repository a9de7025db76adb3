-- PostgreSQL text of migration 5 (schema/0005_imports.sql): the same, except
-- that the references from fit_run and surface_run to run, which SQLite
-- drops by rebuilding the two tables, are dropped in place. The dialect layer
-- (src/store/dialect.hpp) still applies.
-- hydrocoef run database, migration 5: what identifies an import, and a
-- database that can be corrected.
--
-- An import is a file's bytes (source_file, by SHA-256) read with one set of
-- effective settings (key, body, arrays, units, frame, density, reference
-- pressure and point, window, symmetry). The same bytes with the same
-- settings are one import; with other settings they are refused, replaced
-- (--replace) or kept as a second reading of the file (--also NAME). Each
-- force component remembers the import it came from, with every setting's
-- value and source (settings, JSON).
--
-- Fits become stale, like surfaces, when a force of a run they were built
-- from changes or is deleted; the run ids of a fit or surface are kept even
-- when the run is deleted since (fit_run and surface_run no longer refer to
-- run), so a stale fit still says what it was built from.

CREATE TABLE import (
  id                INTEGER PRIMARY KEY,
  source_id         INTEGER NOT NULL REFERENCES source_file(id),
  reading           TEXT NOT NULL DEFAULT '',  -- '' or the name given with --also
  settings_key      TEXT NOT NULL DEFAULT '',  -- canonical effective settings: with the bytes, the identity
  settings          TEXT NOT NULL DEFAULT '',  -- JSON: every setting with value, source and place
  path              TEXT NOT NULL,             -- as given
  resolved_path     TEXT NOT NULL DEFAULT '',  -- absolute, symbolic links resolved
  importer          TEXT NOT NULL,
  importer_version  TEXT NOT NULL,
  hydrocoef_version TEXT NOT NULL DEFAULT '',
  imported_at       TEXT NOT NULL,             -- UTC, ISO 8601
  UNIQUE (source_id, reading)
);

-- The imports of an older database: one per file, settings not recorded.
INSERT INTO import (source_id, path, importer, importer_version, imported_at)
  SELECT id, path, importer, importer_version, imported_at FROM source_file;

ALTER TABLE run_force ADD COLUMN import_id INTEGER REFERENCES import(id);
UPDATE run_force SET import_id = (SELECT import.id FROM import WHERE import.source_id = run_force.source_id);
CREATE INDEX run_force_import ON run_force(import_id);

ALTER TABLE fit ADD COLUMN stale INTEGER NOT NULL DEFAULT 0 CHECK (stale IN (0, 1));

ALTER TABLE fit_run DROP CONSTRAINT fit_run_run_id_fkey;
ALTER TABLE surface_run DROP CONSTRAINT surface_run_run_id_fkey;

-- Any change to a force of a run a fit used makes the fit stale.
CREATE TRIGGER run_force_insert_stales_fits AFTER INSERT ON run_force
BEGIN
  UPDATE fit SET stale = 1 WHERE id IN (SELECT fit_id FROM fit_run WHERE run_id = NEW.run_id);
END;
CREATE TRIGGER run_force_update_stales_fits AFTER UPDATE ON run_force
BEGIN
  UPDATE fit SET stale = 1 WHERE id IN (SELECT fit_id FROM fit_run WHERE run_id = NEW.run_id);
END;
CREATE TRIGGER run_force_delete_stales_fits AFTER DELETE ON run_force
BEGIN
  UPDATE fit SET stale = 1 WHERE id IN (SELECT fit_id FROM fit_run WHERE run_id = OLD.run_id);
END;
