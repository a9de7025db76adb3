#!/usr/bin/env bash
# Regenerates a forced-oscillation (virtual planar motion mechanism) OpenFOAM
# case of the R = 0.15 m sphere in water: the whole mesh translates rigidly in
# surge, x(t) = A sin(2 pi t / T), the water far away stays at rest.
#
#   scripts/make-pmm-sphere-case.sh AMPLITUDE PERIOD [PERIODS [STEPS_PER_PERIOD]]
#   e.g. scripts/make-pmm-sphere-case.sh 0.015 2        (6 periods, 100 steps each)
#
# Needs OpenFOAM v1912 from Debian (`apt-get install openfoam`); only this
# script needs it, to regenerate the data, so no install script of the
# project installs it. Reads only the dictionaries in
# examples/openfoam-sphere/pmm/template (placeholders @NAME@), meshes
# (blockMesh, snappyHexMesh, checkMesh) and runs pimpleFoam on one core under
# nice in a scratch folder, then writes
# examples/openfoam-sphere/pmm/surge-A<AMPLITUDE>-T<PERIOD>/ as the solver left
# the case, less the mesh (constant/polyMesh) and the time folders:
# 0/, constant/, system/, postProcessing/forces/0/force.dat and moment.dat
# (every time step), log.checkMesh and log.pimpleFoam (gzipped if over 1 MB).
#
# Environment: FOAM_DIR (default /usr/share/openfoam), KEEP_WORK=1 keeps the
# scratch folder (mesh and time folders) and prints its path, FORCE=1
# replaces an existing output folder, OUT=DIR writes the case there instead
# (for sensitivity runs that are not kept).
set -euo pipefail

usage="usage: make-pmm-sphere-case.sh AMPLITUDE PERIOD [PERIODS [STEPS_PER_PERIOD]]"
amplitude=${1:?$usage}
period=${2:?$usage}
periods=${3:-6}
steps=${4:-100}

number='^[0-9]+([.][0-9]+)?$'
for v in "$amplitude" "$period"; do
  [[ $v =~ $number ]] || { echo "not a positive number: $v" >&2; exit 2; }
done
[[ $periods =~ ^[1-9][0-9]*$ && $steps =~ ^[1-9][0-9]*$ ]] || { echo "$usage" >&2; exit 2; }

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
template="$root/examples/openfoam-sphere/pmm/template"
out=${OUT:-"$root/examples/openfoam-sphere/pmm/surge-A${amplitude}-T${period}"}
if [[ -e $out && ${FORCE:-0} != 1 ]]; then
  echo "$out exists (FORCE=1 replaces it)" >&2
  exit 1
fi

omega=$(awk -v T="$period" 'BEGIN { printf "%.15g", 2 * atan2(0, -1) / T }')
delta_t=$(awk -v T="$period" -v n="$steps" 'BEGIN { printf "%.10g", T / n }')
end_time=$(awk -v T="$period" -v k="$periods" 'BEGIN { printf "%.10g", T * k }')
write_steps=$((periods * steps))

work=$(mktemp -d "${TMPDIR:-/tmp}/pmm-sphere.XXXXXX")
if [[ ${KEEP_WORK:-0} != 1 ]]; then
  trap 'rm -rf "$work"' EXIT
fi
cp -r "$template/0" "$template/constant" "$template/system" "$work/"
for f in "$work/system/controlDict" "$work/constant/dynamicMeshDict"; do
  sed -i -e "s/@AMPLITUDE@/$amplitude/g" -e "s/@PERIOD@/$period/g" -e "s/@OMEGA@/$omega/g" \
    -e "s/@PERIODS@/$periods/g" -e "s/@STEPS@/$steps/g" -e "s/@DELTA_T@/$delta_t/g" \
    -e "s/@END_TIME@/$end_time/g" -e "s/@WRITE_STEPS@/$write_steps/g" "$f"
done
if grep -rn '@[A-Z_]*@' "$work"; then
  echo "unsubstituted placeholders above" >&2
  exit 1
fi

# Debian's OpenFOAM: the binaries are in /usr/bin but find their etc/ files
# through WM_PROJECT_DIR, set by the project's etc/bashrc (which complains
# about helper scripts the package leaves out; harmless).
export WM_PROJECT_DIR=${FOAM_DIR:-/usr/share/openfoam}
set +eu
# shellcheck disable=SC1091
. "$WM_PROJECT_DIR/etc/bashrc" > /dev/null 2>&1
set -eu
command -v pimpleFoam > /dev/null || { echo "pimpleFoam not found: apt-get install openfoam" >&2; exit 1; }

cd "$work"
echo "== $out: A = $amplitude m, T = $period s (omega = $omega rad/s), $periods periods, dt = $delta_t s"
start=$(date +%s)
blockMesh > log.blockMesh 2>&1
nice snappyHexMesh -overwrite > log.snappyHexMesh 2>&1
checkMesh > log.checkMesh 2>&1 || { tail -30 log.checkMesh >&2; exit 1; }
grep -q '^Mesh OK' log.checkMesh || { echo "checkMesh failed (log.checkMesh in $work)" >&2; exit 1; }
grep -E '^ +cells:|^ +sphere ' log.checkMesh
mesh_end=$(date +%s)
nice pimpleFoam > log.pimpleFoam 2>&1 || { tail -30 log.pimpleFoam >&2; exit 1; }
end=$(date +%s)
grep -q '^End' log.pimpleFoam || { echo "pimpleFoam did not finish" >&2; exit 1; }
echo "meshing $((mesh_end - start)) s, pimpleFoam $((end - mesh_end)) s wall;" \
  "$(grep '^ExecutionTime' log.pimpleFoam | tail -1)"

rm -rf "$out"
mkdir -p "$out/postProcessing/forces/0" "$out/constant"
cp -r 0 system "$out/"
find constant -mindepth 1 -maxdepth 1 ! -name polyMesh -exec cp -r {} "$out/constant/" \;
cp postProcessing/forces/0/force.dat postProcessing/forces/0/moment.dat "$out/postProcessing/forces/0/"
cp log.checkMesh log.pimpleFoam "$out/"
if (($(stat -c %s "$out/log.pimpleFoam") > 1048576)); then
  gzip -9 "$out/log.pimpleFoam"
fi
if [[ ${KEEP_WORK:-0} == 1 ]]; then
  echo "scratch case kept in $work"
fi
echo "wrote $out"
