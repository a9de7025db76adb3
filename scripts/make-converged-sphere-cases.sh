#!/usr/bin/env bash
# Regenerates the steady OpenFOAM runs of the R = 0.15 m sphere in water that
# STOP on SIMPLE residualControl (data/openfoam-sphere/converged/), and the
# truly converged value each of them is creeping towards.
#
#   scripts/make-converged-sphere-cases.sh quarter MESH U
#   e.g. scripts/make-converged-sphere-cases.sh quarter 2 0.3
#   scripts/make-converged-sphere-cases.sh sweep U V
#   e.g. scripts/make-converged-sphere-cases.sh sweep 0.2 0.05
#
# quarter: quarter domain (symmetry planes y = 0 and z = 0), mesh MESH = 1
#   (coarse), 2 or 3 (fine): the background cells of blockMesh shrink by about
#   1.37 per direction per level (24, 33, 45 cells along x) and the
#   snappyHexMesh refinement levels and regions stay the same, so every cell
#   shrinks by about that ratio, except the two wall layers, which keep the
#   same absolute thickness (first layer 2.5 mm) so that the wall functions see
#   the same y+ on every mesh. Free stream (U, 0, 0). Writes
#   converged/cases/M<MESH>-U<U>/, then (unless REFERENCE=0) continues the same
#   run from its final state with residualControl REF_RESIDUAL (default 1e-7)
#   and linear-solver tolerances 1e-12, until that is met, or until the means
#   of every component of the total force and moment over the last two windows
#   of 50 iterations differ by less than REF_CHANGE (default 1e-8) times the
#   magnitude of that vector (the runs end in a small limit cycle, of period 2
#   or irregular, whose residuals stay near 1e-7 to 1e-6, so the final iterate
#   alone does not settle), or
#   for at most REF_MAX_ITER (default 3000) iterations; the numbers of that run
#   go into converged/reference.json (its case folder is not kept).
# sweep: half domain (symmetry plane z = 0 only, so sway forces exist), mesh
#   SWEEP_MESH (default 1: the coarse one; mesh 2 is 98k cells in the half
#   domain and its runs that never settle take 10 min each on a shared core),
#   free stream (U, V, 0). Writes converged/sweep/u<U>_v<V>/. endTime is
#   SWEEP_END_TIME (default 1000): a run that never meets residualControl stops
#   there (the script says so).
#
# Both: SIMPLE residualControl 1e-4 on p, U, k, omega, endTime 3000 (quarter).
# Needs OpenFOAM v1912 from Debian (`apt-get install openfoam`); only this
# script needs it. Reads only the dictionaries in
# data/openfoam-sphere/converged/template (placeholders @NAME@), meshes
# (blockMesh, snappyHexMesh, checkMesh) and runs simpleFoam on one core under
# nice in a scratch folder, then writes the case as the solver left it, less
# the mesh (constant/polyMesh) and the time folders: 0/, constant/, system/,
# postProcessing/forces/0/force.dat and moment.dat (every iteration),
# postProcessing/solverInfo/0/solverInfo.dat, log.checkMesh and log.simpleFoam
# (gzipped if over 1 MB).
#
# Environment: FOAM_DIR (default /usr/share/openfoam), KEEP_WORK=1 keeps the
# scratch folder (mesh and time folders) and prints its path, FORCE=1
# replaces an existing output folder, OUT=DIR writes the case there instead
# (for sensitivity runs that are not kept), REFERENCE=0 skips the tight run.
set -euo pipefail

usage="usage: make-converged-sphere-cases.sh quarter MESH U | sweep U V"
mode=${1:?$usage}
number='^[0-9]+([.][0-9]+)?$'
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
base="$root/data/openfoam-sphere/converged"
template="$base/template"

case $mode in
  quarter)
    mesh=${2:?$usage}
    u=${3:?$usage}
    v=0
    [[ $mesh =~ ^[123]$ ]] || { echo "MESH is 1, 2 or 3: $mesh" >&2; exit 2; }
    name=$(awk -v m="$mesh" -v u="$u" 'BEGIN { printf "M%d-U%.4f", m, u }')
    out=${OUT:-"$base/cases/$name"}
    end_time=3000
    reference=${REFERENCE:-1}
    ;;
  sweep)
    mesh=${SWEEP_MESH:-1}
    u=${2:?$usage}
    v=${3:?$usage}
    name=$(awk -v u="$u" -v v="$v" 'BEGIN { printf "u%.2f_v%.2f", u, v }')
    out=${OUT:-"$base/sweep/$name"}
    end_time=${SWEEP_END_TIME:-1000}
    reference=0
    [[ $mesh =~ ^[123]$ ]] || { echo "SWEEP_MESH is 1, 2 or 3: $mesh" >&2; exit 2; }
    ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
