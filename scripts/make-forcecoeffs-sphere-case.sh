#!/usr/bin/env bash
# Makes data/openfoam-sphere/forcecoeffs/M1-U0.1000: a steady OpenFOAM run of
# the R = 0.15 m sphere in water with the coefficients OpenFOAM's own
# `forceCoeffs` function object writes for it, so that a test can check
# hydrocoef's `runs --coefficients` against the solver's numbers for the same
# run (tests/cli/cli_forcecoeffs_test.cpp).
#
#   scripts/make-forcecoeffs-sphere-case.sh
#
# The run is the quarter-domain case of scripts/make-converged-sphere-cases.sh
# on its coarse mesh (M1: 17.5k cells; about a minute of meshing and 10 s of
# simpleFoam on one core) at 0.1 m/s, made by that script (OUT=..., its scratch
# folder kept). In its scratch folder, `forceCoeffs` is then evaluated on the
# run's final state (simpleFoam -postProcess -latestTime, the dictionary
# system/forceCoeffsDict written here): patch sphere, rhoInf 998.2, magUInf
# 0.1 (the free stream), lRef 0.3 (2R), Aref pi R^2 / 4 = 0.01767145867644259
# (the quarter sphere's frontal area: the patch is a quarter of the sphere),
# dragDir (1 0 0), liftDir (0 0 1), CofR (0 0 0). The case folder is kept as
# the other script keeps it (no mesh, no time folders) with that dictionary,
# postProcessing/forceCoeffs/<time>/coefficient.dat and log.forceCoeffs.
#
# Needs Debian's OpenFOAM v1912 (`apt-get install openfoam`). FORCE=1 replaces
# an existing output folder.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$root/data/openfoam-sphere/forcecoeffs/M1-U0.1000"
if [[ -e $out && ${FORCE:-0} != 1 ]]; then
  echo "$out exists (FORCE=1 replaces it)" >&2
  exit 1
fi
scratch=$(mktemp -d "${TMPDIR:-/tmp}/forcecoeffs-sphere.XXXXXX")
work=""
cleanup() {
  rm -rf "$scratch"
  [[ -z $work ]] || rm -rf "$work"
}
trap cleanup EXIT

OUT="$scratch/case" KEEP_WORK=1 REFERENCE=0 FORCE=1 bash "$root/scripts/make-converged-sphere-cases.sh" quarter 1 0.1 |
  tee "$scratch/log"
work=$(sed -n 's/^scratch case kept in //p' "$scratch/log")
[[ -d $work ]] || { echo "the run's scratch folder was not kept" >&2; exit 1; }

cat > "$work/system/forceCoeffsDict" << 'EOF'
/*--------------------------------*- C++ -*----------------------------------*\
  OpenFOAM v1912 (Debian package) -- sphere R=0.15 m, quarter domain:
  forceCoeffs of the final state (scripts/make-forcecoeffs-sphere-case.sh)
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      forceCoeffsDict;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

functions
{
    // Cd = Fx / (1/2 rhoInf magUInf^2 Aref) of the quarter patch, Aref the
    // quarter sphere's frontal area pi R^2 / 4; moments about CofR over lRef.
    forceCoeffs
    {
        type            forceCoeffs;
        libs            ("libforces.so");
        writeControl    timeStep;
        writeInterval   1;
        log             yes;
        patches         (sphere);
        p               p;
        U               U;
        rho             rhoInf;
        rhoInf          998.2;
        CofR            (0 0 0);
        liftDir         (0 0 1);
        dragDir         (1 0 0);
        pitchAxis       (0 1 0);
        magUInf         0.1;
        lRef            0.3;
        Aref            0.01767145867644259;
    }
}

// ************************************************************************* //
EOF

export WM_PROJECT_DIR=${FOAM_DIR:-/usr/share/openfoam}
set +eu
# shellcheck disable=SC1091
. "$WM_PROJECT_DIR/etc/bashrc" > /dev/null 2>&1
set -eu
(cd "$work" && nice simpleFoam -postProcess -dict system/forceCoeffsDict -latestTime > log.forceCoeffs 2>&1) || {
  tail -30 "$work/log.forceCoeffs" >&2
  exit 1
}
coefficients=$(find "$work/postProcessing/forceCoeffs" -name 'coefficient*.dat' | head -1)
[[ -n $coefficients ]] || { echo "forceCoeffs wrote no coefficient file (see $work/log.forceCoeffs)" >&2; exit 1; }
time_dir=$(basename "$(dirname "$coefficients")")

rm -rf "$out"
mkdir -p "$(dirname "$out")"
cp -r "$scratch/case" "$out"
cp "$work/system/forceCoeffsDict" "$out/system/"
mkdir -p "$out/postProcessing/forceCoeffs/$time_dir"
cp "$coefficients" "$out/postProcessing/forceCoeffs/$time_dir/"
cp "$work/log.forceCoeffs" "$out/"
echo "forceCoeffs at time $time_dir: $(grep -v '^#' "$coefficients" | tail -1)"
echo "wrote $out"
