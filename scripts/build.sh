#!/usr/bin/env bash
# Configures and builds hydrocoef in a build directory.
#   scripts/build.sh [release|test|heavy]
# release: optimized, in build/release (the CLI, examples and benchmarks).
# test:    AddressSanitizer + UBSan at -O1 with Clang, in build/test (the test
#          suite but its heavy tests, and the libFuzzer targets of its smoke run).
# heavy:   optimized, no sanitizers, in build/heavy: the heavy tests alone
#          (*_heavy_test.cpp: statistical checks with hundreds of fits).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kind=${1:-release}
jobs=$(nproc 2>/dev/null || echo 2)

case "$kind" in
  release) dir="$root/build/release"; flags=(-DCMAKE_BUILD_TYPE=Release -DHYDROCOEF_BUILD_TESTS=OFF) ;;
  # -O1 (as AddressSanitizer advises): the checks stay, and Eigen and the
  # numerical tests do not run tens of times slower as at -O0. -g1: line
  # tables only, enough for the sanitizers' stack traces (file:line), and a
  # fifth less compile time than -g; LLVM's lld links the test programs in a
  # fraction of ld.bfd's time (gold, as fast, warns about every ASan helper
  # symbol of Clang's runtime).
  # Clang: the libFuzzer targets of the fuzz smoke run link this build's own
  # library (HYDROCOEF_FUZZ_SMOKE), so no second sanitizer build of the
  # parsers is needed; and Clang compiles this configuration faster than GCC.
  # The test programs and the CLI start thousands of times in a test run:
  # linked as position-dependent executables they have no million relative
  # relocations (the sanitizers' metadata) to apply at each start, and with
  # --as-needed they load only the shared libraries they use (102 of 124):
  # a fifth less CPU per CLI call.
  test)    dir="$root/build/test"; flags=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g1 -O1" "-DCMAKE_C_FLAGS_DEBUG=-g1 -O1"
                                          -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
                                          "-DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld -no-pie -Wl,--as-needed" -DHYDROCOEF_FUZZ_SMOKE=ON
                                          -DHYDROCOEF_SANITIZE=ON -DHYDROCOEF_BUILD_BENCH=OFF -DHYDROCOEF_TEST_SET=fast
                                          -DHYDROCOEF_UNITY_BUILD=ON) ;;
  # -O2: what Debian builds its packages with (the .deb is made from this
  # build), and an eighth less compile time than CMake's Release -O3.
  # --as-needed: the CLI loads only the shared libraries it uses.
  # Unity groups (cmake/unity_groups.cmake) in both builds a test run makes
  # from scratch: a third less CPU for the library, the CLI and the module.
  # Clang: with the library's precompiled header (Clang only) it compiles the
  # library in two thirds of GCC's CPU time (433 s against 660 s here), and
  # the heavy tests run as fast.
  heavy)   dir="$root/build/heavy"; flags=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"
                                           "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" -DCMAKE_EXE_LINKER_FLAGS=-Wl,--as-needed
                                           -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
                                           -DHYDROCOEF_BUILD_BENCH=OFF
                                           -DHYDROCOEF_TEST_SET=heavy -DHYDROCOEF_UNITY_BUILD=ON) ;;
  *) echo "usage: scripts/build.sh [release|test|heavy]" >&2; exit 2 ;;
esac

bash "$root/scripts/install-deps.sh"
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
# ccache where present (rebuilds of unchanged sources are cache hits; several
# work trees of one machine share them through the base directory).
if command -v ccache >/dev/null 2>&1; then
  flags+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(dirname "$root")} CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
fi
# A test build configured before it was a Clang build with the fuzz targets,
# or a heavy build configured before it was a Clang build, is made again (a
# build cannot change its compiler).
if [[ $kind == test && -f "$dir/CMakeCache.txt" ]] && ! grep -q '^HYDROCOEF_FUZZ_SMOKE:BOOL=ON' "$dir/CMakeCache.txt"; then
  rm -rf "$dir"
fi
if [[ $kind == heavy && -f "$dir/CMakeCache.txt" ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++$' "$dir/CMakeCache.txt"; then
  rm -rf "$dir"
fi
# Configured when new, or again when a build made before the unity groups
# (cmake/unity_groups.cmake) lacks them.
if [[ ! -f "$dir/CMakeCache.txt" ]] ||
   { [[ " ${flags[*]} " == *" -DHYDROCOEF_UNITY_BUILD=ON "* ]] && ! grep -q '^HYDROCOEF_UNITY_BUILD:BOOL=ON' "$dir/CMakeCache.txt"; }; then
  cmake -S "$root" -B "$dir" "${generator[@]}" "${flags[@]}" >/dev/null
fi
cmake --build "$dir" -j "$jobs"
