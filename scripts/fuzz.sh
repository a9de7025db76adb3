#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with Clang in build/fuzz and runs
# each for SECONDS (default 60), printing the executions per target.
#   scripts/fuzz.sh [SECONDS] [TARGET...]      e.g. scripts/fuzz.sh 600 cfdpost_export_fuzz
#   scripts/fuzz.sh --build-only               build them only (the test command's sanitizer build makes
#                                              its own for the smoke run: HYDROCOEF_FUZZ_SMOKE)
# Each target first replays its regression files (tests/data/bad/fuzz-regressions/
# TARGET/) and its seeds, then fuzzes with a fixed seed from a working corpus
# kept in build/fuzz/corpus/TARGET. An input that crashes, leaks or hangs is
# copied into tests/data/bad/fuzz-regressions/TARGET/ (commit it, fix the
# parser) and the script exits with status 1.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_only=false
if [[ ${1:-} == --build-only ]]; then build_only=true; shift; fi
seconds=${1:-60}
shift || true
dir=${HYDROCOEF_FUZZ_BUILD_DIR:-$root/build/fuzz}
jobs=$(nproc 2>/dev/null || echo 2)
regressions="$root/tests/data/bad/fuzz-regressions"

bash "$root/scripts/install-deps.sh"
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [[ ! -f "$dir/CMakeCache.txt" ]]; then
  # -O1 with line tables: what libFuzzer's documentation builds with, and a
  # quarter less compile time than RelWithDebInfo's -O2 -g.
  cmake -S "$root" -B "$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DHYDROCOEF_FUZZ=ON \
    -DHYDROCOEF_BUILD_TESTS=OFF -DHYDROCOEF_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$dir" -j "$jobs" --target hydrocoef_fuzz
if $build_only; then exit 0; fi

# Seeds: the good and bad files the project already has, per parser.
seed_files() {
  case "$1" in
    force_table_fuzz) ls "$root"/examples/asr-v/*.csv "$root"/tests/data/bad/table-*.csv ;;
    cfx_monitor_fuzz) ls "$root"/tests/data/bad/monitor-*.csv ;;
    cfdpost_export_fuzz) ls "$root"/tests/data/bad/cfdpost-*.csv "$root"/data/cfx-samples/*.csv 2>/dev/null || true ;;
    vehicle_fuzz) ls "$root"/examples/asr-v/vehicle*.json 2>/dev/null || true ;;
    scenario_fuzz) ls "$root"/examples/asr-v/scenario*.json 2>/dev/null || true ;;
    vtp_fuzz) ls "$root"/tests/data/vtp-encodings/*.vtp "$root"/tests/data/bad/vtp-*.vtp ;;
    stored_record_fuzz) ls "$root"/tests/data/fuzz-seeds/stored-record-* ;;
    case_motion_fuzz) ls "$root"/tests/data/fuzz-seeds/case-motion.ccl "$root"/tests/data/cfx/*.ccl 2>/dev/null || true ;;
    cfx_ccl_fuzz) ls "$root"/tests/data/fuzz-seeds/*.ccl "$root"/tests/data/cfx/*.ccl 2>/dev/null || true ;;
    openfoam_dictionary_fuzz) ls "$root"/tests/data/fuzz-seeds/*.foam "$root"/data/openfoam-sphere/cases/*/system/controlDict \
                                 "$root"/data/openfoam-sphere/cases/*/0/U 2>/dev/null || true ;;
  esac
}
write_seeds() {  # target seed-dir
  mkdir -p "$2"
  local i=0 file
  for file in $(seed_files "$1"); do
    if [[ $1 == cfx_monitor_fuzz ]]; then
      # The first byte picks the averaging window; '\0' = the last iteration.
      { printf '\0'; cat "$file"; } >"$2/seed-$i"
    else
      cp "$file" "$2/seed-$i"
    fi
    i=$((i + 1))
  done
  if [[ $1 == units_fuzz ]]; then
    for unit in 'm s^-1' '[ N m ]' 'kPa' 'deg s^-1' 'kg m^-3' 'mm' 'm^2 s^-1' 'rev/min' 'N/m2' 'kg*m.s^-2' 'X [ kN ]' '1'; do
      printf '%s' "$unit" >"$2/seed-$i"
      i=$((i + 1))
    done
  fi
}

targets=("$@")
if ((${#targets[@]} == 0)); then
  for exe in "$dir"/tests/fuzz/*_fuzz; do targets+=("$(basename "$exe")"); done
fi

status=0
summary=()
for target in "${targets[@]}"; do
  exe="$dir/tests/fuzz/$target"
  corpus="$dir/corpus/$target"
  seeds="$dir/seeds/$target"
  artifacts="$dir/artifacts/$target/"
  rm -rf "$seeds" "$artifacts"
  mkdir -p "$corpus" "$artifacts" "$regressions/$target"
  write_seeds "$target" "$seeds"
  log="$dir/$target.log"
  # -timeout: a parser that takes 10 s on one small input is a hang.
  if "$exe" -seed=1 -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$artifacts" "$corpus" "$seeds" "$regressions/$target" >"$log" 2>&1; then
    result=ok
  else
    result=FAILED
    status=1
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  found=0
  for artifact in "$artifacts"*; do
    [[ -f $artifact ]] || continue
    known=
    for regression in "$regressions/$target"/*; do
      if [[ -f $regression ]] && cmp -s "$artifact" "$regression"; then known=$(basename "$regression"); fi
    done
    found=$((found + 1))
    if [[ -n $known ]]; then
      echo "fuzz: $target: still fails on the known regression $known" >&2
      continue
    fi
    cp "$artifact" "$regressions/$target/"
    echo "fuzz: $target: $(basename "$artifact") copied to tests/data/bad/fuzz-regressions/$target/" >&2
  done
  if [[ $result == FAILED ]]; then
    echo "fuzz: $target failed; the end of $log:" >&2
    tail -40 "$log" >&2
  fi
  summary+=("$(printf '%-22s %10s executions in %ss, corpus %4s inputs, %d finding(s): %s' "$target" "${execs:-?}" \
    "$seconds" "$(find "$corpus" -type f | wc -l)" "$found" "$result")")
done
printf 'fuzz: %s\n' "${summary[@]}"
exit "$status"
