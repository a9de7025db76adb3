-- PostgreSQL text of migration 8 (schema/0008_gp_surfaces.sql), which
-- rebuilds table surface in SQLite (dropping and re-creating its staleness
-- triggers) to allow kind 'gp'; PostgreSQL changes the constraint in place.
ALTER TABLE surface DROP CONSTRAINT surface_kind_check;
ALTER TABLE surface ADD CONSTRAINT surface_kind_check CHECK (kind IN ('grid', 'rbf', 'gp'));
