-- PostgreSQL text of migration 4 (schema/0004_fit_statistics_optional.sql),
-- which rebuilds table fit in SQLite to change its constraints; PostgreSQL
-- changes them in place. The dialect layer (src/store/dialect.hpp) still
-- applies.
ALTER TABLE fit ADD CONSTRAINT fit_n_check CHECK (n >= 0);
ALTER TABLE fit ALTER COLUMN rmse DROP NOT NULL;
ALTER TABLE fit ADD CONSTRAINT fit_rmse_check CHECK (rmse >= 0);
ALTER TABLE fit ALTER COLUMN r2 DROP NOT NULL;
