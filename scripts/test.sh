#!/usr/bin/env bash
# The README's test command: installs what is missing, builds the test
# configuration (AddressSanitizer + UBSan) and runs the whole GoogleTest suite
# through ctest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh" test
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --test-dir "$root/build/test" --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
# Fuzz smoke: every parser's libFuzzer target (Clang, in build/fuzz), 10 s each;
# a crash becomes a file in tests/data/bad/fuzz-regressions/ and fails this script.
bash "$root/scripts/fuzz.sh" 10
