#!/usr/bin/env bash
# The README's test command: installs what is missing, builds the test
# configuration (AddressSanitizer + UBSan, Clang, with the libFuzzer targets),
# and the optimized build, runs the GoogleTest suite through ctest (the fuzz
# smoke run of every target included; the PostgreSQL repeats of the CLI
# suites on the optimized build's CLI), then the heavy tests in the optimized
# build, and from that build installs hydrocoef, builds programs against it
# and makes, installs and removes its Debian package
# (scripts/package-test.sh).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# Each phase's wall time, printed as it ends and summed up at the end.
started=$SECONDS phase_start=$SECONDS timings=()
phase_done() {
  timings+=("$(printf '%-34s %5d s' "$1" $((SECONDS - phase_start)))")
  echo "[test.sh] $1: $((SECONDS - phase_start)) s"
  phase_start=$SECONDS
}
pg_dir=""
trap '[[ -n "$pg_dir" ]] && bash "$root/scripts/postgresql-test-server.sh" stop "$pg_dir"; printf "[test.sh] %s\n" "${timings[@]}" "total $((SECONDS - started)) s"' EXIT
bash "$root/scripts/build.sh" test
phase_done "sanitizer build (with packages)"
# The heavy tests (statistical checks with hundreds of fits) in an optimized
# build without sanitizers; its CLI also runs the PostgreSQL repeats of the
# CLI suites (tests/support/run_cli.hpp: an ASan CLI start costs four times
# an optimized one, and those repeats test the store's other backend, whose
# code the store and reliability suites run under the sanitizers).
bash "$root/scripts/build.sh" heavy
phase_done "optimized build"
export HYDROCOEF_TEST_POSTGRESQL_CLI="$root/build/heavy/hydrocoef"
# A throw-away PostgreSQL server for the store, CLI and reliability tests that
# run on both backends (tests/support/test_database.hpp); stopped, and its
# folder removed, however this script ends.
pg_dir=$(mktemp -d "${TMPDIR:-/tmp}/hydrocoef-pg.XXXXXX")
server=$(bash "$root/scripts/postgresql-test-server.sh" start "$pg_dir") # fails the script when it fails
eval "$server"
export HYDROCOEF_TEST_POSTGRESQL_REQUIRED=1
phase_done "PostgreSQL test server start"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir "$root/build/test" --output-on-failure -j "$jobs" "$@"
phase_done "sanitizer tests"
ctest --test-dir "$root/build/heavy" --output-on-failure -j "$jobs" "$@"
phase_done "heavy tests and Python"
# hydrocoef as a library others build on: cmake --install, find_package and
# pkg-config consumers, cpack -G DEB and apt-get install of the package.
bash "$root/scripts/package-test.sh" "$root/build/heavy"
phase_done "install and package test"
