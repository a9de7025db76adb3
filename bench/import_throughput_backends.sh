#!/usr/bin/env bash
# Import throughput into each store backend, with 1 and with 8 writers:
#   bench/import_throughput_backends.sh [HYDROCOEF] [FILES]
# (default: build/release/hydrocoef, FILES = 400).
#
# FILES force tables of 3 runs each (distinct speeds, distinct bytes) are
# imported one file per `hydrocoef import` process, as cluster jobs import
# their cases: by one writer in turn, and by 8 writers at once (each its
# share of the files). Into a new SQLite file, and into a new schema on a
# throw-away PostgreSQL 15 server on a local Unix socket
# (scripts/postgresql-test-server.sh; fsync on, as a real server runs).
# Prints imports/s and runs/s of each, the process start and file reading
# included: what a sweep of small cases sees end to end.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
hydrocoef=$(realpath "${1:-$root/build/release/hydrocoef}")
files=${2:-400}
work=$(mktemp -d)
pg=$(mktemp -d) # its own folder: the server (user nobody under root) cannot enter $work
trap 'bash "$root/scripts/postgresql-test-server.sh" stop "$pg" >/dev/null 2>&1 || true; rm -rf "$work" "$pg"' EXIT
for ((i = 0; i < files; i++)); do
  {
    echo "u [m s^-1],X [N]"
    for k in 0 1 2; do
      u=$(printf '%.4f' "$(echo "0.01 + 0.0003 * ($i * 3 + $k)" | bc -l)")
      echo "$u,-$(echo "11 * $u * $u" | bc -l)"
    done
  } >"$work/t$i.csv"
done
server=$(HYDROCOEF_PG_FSYNC=on bash "$root/scripts/postgresql-test-server.sh" start "$pg")
eval "$server"
url=$HYDROCOEF_TEST_POSTGRESQL
export HYDROCOEF_DB_TIMEOUT=600

# run WRITERS DB: imports every file, writer w taking files w, w+WRITERS, ...
run() {
  local writers=$1 db=$2
  local start=$(date +%s.%N)
  for ((w = 0; w < writers; w++)); do
    (for ((i = w; i < files; i += writers)); do
      "$hydrocoef" --db "$db" import "$work/t$i.csv" --body b --quiet >/dev/null
    done) &
  done
  wait
  local end=$(date +%s.%N)
  local runs
  runs=$("$hydrocoef" --db "$db" runs --json | grep -c '"id"')
  [[ $runs -eq $((files * 3)) ]] || { echo "expected $((files * 3)) runs, found $runs" >&2; exit 1; }
  echo "$end - $start" | bc -l
}

printf '%-12s %-8s %10s %10s %10s\n' backend writers seconds imports/s runs/s
for writers in 1 8; do
  for backend in sqlite postgresql; do
    if [[ $backend == sqlite ]]; then
      db="$work/w$writers.db"
    else
      schema="w$writers"
      psql "$url" -q -c "CREATE SCHEMA $schema"   # a schema of its own on the server
      db="$url&options=-csearch_path%3D$schema"
    fi
    seconds=$(run "$writers" "$db")
    printf '%-12s %-8s %10.2f %10.1f %10.1f\n' "$backend" "$writers" "$seconds" \
      "$(echo "$files / $seconds" | bc -l)" "$(echo "3 * $files / $seconds" | bc -l)"
  done
done
