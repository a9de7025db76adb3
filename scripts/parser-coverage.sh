#!/usr/bin/env bash
# Measures how much of the received-file parsers their tests run: builds a
# coverage configuration in build/coverage (Clang source-based coverage,
# -fprofile-instr-generate -fcoverage-mapping, -O0, no sanitizers; only the
# library, the parser tests and their libFuzzer targets), runs the parser
# tests and each fuzz target once over its corpus (the seeds and malformed
# inputs of tests/data, and the target's regression files), merges the
# profiles (llvm-profdata) and prints line and region coverage per parser
# source file (llvm-cov).
#   scripts/parser-coverage.sh
# A measurement, not a test: scripts/test.sh does not run it. The README's
# table ("Names, received files and received databases") comes from it.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir="$root/build/coverage"
jobs=$(nproc 2>/dev/null || echo 2)

# The parsers measured, the tests that exercise them and their fuzz targets.
sources=(importers/openfoam_dictionary.cpp importers/cfx_ccl.cpp importers/case_motion.cpp
         importers/force_table.cpp importers/text_table.cpp importers/force_history_csv.cpp)
tests=(openfoam_dictionary_test cfx_ccl_test case_motion_test force_table_test text_table_test
       force_history_csv_test)
fuzzers=(openfoam_dictionary_fuzz cfx_ccl_fuzz case_motion_fuzz force_table_fuzz)

bash "$root/scripts/install-deps.sh"
# llvm-profdata and llvm-cov of the Clang that builds (Debian package
# llvm-N), installed the way scripts/install-deps.sh installs packages.
llvm_version=$(clang --version | sed -n 's/.*clang version \([0-9][0-9]*\)\..*/\1/p' | head -n 1)
llvm_bin="/usr/lib/llvm-$llvm_version/bin"
if [[ ! -x "$llvm_bin/llvm-profdata" || ! -x "$llvm_bin/llvm-cov" ]]; then
  echo "parser-coverage: installing llvm-$llvm_version (llvm-profdata, llvm-cov)" >&2
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "llvm-$llvm_version" >/dev/null
fi

# The fuzz targets link the library (HYDROCOEF_FUZZ_SMOKE), whose objects then
# count their edges for libFuzzer; without a sanitizer runtime the other
# programs get those counters' hooks from libFuzzer's runtime without its main
# (-fsanitize=fuzzer-no-link at link time).
coverage="-fprofile-instr-generate -fcoverage-mapping"
flags=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -g0 $coverage" "-DCMAKE_C_FLAGS_DEBUG=-O0 -g0 $coverage"
       -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
       "-DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld -fprofile-instr-generate -fsanitize=fuzzer-no-link"
       -DHYDROCOEF_FUZZ_SMOKE=ON -DHYDROCOEF_BUILD_BENCH=OFF -DHYDROCOEF_TEST_SET=fast)
if command -v ccache >/dev/null 2>&1; then
  flags+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(dirname "$root")} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
fi
cmake -S "$root" -B "$dir" -G Ninja "${flags[@]}" >/dev/null
ninja -C "$dir" -j "$jobs" "${tests[@]}" "${fuzzers[@]}"

profiles="$dir/profiles"
rm -rf "$profiles"
mkdir -p "$profiles"
for test in "${tests[@]}"; do
  LLVM_PROFILE_FILE="$profiles/$test-%p.profraw" "$dir/tests/$test" >"$profiles/$test.log" 2>&1 ||
    { cat "$profiles/$test.log" >&2; echo "parser-coverage: $test failed" >&2; exit 1; }
done
# Each fuzz target runs every file of its corpus once (-runs=0: no fuzzing,
# so the figures do not depend on time or chance).
corpus="$profiles/corpus"
mkdir -p "$corpus"
for folder in bad fuzz-seeds; do
  find "$root/tests/data/$folder" -maxdepth 1 -type f \( -name '*.csv' -o -name '*.ccl' -o -name '*.foam' \) \
    -exec cp {} "$corpus/" \;
done
for fuzzer in "${fuzzers[@]}"; do
  inputs=("$corpus")
  if [[ -d "$root/tests/data/bad/fuzz-regressions/$fuzzer" ]]; then
    inputs+=("$root/tests/data/bad/fuzz-regressions/$fuzzer")
  fi
  LLVM_PROFILE_FILE="$profiles/$fuzzer-%p.profraw" "$dir/tests/fuzz/$fuzzer" -runs=0 "${inputs[@]}" \
    >"$profiles/$fuzzer.log" 2>&1 ||
    { cat "$profiles/$fuzzer.log" >&2; echo "parser-coverage: $fuzzer failed" >&2; exit 1; }
done

"$llvm_bin/llvm-profdata" merge -sparse "$profiles"/*.profraw -o "$profiles/parsers.profdata"
objects=("$dir/tests/${tests[0]}")
for test in "${tests[@]:1}"; do objects+=(-object "$dir/tests/$test"); done
for fuzzer in "${fuzzers[@]}"; do objects+=(-object "$dir/tests/fuzz/$fuzzer"); done
# Line and region coverage of each parser, as a Markdown table. (llvm-cov's
# own file filter misses these files: ccache hands the compiler paths
# relative to the build folder.)
echo "| file | lines | regions |"
echo "|---|---:|---:|"
"$llvm_bin/llvm-cov" export -summary-only -instr-profile="$profiles/parsers.profdata" "${objects[@]}" 2>/dev/null |
  python3 -c '
import json, os, sys
root, wanted = sys.argv[1], sys.argv[2:]
files = {os.path.relpath(os.path.normpath(f["filename"]), root): f["summary"]
         for f in json.load(sys.stdin)["data"][0]["files"]}
for name in wanted:
    lines, regions = files[name]["lines"], files[name]["regions"]
    print("| `%s` | %.1f %% (%d of %d) | %.1f %% (%d of %d) |" % (name, lines["percent"], lines["covered"],
          lines["count"], regions["percent"], regions["covered"], regions["count"]))
' "$root" "${sources[@]}"
