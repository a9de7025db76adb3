#!/usr/bin/env bash
# Makes tampered copies of a good hydrocoef database, one file per case, for
# tests/reliability/tampered_databases_heavy_test.cpp: every way a database
# received from someone else can be wrong (a foreign trigger or view, a
# dropped column, an impossible schema version, values of the wrong type or
# out of range, hostile names, oversized or truncated blobs, sizes near 2^63,
# a truncated file). Each copy is left in rollback-journal mode, with no -wal
# file beside it, so that its bytes are the whole database.
#   make-tampered.sh GOOD.db OUT_DIR
# The good database must hold the body asr-v with runs, fits, the grid
# surface "surge" and the RBF surface "rbf" (the test makes it).
set -euo pipefail
good=$1
out=$2
mkdir -p "$out"
command -v sqlite3 >/dev/null || { echo "make-tampered.sh: needs the sqlite3 program (Debian package sqlite3)" >&2; exit 1; }

count=0
# case NAME SQL: a copy of the good database with SQL applied.
case_sql() {
  local name=$1 sql=$2
  cp "$good" "$out/$name.db"
  sqlite3 -bail "$out/$name.db" "PRAGMA journal_mode = DELETE; $sql" >/dev/null
  count=$((count + 1))
}
# Statements that break the schema's CHECK constraints need them off.
unchecked() { echo "PRAGMA ignore_check_constraints = 1; $1"; }

rbf_where="WHERE name = 'rbf'"
grid_where="WHERE name = 'surge'"

# The schema version.
case_sql version-negative "PRAGMA user_version = -1;"
case_sql version-1 "PRAGMA user_version = 1;"
case_sql version-2 "PRAGMA user_version = 2;"
case_sql version-3 "PRAGMA user_version = 3;"
case_sql version-future "PRAGMA user_version = 99;"
case_sql version-huge "PRAGMA user_version = 2147483647;"

# The schema itself.
case_sql trigger-deletes-fits "CREATE TRIGGER evil AFTER INSERT ON run_force BEGIN DELETE FROM fit; DELETE FROM surface; END;"
case_sql trigger-on-read-table "CREATE TRIGGER evil2 AFTER UPDATE ON body BEGIN DELETE FROM run; END;"
case_sql view-added "CREATE VIEW all_runs AS SELECT * FROM run;"
case_sql index-added "CREATE INDEX run_u ON run(u);"
case_sql table-added "CREATE TABLE notes(text TEXT);"
case_sql table-dropped "DROP TABLE surface_run;"
case_sql column-dropped "ALTER TABLE run DROP COLUMN ref_z;"
case_sql column-added "ALTER TABLE run ADD COLUMN comment TEXT;"
case_sql trigger-dropped "DROP TRIGGER run_force_insert_stales_surfaces;"

# Values of the wrong type or out of range.
case_sql velocity-text "UPDATE run SET u = 'fast' WHERE id = (SELECT min(id) FROM run);"
case_sql velocity-infinite "UPDATE run SET v = 9e999 WHERE id = (SELECT min(id) FROM run);"
case_sql density-negative "UPDATE run SET density = -1000;"
case_sql force-text "UPDATE run_force SET total = 'abc';"
case_sql force-infinite "UPDATE run_force SET total = -9e999;"
case_sql source-line-text "UPDATE run_force SET source_line = 'line 5';"
case_sql coefficient-text "UPDATE fit_coefficient SET value = 'abc';"
case_sql std-error-negative "UPDATE fit_coefficient SET std_error = -1;"
case_sql fit-count-negative "$(unchecked "UPDATE fit SET n = -5;")"
case_sql fit-r2-text "UPDATE fit SET r2 = 'high';"
case_sql stale-two "$(unchecked "UPDATE surface SET stale = 2;")"
case_sql sign-unknown "$(unchecked "UPDATE run_force SET sign_convention = 'sideways';")"
case_sql surface-kind-unknown "$(unchecked "UPDATE surface SET kind = 'spline' $grid_where;")"
case_sql orphan-fit-run "INSERT INTO fit_run(fit_id, run_id) SELECT min(id), 999999 FROM fit;"
# Statistics of averaged force components (migration 6).
stats_columns="run_id, component, abscissa, window_method, window_first, window_last, samples, flags, standard_error, spread, drift, effective_samples"
case_sql statistics-of-missing-component "INSERT INTO run_force_statistics($stats_columns) SELECT run_id, 'Y', 'time', 'MSER-5', 1, 2, 10, '', 0.1, 0.1, 0, 5 FROM run_force WHERE component = 'X' LIMIT 1;"
case_sql statistics-negative-error "$(unchecked "INSERT INTO run_force_statistics($stats_columns) SELECT run_id, 'X', 'time', 'MSER-5', 1, 2, 10, '', -0.1, 0.1, 0, 5 FROM run_force WHERE component = 'X' LIMIT 1;")"
case_sql statistics-flag-newline "INSERT INTO run_force_statistics($stats_columns) SELECT run_id, 'X', 'time', 'MSER-5', 1, 2, 10, 'drifting' || char(10) || 'system(\"touch PWNED\")', 0.1, 0.1, 0, 5 FROM run_force WHERE component = 'X' LIMIT 1;"
case_sql statistics-abscissa-unknown "$(unchecked "INSERT INTO run_force_statistics($stats_columns) SELECT run_id, 'X', 'lightyears', 'MSER-5', 1, 2, 10, '', 0.1, 0.1, 0, 5 FROM run_force WHERE component = 'X' LIMIT 1;")"

