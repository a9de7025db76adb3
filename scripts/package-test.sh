#!/usr/bin/env bash
# hydrocoef as a library others build on, checked from an optimized build directory (default build/heavy,
# which scripts/test.sh builds first; nothing is compiled again but the consumers):
#   1. cmake --install into a temporary prefix: the layout (public headers only, both libraries, the CLI,
#      the CMake package, pkg-config, schema, docs, the man pages made from --help);
#   2. the installed CLI makes a database (the ASR-V surge table) and a surface, and queries it (--json);
#   3. tests/package/consumer, configured with find_package(hydrocoef 0.1 CONFIG REQUIRED) against the prefix,
#      built against the shared and the static library, opens that database and gets the CLI's number;
#   4. the same program compiled alone with `pkg-config --cflags --libs hydrocoef`, run with LD_LIBRARY_PATH;
#      the installed Python module (when built) gets the same number;
#   5. cpack -G DEB; apt-get install ./hydrocoef_*.deb; /usr/bin/hydrocoef makes and queries a database,
#      the consumer built against /usr with pkg-config and /usr/bin/python3 get the same number;
#      apt-get purge hydrocoef (no trace left in dpkg either).
# Step 5 installs a package system-wide (root or sudo; it is removed again); HYDROCOEF_PACKAGE_TEST_NO_DEB=1
# skips it. Each check prints one line; the first failure exits 1 saying what was wrong.
#   scripts/package-test.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build/heavy}" && pwd)
jobs=$(nproc 2>/dev/null || echo 2)

say() { echo "package-test: $*"; }
fail() {
  echo "package-test: FAILED: $*" >&2
  exit 1
}

work=$(mktemp -d /tmp/hydrocoef-package-test.XXXXXX)
chmod 755 "$work" # apt-get reads the .deb as the _apt user
installed_deb=false
cleanup() {
  if $installed_deb; then "${sudo_cmd[@]}" apt-get purge -y -qq -o DPkg::Lock::Timeout=300 hydrocoef >/dev/null 2>&1 || true; fi
  rm -rf "$work"
}
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
trap cleanup EXIT

[[ -f $build/CMakeCache.txt ]] || fail "$build is not a configured build directory (run scripts/build.sh heavy)"
# Everything cmake --install installs (nothing to do after scripts/build.sh heavy).
cmake --build "$build" -j "$jobs" >/dev/null || fail "building $build"
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
multiarch=$(sed -n 's/^CMAKE_INSTALL_LIBDIR:[A-Z]*=//p' "$build/CMakeCache.txt")
[[ -n $version && -n $multiarch ]] || fail "no project version or CMAKE_INSTALL_LIBDIR in $build/CMakeCache.txt"

# --- 1. cmake --install -------------------------------------------------------------------------------
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || {
  cat "$work/install.log" >&2
  fail "cmake --install $build --prefix $prefix"
}
expected=(
  bin/hydrocoef
  "$multiarch/libhydrocoef.so.$version" "$multiarch/libhydrocoef.so.0" "$multiarch/libhydrocoef.so"
  "$multiarch/libhydrocoef.a"
  "$multiarch/libhydrocoef_runtime.so.1" "$multiarch/libhydrocoef_runtime.a" include/hydrocoef/runtime.h
  include/hydrocoef/runtime_frames.h include/hydrocoef/runtime.hpp
  "$multiarch/cmake/hydrocoef/hydrocoefConfig.cmake" "$multiarch/cmake/hydrocoef/hydrocoefConfigVersion.cmake"
  "$multiarch/cmake/hydrocoef/hydrocoefTargets.cmake" "$multiarch/cmake/hydrocoef/hydrocoefStaticTargets.cmake"
  "$multiarch/pkgconfig/hydrocoef.pc"
  include/hydrocoef/hydrocoef.hpp include/hydrocoef/error.hpp include/hydrocoef/version.hpp
  share/hydrocoef/schema/0001_initial.sql share/doc/hydrocoef/README.md share/doc/hydrocoef/PROVENANCE.md
  share/doc/hydrocoef/docs/importing.md share/man/man1/hydrocoef.1 share/man/man1/hydrocoef-import.1
)
for file in "${expected[@]}"; do
  [[ -e $prefix/$file ]] || fail "cmake --install did not install $file"