for x in "$u" "$v"; do
  [[ $x =~ $number ]] || { echo "not a non-negative number: $x" >&2; exit 2; }
done
if [[ -e $out && ${FORCE:-0} != 1 ]]; then
  echo "$out exists (FORCE=1 replaces it)" >&2
  exit 1
fi

# Background mesh: NX cells along the 3.5 m of x; cells as near cubic as the
# box allows.
nx=$(awk -v m="$mesh" 'BEGIN { split("24 33 45", n, " "); print n[m] }')
h=$(awk -v n="$nx" 'BEGIN { printf "%.6g", 3.5 / n }')
ny=$(awk -v n="$nx" 'BEGIN { printf "%d", 1.75 / 3.5 * n + 0.5 }')
nz=$(awk -v n="$nx" 'BEGIN { printf "%d", 1.55 / 3.5 * n + 0.5 }')
if [[ $mode == quarter ]]; then
  ymin=0; wake_ymin=0.0; wake_ymax=0.35
  freestream_ymin=''
  symy='    symY { type symmetryPlane; faces ((0 1 5 4)); }   // y = 0'
else
  ymin=-1.75; ny=$((2 * ny)); wake_ymin=-0.35; wake_ymax=0.9
  freestream_ymin='            (0 1 5 4)             // y-min'
  symy=''
fi
# Inlet turbulence: intensity 1 %, eddy-viscosity ratio 10.
k=$(awk -v u="$u" -v v="$v" 'BEGIN { printf "%.6e", 1.5 * (0.01 * sqrt(u * u + v * v))^2 }')
omega=$(awk -v k="$k" 'BEGIN { printf "%.6e", k / (10 * 1.004e-6) }')

work=$(mktemp -d "${TMPDIR:-/tmp}/converged-sphere.XXXXXX")
if [[ ${KEEP_WORK:-0} != 1 ]]; then
  trap 'rm -rf "$work"' EXIT
fi
cp -r "$template/0" "$template/constant" "$template/system" "$work/"
[[ -n $symy ]] || sed -i '/@SYMY@/d' "$work/system/blockMeshDict"
[[ -n $freestream_ymin ]] || sed -i '/@FREESTREAM_YMIN@/d' "$work/system/blockMeshDict"
fill() {  # fill FILE RESIDUAL
  sed -i -e "s/@U@/$u/g" -e "s/@V@/$v/g" -e "s/@K@/$k/g" -e "s/@OMEGA@/$omega/g" \
    -e "s/@NX@/$nx/g" -e "s/@NY@/$ny/g" -e "s/@NZ@/$nz/g" -e "s/@H@/$h/g" -e "s/@YMIN@/$ymin/g" \
    -e "s/@WAKE_YMIN@/$wake_ymin/g" -e "s/@WAKE_YMAX@/$wake_ymax/g" -e "s|@SYMY@|$symy|" \
    -e "s|@FREESTREAM_YMIN@|$freestream_ymin|" -e "s/@END_TIME@/$end_time/g" \
    -e "s/@RESIDUAL@/$2/g" "$1"
}
while IFS= read -r -d '' f; do fill "$f" 1e-4; done < <(find "$work/0" "$work/constant" "$work/system" -type f -print0)
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
command -v simpleFoam > /dev/null || { echo "simpleFoam not found: apt-get install openfoam" >&2; exit 1; }

cd "$work"
echo "== $out: free stream ($u, $v, 0) m/s, $mode domain, mesh $mesh (background $nx x $ny x $nz, $h m)"
start=$(date +%s)
nice blockMesh > log.blockMesh 2>&1
nice snappyHexMesh -overwrite > log.snappyHexMesh 2>&1
nice checkMesh > log.checkMesh 2>&1 || { tail -30 log.checkMesh >&2; exit 1; }
grep -q '^Mesh OK' log.checkMesh || { echo "checkMesh failed (log.checkMesh in $work)" >&2; exit 1; }
grep -E '^ +cells:|^ +sphere ' log.checkMesh
cells=$(awk '/^ +cells:/ { print $2; exit }' log.checkMesh)
mesh_end=$(date +%s)
nice simpleFoam > log.simpleFoam 2>&1 || { tail -30 log.simpleFoam >&2; exit 1; }
end=$(date +%s)
grep -q '^End' log.simpleFoam || { echo "simpleFoam did not finish" >&2; exit 1; }
last=$(awk '!/^#/ { t = $1 } END { print t }' postProcessing/forces/0/force.dat)
if converged=$(grep -m1 'SIMPLE solution converged in' log.simpleFoam); then
  echo "$converged"
