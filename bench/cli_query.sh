#!/usr/bin/env bash
# Batch queries through the command line: 1 million random points of a 2-D
# 20 x 20 surface over (u, v) with six outputs (X..N), PCHIP, read from a CSV
# file and written to a CSV file (and once through a pipe, stdin to stdout).
# Goal: >= 1 million points per second.
#
#   bench/cli_query.sh [HYDROCOEF_BINARY] [POINTS]
#
# Default binary: build/release/hydrocoef (bash scripts/build.sh release).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
hydrocoef=${1:-$here/../build/release/hydrocoef}
points=${2:-1000000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A 20 x 20 table of runs; the forces are smooth functions of (u, v).
awk 'BEGIN {
  print "u [m s^-1],v [m s^-1],X [N],Y [N],Z [N],K [N m],M [N m],N [N m]"
  for (j = 0; j < 20; ++j) for (i = 0; i < 20; ++i) {
    u = -0.5 + i / 19.0; v = -0.3 + 0.6 * j / 19.0
    printf "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", u, v,
      -11 * u * (u < 0 ? -u : u) - 0.02 * u, -9 * v * (v < 0 ? -v : v) + 0.3 * u * v, 0.1 * u * v,
      0.01 * v, -0.02 * u * v, -0.08 * v * u
  }
}' >"$work/runs.csv"
"$hydrocoef" --db "$work/b.db" import "$work/runs.csv" --body bench >/dev/null
"$hydrocoef" --db "$work/b.db" surface build all6 --body bench --outputs X,Y,Z,K,M,N --axes u,v --method pchip \
  >/dev/null
awk -v n="$points" 'BEGIN { srand(1); print "u,v"; for (k = 0; k < n; ++k) printf "%.9f,%.9f\n", -0.5 + rand(), -0.3 + 0.6 * rand() }' \
  >"$work/points.csv"

seconds() { date +%s.%N; }
t0=$(seconds)
"$hydrocoef" --db "$work/b.db" query all6 --input "$work/points.csv" --output "$work/out.csv" 2>/dev/null
t1=$(seconds)
"$hydrocoef" --db "$work/b.db" query all6 --input - <"$work/points.csv" >"$work/out2.csv"
t2=$(seconds)
rows=$(($(wc -l <"$work/out.csv") - 1))
cmp -s "$work/out.csv" "$work/out2.csv" || { echo "file and pipe outputs differ" >&2; exit 1; }
awk -v n="$rows" -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN {
  printf "cli batch query, 2-D 20x20 pchip, 6 outputs: %d points\n", n
  printf "  file to file:    %.3f s  %.2f M points/s\n", b - a, n / (b - a) / 1e6
  printf "  stdin to stdout: %.3f s  %.2f M points/s\n", c - b, n / (c - b) / 1e6
}'