done
# Public headers only: include/ holds include/hydrocoef/*.hpp and the runtime library's C headers, nothing else.
extra=$(cd "$prefix/include" && find . -type f ! -path './hydrocoef/*.hpp' ! -path './hydrocoef/runtime.h' \
  ! -path './hydrocoef/runtime_frames.h' ! -path './hydrocoef/runtime.hpp' | head -3)
[[ -z $extra ]] || fail "cmake --install put more than include/hydrocoef/*.hpp under include/: $extra"
for header in "$prefix"/include/hydrocoef/*.hpp; do
  if grep -Eq '#include +"(src|importers|cli)/' "$header"; then
    fail "the public header $(basename "$header") includes an internal header"
  fi
done
# A man page made from the CLI's --help: the command's page holds its options.
grep -q -- '\\-\\-key\\-from\\-name' "$prefix/share/man/man1/hydrocoef-import.1" ||
  fail "share/man/man1/hydrocoef-import.1 does not hold import's --help (--key-from-name)"
say "ok: cmake --install $(find "$prefix" -type f | wc -l) files under the prefix: CLI, libhydrocoef.so.$version and .a, $(find "$prefix/include/hydrocoef" -name "*.hpp" | wc -l) public headers, CMake package, pkg-config, schema, docs, man pages"

# --- 2. the installed CLI makes the database the consumers read --------------------------------------
# query_value CLI DB SURFACE AXIS=VALUE OUTPUT: the output's value from `hydrocoef query --json`.
make_database() { # CLI DB
  local cli=$1 db=$2
  rm -f "$db"
  "$cli" --db "$db" import "$root/examples/asr-v/asr-v-surge-damping.csv" --body asr-v --sign opposing \
    --rho 998.2 --nu 1.004e-6 --quiet >/dev/null || fail "$cli import"
  "$cli" --db "$db" surface build surge --body asr-v --outputs X --axes u --method pchip >/dev/null ||
    fail "$cli surface build"
}
query_value() { # CLI DB SURFACE AXIS=VALUE OUTPUT
  local json value
  json=$("$1" --db "$2" query "$3" "$4" --json) || fail "$1 query $3 $4 --json"
  value=$(sed -n '/"values"/,/}/s/^ *"'"$5"'": *\([-+0-9.eE]*\),\{0,1\}$/\1/p' <<<"$json")
  [[ -n $value ]] || fail "no value of $5 in the output of $1 query $3 $4 --json: $json"
  echo "$value"
}
db="$work/asr-v.db"
make_database "$prefix/bin/hydrocoef" "$db"
x=$(query_value "$prefix/bin/hydrocoef" "$db" surge u=0.25 X)
say "ok: the installed CLI imported the ASR-V surge table, built a surface and queried it: X(0.25) = $x N"

# --- 3. a CMake project with find_package ------------------------------------------------------------
run_consumer() { # WHAT EXECUTABLE [ENV...]
  local what=$1 exe=$2
  shift 2
  env "$@" "$exe" "$db" surge u=0.25 --expect "X=$x" >"$work/consumer.log" 2>&1 || {
    cat "$work/consumer.log" >&2
    fail "$what: the consumer's checks (above)"
  }
  grep -q "consumer: ok X" "$work/consumer.log" || fail "$what: the consumer did not compare X: $(cat "$work/consumer.log")"
}
# The Python module, when the build made it: the same value through hydrocoef.Database(...).surface(...).
python_check() { # WHAT [ENV...]
  local what=$1
  shift
  env "$@" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c '
import sys, hydrocoef
x = float(hydrocoef.Database(sys.argv[1], mode="r").surface("surge")(u=0.25)["X"])
expected = float(sys.argv[2])
assert abs(x - expected) <= 1e-12 * max(1.0, abs(expected)), f"X(0.25) = {x!r}, the CLI query {expected!r}"
print(hydrocoef.__file__)' "$db" "$x" >"$work/python.log" 2>&1 || fail "$what: the Python module: $(cat "$work/python.log")"
}
consumer_build="$work/consumer-build"
cmake -S "$root/tests/package/consumer" -B "$consumer_build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >"$work/consumer-configure.log" 2>&1 || {
  cat "$work/consumer-configure.log" >&2
  fail "configuring tests/package/consumer with find_package(hydrocoef 0.1 CONFIG REQUIRED) against $prefix"
}
grep -q "hydrocoef $version from $prefix/" "$work/consumer-configure.log" ||
  fail "find_package found another hydrocoef than the one in $prefix: $(grep 'hydrocoef ' "$work/consumer-configure.log")"
cmake --build "$consumer_build" -j "$jobs" >"$work/consumer-build.log" 2>&1 || {
  cat "$work/consumer-build.log" >&2
  fail "building tests/package/consumer against $prefix"
}
# The shared one finds libhydrocoef.so.0 through its build RPATH (the prefix), not through the system.
# ldd's output is read whole first: `ldd | grep -q` under pipefail fails when
# grep stops reading before ldd has finished writing (SIGPIPE).
shared_libraries=$(ldd "$consumer_build/consumer")
grep -q "libhydrocoef.so.0 => $prefix/" <<<"$shared_libraries" ||
  fail "consumer does not load libhydrocoef.so.0 from $prefix: $(grep hydrocoef <<<"$shared_libraries")"
static_libraries=$(ldd "$consumer_build/consumer_static")
if grep -q libhydrocoef <<<"$static_libraries"; then fail "consumer_static loads libhydrocoef.so"; fi
run_consumer "find_package, hydrocoef::hydrocoef (shared)" "$consumer_build/consumer"
run_consumer "find_package, hydrocoef::hydrocoef_static" "$consumer_build/consumer_static"
say "ok: find_package(hydrocoef 0.1 CONFIG REQUIRED [COMPONENTS static]): consumers built against the shared and the static library opened the database and got X(0.25) = $x N, as the CLI"

# A version the package does not satisfy is refused (0.x: SameMinorVersion).
mkdir -p "$work/wrong-version"
cat >"$work/wrong-version/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.25)
project(wrong_version LANGUAGES CXX)
find_package(hydrocoef 0.99 CONFIG QUIET)
if(hydrocoef_FOUND)
  message(FATAL_ERROR "find_package(hydrocoef 0.99) accepted ${hydrocoef_VERSION}")
endif()
EOF
cmake -S "$work/wrong-version" -B "$work/wrong-version/build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/wrong.log" 2>&1 || {
  cat "$work/wrong.log" >&2
  fail "find_package(hydrocoef 0.99) was not refused by the version file"
}

# --- 3b. a C99 program on libhydrocoef_runtime ------------------------------------------------------
"$prefix/bin/hydrocoef" --db "$db" export surge --format runtime -o "$work/asr-v.hcrt" >/dev/null ||
  fail "$prefix/bin/hydrocoef export surge --format runtime"
cat >"$work/runtime_consumer.c" <<'EOF'
#include <stdio.h>
#include <hydrocoef/runtime.h>
#include <hydrocoef/runtime_frames.h>
int main(int argc, char** argv) {
  hc_runtime_model* model = NULL;
  char err[256] = "";
  double u = 0.25, x = 0.0;
  if (argc != 2 || hc_runtime_open(argv[1], &model, err, sizeof err) != HC_RUNTIME_OK) {
    fprintf(stderr, "%s\n", err);
    return 1;
  }
  if (hc_runtime_evaluate(model, 0, &u, &x, NULL, NULL) != HC_RUNTIME_OK) return 1;
  {
    const double frd[3] = {1.0, 2.0, 3.0};
    double flu[3];
    hc_frames_frd_flu_vector(frd, flu); /* the installed frames header compiles and links as C99 */
    if (flu[1] != -2.0) return 1;
  }
  printf("%.17g\n", x);
  hc_runtime_close(model);
  return 0;
}
EOF
for link in shared static; do
  if [[ $link == shared ]]; then
    libs=(-L"$prefix/$multiarch" -lhydrocoef_runtime)
  else
    libs=("$prefix/$multiarch/libhydrocoef_runtime.a" -lm)
  fi
  cc -std=c99 -pedantic -Wall -Wextra -Werror -I"$prefix/include" -o "$work/runtime_consumer_$link" \
    "$work/runtime_consumer.c" "${libs[@]}" || fail "compiling a C99 program against libhydrocoef_runtime ($link)"
  runtime_x=$(LD_LIBRARY_PATH="$prefix/$multiarch" "$work/runtime_consumer_$link" "$work/asr-v.hcrt") ||
    fail "the C99 runtime consumer ($link) could not evaluate $work/asr-v.hcrt"
  /usr/bin/python3 -c 'import sys; assert float(sys.argv[1]) == float(sys.argv[2]), sys.argv[1:]' "$runtime_x" "$x" ||
    fail "the C99 runtime consumer ($link) gave X(0.25) = $runtime_x, the CLI $x"