elif [[ $mode == sweep ]]; then
  echo "NOT converged: residualControl not met by endTime $end_time (iteration $last)"
else
  echo "simpleFoam stopped at endTime $end_time without meeting residualControl" >&2
  exit 1
fi
echo "meshing $((mesh_end - start)) s, simpleFoam $((end - mesh_end)) s wall;" \
  "$(grep '^ExecutionTime' log.simpleFoam | tail -1)"
echo "final iteration $last: force $(tail -1 postProcessing/forces/0/force.dat | cut -f2)"

rm -rf "$out"
mkdir -p "$out/postProcessing/forces/0" "$out/postProcessing/solverInfo/0" "$out/constant"
cp -r 0 system "$out/"
find constant -mindepth 1 -maxdepth 1 ! -name polyMesh -exec cp -r {} "$out/constant/" \;
cp postProcessing/forces/0/force.dat postProcessing/forces/0/moment.dat "$out/postProcessing/forces/0/"
cp postProcessing/solverInfo/0/solverInfo.dat "$out/postProcessing/solverInfo/0/"
cp log.checkMesh log.simpleFoam "$out/"
if (($(stat -c %s "$out/log.simpleFoam") > 1048576)); then
  gzip -9 "$out/log.simpleFoam"
fi
echo "wrote $out"

if [[ $reference != 1 ]]; then
  [[ ${KEEP_WORK:-0} == 1 ]] && echo "scratch case kept in $work"
  exit 0
fi

# The reference: the same case continued from its final state (time $last)
# with a tight residualControl and tight linear solvers (the fixed point of the
# discrete equations does not depend on either), relaxation unchanged.
ref_residual=${REF_RESIDUAL:-1e-7}
ref_change=${REF_CHANGE:-1e-8}
ref_max=${REF_MAX_ITER:-3000}
ref_end=$((last + ref_max))
cp "$template/system/fvSolution" system/fvSolution
fill system/fvSolution "$ref_residual"
sed -i -E 's/^( +tolerance +)1e-[0-9]+;/\11e-12;/' system/fvSolution
sed -i -E "s/^(endTime +)[0-9]+;/\1$ref_end;/; s/^(writeInterval +)[0-9]+;/\1$ref_end;/" system/controlDict
ref_start=$(date +%s)
nice simpleFoam > log.simpleFoam.reference 2>&1 &
pid=$!
# Force-change watcher: stops the run (by its pid) once the means of every
# component of the total force and moment over the last 50 iterations and
# over the 50 before differ by less than ref_change times |F| (|M|).
steady() {
  local f=postProcessing/forces/$last/force.dat m=postProcessing/forces/$last/moment.dat
  [[ -f $f && -f $m ]] || return 1
  for d in "$f" "$m"; do
    grep -v '^#' "$d" | tail -100 | tr -d '()' | awk -v tol="$ref_change" '
      { n++; for (i = 2; i <= 4; i++) { s[n > 50, i] += $i; last[i] = $i } }
      END {
        if (n < 100) exit 1
        mag = sqrt(last[2]^2 + last[3]^2 + last[4]^2)
        for (i = 2; i <= 4; i++) {
          d = (s[1, i] - s[0, i]) / 50; if (d < 0) d = -d
          if (d > tol * mag) exit 1
        }
      }' || return 1
  done
}
stopped_by=""
while kill -0 "$pid" 2> /dev/null; do
  sleep 5
  if steady; then
    kill "$pid" 2> /dev/null || true
    stopped_by="force-change"
    break
  fi
done
wait "$pid" || true
ref_wall=$(($(date +%s) - ref_start))
if [[ -z $stopped_by ]]; then
  if grep -q 'SIMPLE solution converged in' log.simpleFoam.reference; then
    stopped_by="residualControl"
  else
    stopped_by="endTime"
  fi
fi
echo "reference run: stopped by $stopped_by, ${ref_wall} s wall"

