#!/usr/bin/env bash
# Configures and builds hydrocoef in a build directory.
#   scripts/build.sh [release|test]
# release: optimized, in build/release (the CLI, examples and benchmarks).
# test:    AddressSanitizer + UBSan, in build/test (the test suite).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kind=${1:-release}
jobs=$(nproc 2>/dev/null || echo 2)

case "$kind" in
  release) dir="$root/build/release"; flags=(-DCMAKE_BUILD_TYPE=Release -DHYDROCOEF_BUILD_TESTS=OFF) ;;
  test)    dir="$root/build/test"; flags=(-DCMAKE_BUILD_TYPE=Debug -DHYDROCOEF_SANITIZE=ON -DHYDROCOEF_BUILD_BENCH=OFF) ;;
  *) echo "usage: scripts/build.sh [release|test]" >&2; exit 2 ;;
esac

bash "$root/scripts/install-deps.sh"
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [[ ! -f "$dir/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$dir" "${generator[@]}" "${flags[@]}" >/dev/null
fi
cmake --build "$dir" -j "$jobs"