done
say "ok: a C99 program (-std=c99 -pedantic) linked libhydrocoef_runtime shared and static and evaluated the runtime file: X(0.25) = $x N, as the CLI"

# --- 4. pkg-config -----------------------------------------------------------------------------------
pc_flags=$(PKG_CONFIG_PATH="$prefix/$multiarch/pkgconfig" pkg-config --cflags --libs hydrocoef | xargs) ||
  fail "pkg-config --cflags --libs hydrocoef with PKG_CONFIG_PATH=$prefix/$multiarch/pkgconfig"
[[ $pc_flags == *"-I$prefix/include"* && $pc_flags == *"-L$prefix/$multiarch"* && $pc_flags == *-lhydrocoef* ]] ||
  fail "pkg-config --cflags --libs hydrocoef gave '$pc_flags', not the prefix's include and library directories"
# shellcheck disable=SC2086 # pc_flags is a list of flags
c++ -std=c++17 -O1 -o "$work/consumer_pc" "$root/tests/package/consumer/main.cpp" $pc_flags ||
  fail "compiling the consumer with pkg-config --cflags --libs hydrocoef ($pc_flags)"
run_consumer "pkg-config" "$work/consumer_pc" "LD_LIBRARY_PATH=$prefix/$multiarch"
say "ok: pkg-config --cflags --libs hydrocoef ($pc_flags): the one-file consumer got X(0.25) = $x N"
python_dir="$prefix/lib/python3/dist-packages"
if [[ -d $python_dir/hydrocoef ]]; then
  python_check "cmake --install" "PYTHONPATH=$python_dir"
  grep -q "^$python_dir/hydrocoef/" "$work/python.log" || fail "python3 imported hydrocoef from elsewhere: $(cat "$work/python.log")"
  say "ok: the installed Python module ($python_dir/hydrocoef) got X(0.25) = $x N"