python3 - "$base/reference.json" "$name" "$mesh" "$u" "$cells" "$last" "$stopped_by" "$ref_residual" \
  "$ref_change" "$ref_max" "$ref_wall" "$((end - mesh_end))" "$last" << 'EOF'
import json, os, sys
(path, name, mesh, u, cells, last, stopped_by, ref_residual, ref_change, ref_max, ref_wall,
 run_wall, start) = sys.argv[1:]

def rows(path):
    out = []
    for line in open(path):
        if line.startswith('#'):
            continue
        out.append(line.replace('(', ' ').replace(')', ' ').split())
    return out

def final(path):
    r = rows(path)[-1]
    return int(r[0]), [float(x) for x in r[1:4]]

def window(path, n=100):
    r = [[float(x) for x in row[1:4]] for row in rows(path)[-n:]]
    mean = [sum(c) / len(r) for c in zip(*r)]
    spread = [max(c) - min(c) for c in zip(*r)]
    return [float('%.11g' % x) for x in mean], [float('%.3g' % x) for x in spread]

it, force = final(f'postProcessing/forces/{start}/force.dat')
_, moment = final(f'postProcessing/forces/{start}/moment.dat')
force_mean, force_range = window(f'postProcessing/forces/{start}/force.dat')
moment_mean, moment_range = window(f'postProcessing/forces/{start}/moment.dat')
if stopped_by == 'residualControl':  # converged: the last iterate is the value
    force_mean, moment_mean = force, moment
_, force1 = final('postProcessing/forces/0/force.dat')
_, moment1 = final('postProcessing/forces/0/moment.dat')
info = open(f'postProcessing/solverInfo/{start}/solverInfo.dat').read().splitlines()
head = [l for l in info if l.startswith('# Time')][0].lstrip('#').split()
vals = [l for l in info if not l.startswith('#')][-1].split()
residuals = {k[:-len('_initial')]: float(vals[i]) for i, k in enumerate(head) if k.endswith('_initial')}
entry = {
    'case': f'cases/{name}', 'mesh': int(mesh), 'cells': int(cells), 'U': [float(u), 0.0, 0.0],
    'stop_1e-4': {'iteration': int(last), 'force': force1, 'moment': moment1,
                  'simpleFoam_wall_s': int(run_wall)},
    'reference': {'iteration': it, 'stopped_by': stopped_by,
                  'force': force_mean, 'moment': moment_mean,
                  'force_range': force_range, 'moment_range': moment_range,
                  'force_final': force, 'moment_final': moment,
                  'initial_residuals': residuals, 'wall_s': int(ref_wall)},
}
data = {}
if os.path.exists(path):
    data = json.load(open(path))
data['note'] = (
    'Reference (iteratively converged) values of the cases in cases/: each case continued from its '
    'residualControl-1e-4 final state with the same dictionaries except SIMPLE residualControl '
    f'{ref_residual} on p, U, k, omega and linear-solver tolerances 1e-12 (relaxation unchanged), '
    f'for at most {ref_max} more iterations; stopped_by says what ended it: residualControl (met), '
    f'force-change (the means of every component of the total force and moment over the last 50 '
    f'iterations and the 50 before differed by less than {ref_change} times |F| resp. |M|; the run was '
    'stopped there) or endTime (the cap). The runs end in a small limit cycle, of period 2 or irregular '
    '(initial residuals stay near 1e-7 to 1e-6), so force and moment (the reference values) are the last '
    'iterate when residualControl was met and else the means over the last 100 iterations; '
    'force_range/moment_range are the max - min of each component over the last 100 '
    'iterations (the size of the cycle) and force_final/moment_final the last iterate. All are the '
    'total (pressure + viscous) force and moment on the quarter sphere patch, N and N m, about (0 0 0), '
    'axes as in ../README.md; initial_residuals: solverInfo initial residuals at the last iteration. '
    'stop_1e-4: the kept run at its residualControl-1e-4 stop (its last iterate). cells: checkMesh. '
    'Made by scripts/make-converged-sphere-cases.sh quarter MESH U.')
data.setdefault('cases', {})[name] = entry
data['cases'] = dict(sorted(data['cases'].items()))
tmp = path + '.tmp'
with open(tmp, 'w') as fh:
    json.dump(data, fh, indent=2)
    fh.write('\n')
os.replace(tmp, path)
print(f'reference {name}: iteration {it}, force {force}, residuals {residuals}')
EOF
[[ ${KEEP_WORK:-0} == 1 ]] && echo "scratch case kept in $work"
exit 0
