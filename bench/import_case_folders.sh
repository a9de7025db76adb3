#!/usr/bin/env bash
# A sweep of N OpenFOAM case folders imported end to end by one command:
#   bench/import_case_folders.sh [HYDROCOEF] [N]
# (default: build/release/hydrocoef, N = 1000).
#
# The cases are copies of data/openfoam-sphere/cases/u0.10_v0.00 as the solver
# left it, without its VTK output (system/, constant/, 0/, postProcessing/:
# 1,000 iterations of force.dat and moment.dat), each with its own free stream
# in 0/U (u = 0.1 + i*1e-4 m/s) and its own force file bytes (the case number
# in force.dat's first comment), so that every case is a run of its own. The
# import reads every case's dictionaries, joins its force histories, finds the
# steady window and stores the runs in one transaction.
#
# Prints files/s and the time of each stage from `import --json` (timing_s:
# plan = folder walk and case settings, read = parsing and window analysis on
# every core, store = the transaction); the share outside parsing and analysis
# is (total - read) / total, total being the process's wall-clock time.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
hydrocoef=$(realpath "${1:-$root/build/release/hydrocoef}")
count=${2:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source_case="$root/data/openfoam-sphere/cases/u0.10_v0.00"

echo "making $count case folders in $work ..."
mkdir -p "$work/template"
cp -r "$source_case/0" "$source_case/constant" "$source_case/system" "$work/template/"
mkdir -p "$work/template/postProcessing"
cp -r "$source_case/postProcessing/forces" "$work/template/postProcessing/"
for ((i = 0; i < count; ++i)); do
  case_dir=$(printf '%s/sweep/case%04d' "$work" "$i")
  cp -r "$work/template" "$case_dir" 2>/dev/null || { mkdir -p "$work/sweep"; cp -r "$work/template" "$case_dir"; }
  u=$(awk -v i="$i" 'BEGIN { printf "%.4f", 0.1 + i * 1e-4 }')
  sed -i "s/uniform (0.1 0 0)/uniform ($u 0 0)/g" "$case_dir/0/U"
  sed -i "1s/.*/# Force (case $i)/" "$case_dir/postProcessing/forces/0/force.dat"
done
bytes=$(du -sb "$work/sweep" | cut -f1)

cd "$work"
start=$(date +%s.%N)
"$hydrocoef" --db bench.db import sweep --body sphere --axes=-x,y,-z --quiet --json > import.json
end=$(date +%s.%N)
python3 - "$start" "$end" "$count" "$bytes" <<'PY'
import json, sys
start, end, count, size = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
out = json.load(open("import.json"))
total = end - start
t = out["timing_s"]
runs = out["summary"]["runs_created"]
print(f"{count} case folders ({size / 1e6:.0f} MB), {runs} runs stored in {total:.2f} s: {count / total:.0f} cases/s")
print(f"  plan (walk, 0/U, controlDict, transportProperties) {t['plan']:.2f} s, "
      f"read (force histories parsed and analysed on every core) {t['read']:.2f} s, store {t['store']:.2f} s")
print(f"  outside parsing and analysis: {100 * (total - t['read']) / total:.0f} % of the wall-clock time")
assert runs == count, f"expected {count} runs, stored {runs}"
PY