else
  python_dir=
  say "NOT RUN: the Python module (not built in $build: pybind11-dev, python3-dev, python3-numpy)"
fi

# --- 5. the Debian package ---------------------------------------------------------------------------
if [[ ${HYDROCOEF_PACKAGE_TEST_NO_DEB:-} == 1 ]]; then
  say "NOT RUN: the Debian package (HYDROCOEF_PACKAGE_TEST_NO_DEB=1)"
  exit 0
fi
rm -f "$build"/hydrocoef_*.deb
(cd "$build" && cpack -G DEB) >"$work/cpack.log" 2>&1 || {
  cat "$work/cpack.log" >&2
  fail "cpack -G DEB in $build"
}
arch=$(dpkg --print-architecture)
deb="$build/hydrocoef_${version}_$arch.deb"
[[ -f $deb ]] || fail "cpack -G DEB did not make $deb: $(ls "$build"/*.deb 2>/dev/null)"
depends=$(dpkg-deb --field "$deb" Depends)
[[ $depends == *libvtk9* && $depends == *libsqlite3-0* && $depends == *libstdc++6* ]] ||
  fail "$(basename "$deb") does not depend on the runtime libraries (dpkg-shlibdeps): Depends: $depends"
if grep -q -- '-dev\b' <<<"$depends"; then fail "$(basename "$deb") depends on development packages: $depends"; fi
say "ok: cpack -G DEB made $(basename "$deb") ($(du -k "$deb" | cut -f1) kB), Depends: $depends"