# Surface records.
case_sql quality-not-json "UPDATE surface SET quality = 'not json {';"
case_sql definition-not-json "UPDATE surface SET definition = '{\"axes\": [';"
case_sql definition-wrong-types "UPDATE surface SET definition = json_set(definition, '\$.axes', 'u');"
case_sql definition-axis-hostile "UPDATE surface SET definition = json_set(definition, '\$.axes[0].name', 'u\`touch PWNED\`');"
case_sql definition-unit-newline "UPDATE surface SET definition = json_set(definition, '\$.outputs[0].unit', 'N' || char(10) || 'system(\"touch PWNED\")');"
case_sql grid-blob-truncated "UPDATE surface SET data = substr(data, 1, 8) $grid_where;"
case_sql grid-blob-oversized "UPDATE surface SET data = zeroblob(8000000) $grid_where;"
case_sql grid-blob-odd-size "UPDATE surface SET data = X'0102030405' $grid_where;"
case_sql grid-blob-text "UPDATE surface SET data = 'text' $grid_where;"
case_sql grid-breakpoints-huge "UPDATE surface SET definition = json_set(definition, '\$.axes[0].breakpoints', json('[1e308, -1e308]')) $grid_where;"
case_sql rbf-samples-2-63 "UPDATE surface SET definition = json_set(definition, '\$.rbf.samples', 9223372036854775807) $rbf_where;"
case_sql rbf-samples-wrap "UPDATE surface SET definition = json_set(definition, '\$.rbf.samples', 4611686018427387904), data = zeroblob(32) $rbf_where;"
case_sql rbf-samples-float "UPDATE surface SET definition = json_set(definition, '\$.rbf.samples', 1e300) $rbf_where;"
case_sql rbf-30000-samples "UPDATE surface SET definition = json_remove(json_set(definition, '\$.rbf.samples', 30000), '\$.rbf.solution'), data = zeroblob(480000) $rbf_where;"
case_sql rbf-solution-mismatch "UPDATE surface SET definition = json_set(definition, '\$.rbf.solution.samples_sha256', 'ab') $rbf_where;"
case_sql rbf-terms-huge "UPDATE surface SET definition = json_set(definition, '\$.rbf.solution.polynomial_terms', 9223372036854775807) $rbf_where;"

# Hostile names.
case_sql body-name-newline "UPDATE body SET name = 'asr-v' || char(10) || 'system(\"touch PWNED\")';"
case_sql body-name-backquote "UPDATE body SET name = 'a\`touch PWNED\`b';"
case_sql surface-name-control "UPDATE surface SET name = 'surge' || char(1) $grid_where;"
case_sql fit-name-invalid-utf8 "UPDATE fit SET name = CAST(X'FF41' AS TEXT) WHERE id = (SELECT min(id) FROM fit);"
case_sql disturbance-name-bad "INSERT INTO run_disturbance(run_id, name, value) SELECT min(id), 'a b', 0.5 FROM run;"

# Whole files.
head -c 8192 "$good" > "$out/file-truncated.db"; count=$((count + 1))
head -c 65536 /dev/urandom > "$out/file-random.db"; count=$((count + 1))
: > "$out/file-empty-but-named.db"; count=$((count + 1))

echo "$count"
