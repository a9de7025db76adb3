#!/usr/bin/env bash
# Installs the Debian 12 packages hydrocoef needs to build, test and benchmark.
# Idempotent and quick when everything is present: it asks dpkg first and runs
# apt-get (update once, then install) only for what is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libvtk9-dev           # VTK readers (legacy/XML/EnSight/CGNS) and cross-check filters
  libeigen3-dev         # linear algebra
  libceres-dev          # damping-law fitting and covariance
  libsqlite3-dev        # run database
  libpq-dev             # run database on a PostgreSQL server (src/store/postgresql_backend.cpp)
  postgresql-15         # tests: a throw-away server (scripts/postgresql-test-server.sh)
  sqlite3               # tests: tests/data/tampered/make-tampered.sh edits copies of a database
  libxml2-utils         # tests: xmllint --noout checks the DAVE-ML export is well-formed
  libssl-dev            # SHA-256 of imported files (libcrypto)
  libgtest-dev libgmock-dev
  libcgns-dev           # tests write CGNS files for the CGNS reader path
  ninja-build
  libbenchmark-dev      # bench/
  libcli11-dev          # command line
  nlohmann-json3-dev    # --json output, surface definitions, vehicle files
  libmatio-dev          # MATLAB .mat export
  libdeflate-dev        # zlib blocks of .vtp files, decompressed in parallel
  gnuplot-nox           # hydrocoef plot / report: PNG and SVG (pngcairo, svg terminals)
  chromium              # tests: the HTML report rendered headless
  clang libclang-rt-14-dev  # the sanitizer test build and the libFuzzer targets in tests/fuzz
  lld                   # the sanitizer test build's linker
  clang-format          # scripts/format.sh: the code style of .clang-format
  dpkg-dev              # cpack -G DEB: dpkg-shlibdeps finds the package's runtime dependencies (scripts/package-test.sh)
  pybind11-dev python3-dev python3-numpy  # the Python module (python/)
  python3-pytest        # tests/python
  python3-scipy         # bench/python_vs_scipy.py
  python3-matplotlib    # examples/python/fit_and_plot.py draws its plot (prints numbers without it)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