if dpkg-query -W -f='${Status}' hydrocoef 2>/dev/null | grep -q 'install ok installed'; then
  fail "a hydrocoef package is installed already (apt-get purge hydrocoef first): this test installs and removes its own"
fi
cp "$deb" "$work/"
installed_deb=true
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=300 \
  "$work/$(basename "$deb")" >"$work/apt.log" 2>&1 || {
  cat "$work/apt.log" >&2
  fail "apt-get install ./$(basename "$deb")"
}
listing=$(dpkg -L hydrocoef)
for file in /usr/bin/hydrocoef "/usr/$multiarch/libhydrocoef.so.0" "/usr/$multiarch/libhydrocoef.a" \
  /usr/include/hydrocoef/hydrocoef.hpp "/usr/$multiarch/cmake/hydrocoef/hydrocoefConfig.cmake" \
  "/usr/$multiarch/pkgconfig/hydrocoef.pc" /usr/share/hydrocoef/schema/0001_initial.sql \
  /usr/share/doc/hydrocoef/README.md; do
  grep -qx "$file" <<<"$listing" || fail "dpkg -L hydrocoef does not list $file"
done
[[ $(/usr/bin/hydrocoef --version) == *"$version"* ]] || fail "/usr/bin/hydrocoef --version: $(/usr/bin/hydrocoef --version)"
make_database /usr/bin/hydrocoef "$db"
x=$(query_value /usr/bin/hydrocoef "$db" surge u=0.25 X)
pc_flags=$(pkg-config --cflags --libs hydrocoef | xargs) || fail "pkg-config --cflags --libs hydrocoef after installing the package"
# shellcheck disable=SC2086 # pc_flags is a list of flags
c++ -std=c++17 -O1 -o "$work/consumer_deb" "$root/tests/package/consumer/main.cpp" $pc_flags ||
  fail "compiling the consumer against the installed package ($pc_flags)"
run_consumer "the Debian package" "$work/consumer_deb"
if [[ -n $python_dir ]]; then
  python_check "the Debian package" "PYTHONPATH="
  grep -q "^/usr/lib/python3/dist-packages/hydrocoef/" "$work/python.log" ||
    fail "python3 did not import hydrocoef from the package: $(cat "$work/python.log")"
fi
say "ok: apt-get install ./$(basename "$deb"): /usr/bin/hydrocoef --version, import, surface build and query; the consumer built with pkg-config ($pc_flags)${python_dir:+ and the Python module} got X(0.25) = $x N"
"${sudo_cmd[@]}" apt-get purge -y -qq -o DPkg::Lock::Timeout=300 hydrocoef >/dev/null 2>&1 || fail "apt-get purge hydrocoef"
installed_deb=false
[[ ! -e /usr/bin/hydrocoef ]] || fail "/usr/bin/hydrocoef is still there after apt-get purge hydrocoef"
if dpkg-query -W hydrocoef >/dev/null 2>&1; then fail "dpkg still lists hydrocoef after apt-get purge hydrocoef"; fi
say "ok: apt-get purge hydrocoef left no /usr/bin/hydrocoef and no trace in dpkg"
